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

namespace {

/// pixelSimplified on the points pixelAt(0 .. count - 1) gives, without holding them all.
template <class PixelAt>
QVector<QPointF> simplifiedPixels(qsizetype count, PixelAt&& pixelAt, double tolerance_px)
{
    QVector<QPointF> kept;
    kept.reserve(std::min<qsizetype>(count, 4096));
    const auto keep = [&kept](const QPointF& point, std::size_t) { kept.append(point); };
    StraightRunSimplifier runs(tolerance_px);
    for (qsizetype k = 0; k < count; ++k) {
        const QPointF point = pixelAt(k);
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

}  // namespace

QVector<QPointF> pixelSimplified(const QVector<QPointF>& points, double tolerance_px)
{
    return simplifiedPixels(points.size(), [&points](qsizetype k) { return points[k]; }, tolerance_px);
}

void PixelCurve::draw(QCPPainter* painter)
{
    const PixelMap toPixels(mKeyAxis.data(), mValueAxis.data());
    const auto first = mDataContainer->constBegin();
    const QVector<QPointF> kept = simplifiedPixels(
        mDataContainer->size(), [&](qsizetype k) { return toPixels((first + k)->key, (first + k)->value); }, tolerance_px_);
    applyDefaultAntialiasingHint(painter);
    painter->setPen(mPen);
    painter->setBrush(Qt::NoBrush);
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

void StampedMarkerGraph::drawScatterPlot(QCPPainter* painter, const QVector<QPointF>& scatters,
                                         const QCPScatterStyle& style) const
{
    if (painter->modes().testFlag(QCPPainter::pmVectorized) || style.isNone()
        || style.shape() == QCPScatterStyle::ssPixmap || style.shape() == QCPScatterStyle::ssCustom) {
        QCPGraph::drawScatterPlot(painter, scatters, style);
        return;
    }
    applyScattersAntialiasingHint(painter);
    const QPixmap& marker =
        stamp(style, painter->device() ? painter->device()->devicePixelRatioF() : 1.0, painter->antialiasing());
    // The stamp holds the shape as QCPPainter draws it at its centre, half-pixel shift of the
    // antialiased mode included; copied without that shift, at the whole pixel nearest the point.
    const double half = 0.5 * marker.width() / marker.devicePixelRatioF();
    painter->save();
    painter->setAntialiasing(false);
    for (const QPointF& scatter : scatters)
        painter->drawPixmap(QPointF(std::round(scatter.x()) - half, std::round(scatter.y()) - half), marker);
    painter->restore();
}

const QPixmap& StampedMarkerGraph::stamp(const QCPScatterStyle& style, qreal pixelRatio, bool antialiased) const
{
    const bool same = !stamp_.isNull() && stamp_.devicePixelRatioF() == pixelRatio && stampAntialiased_ == antialiased
                      && stampStyle_.shape() == style.shape() && stampStyle_.size() == style.size()
                      && stampStyle_.pen() == style.pen() && stampStyle_.brush() == style.brush();
    if (same)
        return stamp_;
    // Room for the shape and its pen on every side, an even number of pixels so the centre is a corner.
    const int side = 2 * static_cast<int>(std::ceil(0.5 * style.size() + style.pen().widthF() + 1.0));
    stamp_ = QPixmap(QSize(side, side) * pixelRatio);
    stamp_.setDevicePixelRatio(pixelRatio);
    stamp_.fill(Qt::transparent);
    QCPPainter stampPainter(&stamp_);
    stampPainter.setAntialiasing(antialiased);
    style.applyTo(&stampPainter, mPen);
    style.drawShape(&stampPainter, QPointF(side / 2, side / 2));
    stampPainter.end();
    stampStyle_ = style;
    stampAntialiased_ = antialiased;
    return stamp_;
}

}  // namespace footpath
