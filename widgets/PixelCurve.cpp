#include "PixelCurve.h"

#include <cmath>

namespace footpath {

PixelMap::Axis::Axis(const QCPAxis* axis_)
    : axis(axis_), linear(axis_->scaleType() == QCPAxis::stLinear && axis_->range().size() > 0.0),
      lower(axis_->range().lower), origin_px(axis_->coordToPixel(lower)),
      scale(linear ? (axis_->coordToPixel(axis_->range().upper) - origin_px) / axis_->range().size() : 0.0)
{
}

PixelMap::PixelMap(const QCPAxis* keyAxis, const QCPAxis* valueAxis)
    : key_(keyAxis), value_(valueAxis), keyIsHorizontal_(keyAxis->orientation() == Qt::Horizontal)
{
}

QVector<QPointF> pixelSimplified(const QVector<QPointF>& points, double tolerance_px)
{
    QVector<QPointF> kept;
    kept.reserve(std::min<qsizetype>(points.size(), 4096));
    const auto keep = [&kept](const QPointF& point, std::size_t) { kept.append(point); };
    StraightRunSimplifier runs(tolerance_px);
    for (qsizetype k = 0; k < points.size(); ++k) {
        const QPointF& point = points[k];
        if (std::isnan(point.x()) || std::isnan(point.y())) {
            runs.finish(keep);
            kept.append(point);
            continue;
        }
        runs.add(point, static_cast<std::size_t>(k), keep);
    }
    runs.finish(keep);
    return kept;
}

void PixelCurve::draw(QCPPainter* painter)
{
    QVector<QPointF> pixels;
    pixels.reserve(mDataContainer->size());
    const PixelMap toPixels(mKeyAxis.data(), mValueAxis.data());
    for (const QCPCurveData& point : *mDataContainer)
        pixels.append(toPixels(point.key, point.value));
    applyDefaultAntialiasingHint(painter);
    painter->setPen(mPen);
    painter->setBrush(Qt::NoBrush);
    const QVector<QPointF> kept = pixelSimplified(pixels, tolerance_px_);
    // QPainter strokes a wide polyline as one outline, which for a path of many laps crossing
    // itself takes tens of milliseconds; line segments are quick. An opaque solid pen draws
    // nearly the same pixels either way (antialiased joints blend their soft edge twice; a
    // translucent pen would darken where its segments overlap). Vector output (the PDF report)
    // keeps the polyline: one path, not thousands of separate lines.
    const bool vectorOutput = painter->modes().testFlag(QCPPainter::pmVectorized);
    if (vectorOutput || mPen.style() != Qt::SolidLine || mPen.color().alpha() != 255) {
        drawCurveLine(painter, kept);
        return;
    }
    QVector<QLineF> segments;
    segments.reserve(kept.size());
    for (qsizetype k = 1; k < kept.size(); ++k)
        if (qIsFinite(kept[k - 1].x()) && qIsFinite(kept[k - 1].y()) && qIsFinite(kept[k].x()) && qIsFinite(kept[k].y()))
            segments.append(QLineF(kept[k - 1], kept[k]));
    painter->drawLines(segments);
}

}  // namespace footpath
