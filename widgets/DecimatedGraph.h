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
    /// What a pixel column holding several samples is drawn as.
    enum class Reduction {
        LowestAndHighest,  ///< a line: QCustomPlot's adaptive sampling
        Highest,           ///< the upper edge of a band: one point per column, its highest sample
        Lowest,            ///< the lower edge of a band
    };

    DecimatedGraph(QCPAxis* keyAxis, QCPAxis* valueAxis, Reduction reduction = Reduction::LowestAndHighest);

    /// The points a replot at the axes' current ranges draws (a NaN value is a gap); for tests.
    QVector<QCPGraphData> drawnData() const;

protected:
    void getOptimizedLineData(QVector<QCPGraphData>* lineData, const QCPGraphDataContainer::const_iterator& begin,
                              const QCPGraphDataContainer::const_iterator& end) const override;

private:
    /// One stretch without gaps, reduced as reduction_ says, appended to lineData.
    void appendReduced(QVector<QCPGraphData>* lineData, const QCPGraphDataContainer::const_iterator& begin,
                       const QCPGraphDataContainer::const_iterator& end) const;
    /// The band edge of a stretch: per pixel column the sample with the highest (or lowest) value.
    void appendEnvelope(QVector<QCPGraphData>* lineData, const QCPGraphDataContainer::const_iterator& begin,
                        const QCPGraphDataContainer::const_iterator& end) const;

    Reduction reduction_;
};

}  // namespace footpath
