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

bool StampedMarkerGraph::paintsPixels(const QCPPainter* painter)
{
    const QPaintDevice* device = painter->device();
    if (device == nullptr || painter->modes().testFlag(QCPPainter::pmVectorized)
        || (device->devType() != QInternal::Pixmap && device->devType() != QInternal::Image))
        return false;
    const qreal ratio = device->devicePixelRatioF();
    return ratio == std::floor(ratio) && painter->worldTransform().type() <= QTransform::TxTranslate;
}

void StampedMarkerGraph::drawScatterPlot(QCPPainter* painter, const QVector<QPointF>& scatters,
                                         const QCPScatterStyle& style) const
{
    if (!paintsPixels(painter) || style.isNone() || style.shape() == QCPScatterStyle::ssPixmap
        || style.shape() == QCPScatterStyle::ssCustom) {
        QCPGraph::drawScatterPlot(painter, scatters, style);
        return;
    }
    applyScattersAntialiasingHint(painter);
    const qreal ratio = painter->device()->devicePixelRatioF();
    const QPixmap& marker = stamp(style, ratio, painter->antialiasing());
    // The stamp holds the shape as QCPPainter draws it at its centre, half-pixel shift of the
    // antialiased mode included; copied without that shift, at the device pixel nearest the point.
    const double half = 0.5 * stampSide_;
    painter->save();
    painter->setAntialiasing(false);
    for (const QPointF& scatter : scatters)
        painter->drawPixmap(QPointF(std::round(scatter.x() * ratio) / ratio - half, std::round(scatter.y() * ratio) / ratio - half),
                            marker);
    painter->restore();
}

const QPixmap& StampedMarkerGraph::stamp(const QCPScatterStyle& style, qreal pixelRatio, bool antialiased) const
{
    const QPen pen = style.isPenDefined() ? style.pen() : mPen;
    const bool same = !stamp_.isNull() && stamp_.devicePixelRatioF() == pixelRatio && stampAntialiased_ == antialiased
                      && stampStyle_.shape() == style.shape() && stampStyle_.size() == style.size()
                      && stampPen_ == pen && stampStyle_.brush() == style.brush();
    if (same)
        return stamp_;
    // Room for the shape and its pen on every side, an even number of pixels so the centre is a
    // pixel corner (a whole pixel ratio keeps it one in device pixels).
    stampSide_ = 2 * static_cast<int>(std::ceil(0.5 * style.size() + pen.widthF() + 1.0));
    stamp_ = QPixmap(QSize(stampSide_, stampSide_) * pixelRatio);
    stamp_.setDevicePixelRatio(pixelRatio);
    stamp_.fill(Qt::transparent);
    QCPPainter stampPainter(&stamp_);
    stampPainter.setAntialiasing(antialiased);
    style.applyTo(&stampPainter, mPen);
    style.drawShape(&stampPainter, QPointF(stampSide_ / 2, stampSide_ / 2));
    stampPainter.end();
    stampStyle_ = style;
    stampPen_ = pen;
    stampAntialiased_ = antialiased;
    return stamp_;
}

}  // namespace footpath
