#pragma once

#include <qcustomplot.h>

namespace footpath {

/// A plottable's coordinate-to-pixel map with each linear axis as one multiply-add: through
/// QCPAxis::coordToPixel (a call and its scale and orientation branches per coordinate) the 2D
/// view's paths were an eighth of a slider move's redraw on a 30-minute walk. A logarithmic axis
/// still goes through coordToPixel. Valid until an axis' range or the axis rect changes.
class PixelMap {
public:
    PixelMap(const QCPAxis* keyAxis, const QCPAxis* valueAxis);
    QPointF operator()(double key, double value) const
    {
        return keyIsHorizontal_ ? QPointF(key_(key), value_(value)) : QPointF(value_(value), key_(key));
    }
    double keyPixel(double key) const { return key_(key); }

private:
    /// pixel = origin + (coordinate - lower) * scale on a linear axis.
    struct Axis {
        explicit Axis(const QCPAxis* axis);
        double operator()(double coordinate) const
        {
            return linear ? origin_px + (coordinate - lower) * scale : axis->coordToPixel(coordinate);
        }
        const QCPAxis* axis;
        bool linear;
        double lower, origin_px, scale;
    };
    Axis key_, value_;
    bool keyIsHorizontal_;
};

/// The points of a pixel polyline that lie at least about a pixel (Manhattan distance tolerance_px)
/// from the last point kept, with the first and the last always kept and NaN points (gaps) kept as they are.
/// The line through them strays less than a pixel from the full one: a walk of 180,000 samples
/// becomes a few thousand points at any zoom that shows all of it, and every point when zoomed in
/// far enough that the samples are pixels apart.
QVector<QPointF> pixelSimplified(const QVector<QPointF>& points, double tolerance_px = 1.0);

/// A QCPCurve (the 2D view's reference, ghost and comparison paths) whose line is drawn through
/// pixelSimplified() points: QCPCurve draws every sample, and a translucent or dashed wide pen then
/// goes through QPainter's path stroker, which takes seconds for a 30-minute path.
class PixelCurve : public QCPCurve {
public:
    using QCPCurve::QCPCurve;

    /// How far the drawn line may stray from the samples: a pixel, or more for a faint wide line
    /// (the ghost) whose stroking costs in proportion to its points.
    void setTolerance(double tolerance_px) { tolerance_px_ = tolerance_px; }

protected:
    void draw(QCPPainter* painter) override;

private:
    double tolerance_px_ = 1.0;
};

}  // namespace footpath
