#pragma once

#include "Result.h"

#include <QRectF>
#include <QWidget>

class QCustomPlot;
class QCPCurve;
class QCPGraph;

namespace footpath {

/// Top view of the estimated foot path: the path, one dot per stance, start and end marked, equal
/// scales on both axes so a rectangle looks like one. Drawn by QCustomPlot without OpenGL.
class TrajectoryView2D : public QWidget {
    Q_OBJECT
public:
    explicit TrajectoryView2D(QWidget* parent = nullptr);

    void showResult(const Result& result);
    void clear();

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void keepEqualAxisScales();

    QCustomPlot* plot_;
    QCPCurve* path_;
    QCPGraph* stances_;
    QCPGraph* start_;
    QCPGraph* end_;
    QRectF dataBounds_;  ///< extent of the path, kept so resizing never compounds margins
};

}  // namespace footpath
