#pragma once

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

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

/// Walks a pixel polyline and keeps only the points a line through the kept ones needs to stay
/// within tolerance_px of every point: a run of points along a nearly straight line (a foot's
/// swing, at any zoom that shows a whole walk) becomes its two ends, a foot at rest one point.
/// A run is a strip 2h wide along the direction from its first point to the first point h away;
/// it ends where a point leaves the strip or turns back along it by more than h, and its last point
/// inside is kept and starts the next run. A point is then at most 2h from the segment drawn
/// through its run (h off the strip's centre line, h where the segment's end is off it), or
/// sqrt(5) h past the segment's end (h further along, 2h across): h = tolerance_px / sqrt(5)
/// keeps every point within tolerance_px of the line drawn.
/// Each kept point goes to keep(point, index) once, in order; a point is known to be needed only
/// when a later one leaves its run, so the calls lag one point behind add().
class StraightRunSimplifier {
public:
    explicit StraightRunSimplifier(double tolerance_px) : halfWidth_px_(tolerance_px / std::sqrt(5.0)) {}

    template <class Keep>
    void add(const QPointF& point, std::size_t index, Keep&& keep)
    {
        if (!started_) {
            started_ = true;
            anchor_ = point;
            keep(point, index);
            return;
        }
        const QPointF offset = point - anchor_;
        if (!hasDirection_) {
            // Most points of a foot at rest end here: the square root only for the one that leaves.
            const double squaredLength = QPointF::dotProduct(offset, offset);
            if (squaredLength >= halfWidth_px_ * halfWidth_px_) {
                const double length = std::sqrt(squaredLength);
                direction_ = offset / length;
                hasDirection_ = true;
                farthest_px_ = length;
            }
            setPending(point, index);
            return;
        }
        const double along = QPointF::dotProduct(offset, direction_);
        const double across = std::abs(offset.x() * direction_.y() - offset.y() * direction_.x());
        if (across <= halfWidth_px_ && along >= farthest_px_ - halfWidth_px_) {
            farthest_px_ = std::max(farthest_px_, along);
            setPending(point, index);
            return;
        }
        breakRun(keep);
        add(point, index, keep);  // the first point after the new run's start: no recursion beyond this
    }

    /// Ends the run here (a change of colour): its last point is kept and starts the next run.
    template <class Keep>
    void breakRun(Keep&& keep)
    {
        hasDirection_ = false;
        if (!pending_.waiting)
            return;
        keep(pending_.point, pending_.index);
        anchor_ = pending_.point;
        pending_.waiting = false;
    }

    /// Ends the polyline (or a piece of it, before a gap): its last point is kept, and the next
    /// point added starts afresh.
    template <class Keep>
    void finish(Keep&& keep)
    {
        breakRun(keep);
        started_ = false;
    }

private:
    /// Field by field: an aggregate assigned whole was built on the stack and copied back with
    /// wider loads than its stores, a store-forwarding stall on every point (perf annotate; the
    /// 2D view's redraw of a 30-minute walk 7.7 -> 5.7 ms).
    void setPending(const QPointF& point, std::size_t index)
    {
        pending_.point = point;
        pending_.index = index;
        pending_.waiting = true;
    }

    struct Pending {
        QPointF point;
        std::size_t index = 0;
        bool waiting = false;
    };
    double halfWidth_px_;
    bool started_ = false;
    bool hasDirection_ = false;
    QPointF anchor_, direction_;
    double farthest_px_ = 0.0;  ///< along the direction, the farthest point of the run so far
    Pending pending_;           ///< the run's last point, not kept yet
};

/// The points of a pixel polyline that StraightRunSimplifier keeps, piece by piece between NaN
/// points (gaps), which are kept as they are. The line through them strays at most tolerance_px
/// from the full one: a walk of 180,000 samples becomes a few thousand points at any
/// zoom that shows all of it, and every point when zoomed in so far that they are pixels apart
/// off a straight line.
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

/// A scatter-only QCPGraph (the 2D view's stance, start and end markers) that draws each marker on
/// screen as a copy of one pre-drawn image: QPainter draws an antialiased circle as Bezier curves,
/// and a 30-minute walk's 1600 stance rings took 3 ms of every redraw. The copy sits on the whole
/// pixel nearest the point (at most half a pixel off in each direction). Only on an image or pixmap
/// painted unscaled at a whole pixel ratio (the plot's own buffers, a plain grab); anything else
/// (the PDF and SVG exports and reports, a PNG exported at twice the size) gets the shapes drawn.
class StampedMarkerGraph : public QCPGraph {
public:
    using QCPGraph::QCPGraph;

protected:
    void drawScatterPlot(QCPPainter* painter, const QVector<QPointF>& scatters, const QCPScatterStyle& style) const override;

private:
    /// Whether painter's markers may be copies: a raster device, whole pixel ratio, no scaling.
    static bool paintsPixels(const QCPPainter* painter);
    /// The marker drawn once, as QCPPainter draws it at the centre of a square of an even number
    /// of pixels (stampSide_), at this pixel ratio and antialiasing; drawn again when the style
    /// (with the pen it falls back on), the ratio or the antialiasing changes.
    const QPixmap& stamp(const QCPScatterStyle& style, qreal pixelRatio, bool antialiased) const;

    mutable QPixmap stamp_;
    mutable int stampSide_ = 0;  ///< in logical pixels
    mutable QCPScatterStyle stampStyle_;
    mutable QPen stampPen_;  ///< the pen the stamp was drawn with (the style's, or the graph's)
    mutable bool stampAntialiased_ = false;
};

}  // namespace footpath
