#pragma once

#include <qcustomplot.h>

namespace footpath {

/// A time series drawn as the screen can show it: QCustomPlot's adaptive sampling keeps, for each
/// pixel column holding several samples, its lowest and highest value (a one-sample spike is still
/// drawn when half an hour fits the row), and draws every sample once the view is zoomed in so far
/// that they are fewer than the pixels. Plain adaptive sampling bridges a NaN gap (a wrapped angle)
/// with a line through the whole row; here it runs on each stretch between gaps, and the gaps stay.
class DecimatedGraph : public QCPGraph {
public:
    DecimatedGraph(QCPAxis* keyAxis, QCPAxis* valueAxis);

    /// The points a replot at the axes' current ranges draws (a NaN value is a gap); for tests.
    QVector<QCPGraphData> drawnData() const;

protected:
    void getOptimizedLineData(QVector<QCPGraphData>* lineData, const QCPGraphDataContainer::const_iterator& begin,
                              const QCPGraphDataContainer::const_iterator& end) const override;
};

}  // namespace footpath
