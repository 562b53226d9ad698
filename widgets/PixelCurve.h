#pragma once

#include <qcustomplot.h>

namespace footpath {

/// The points of a pixel polyline that lie at least about a pixel (Manhattan distance 1) from the
/// last point kept, with the first and the last always kept and NaN points (gaps) kept as they are.
/// The line through them strays less than a pixel from the full one: a walk of 180,000 samples
/// becomes a few thousand points at any zoom that shows all of it, and every point when zoomed in
/// far enough that the samples are pixels apart.
QVector<QPointF> pixelSimplified(const QVector<QPointF>& points);

/// A QCPCurve (the 2D view's reference, ghost and comparison paths) whose line is drawn through
/// pixelSimplified() points: QCPCurve draws every sample, and a translucent or dashed wide pen then
/// goes through QPainter's path stroker, which takes seconds for a 30-minute path.
class PixelCurve : public QCPCurve {
public:
    using QCPCurve::QCPCurve;

protected:
    void drawCurveLine(QCPPainter* painter, const QVector<QPointF>& lines) const override;
};

}  // namespace footpath
