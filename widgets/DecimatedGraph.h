#pragma once

#include <qcustomplot.h>

#include <optional>
#include <utility>

namespace footpath {

/// The samples a point pair of a coarse copy stands for (coarseEnvelope, DecimatedGraph::setSeries).
constexpr int kCoarseBucket = 16;

/// A coarse copy of a time series for drawing it zoomed out: each stretch of up to bucket samples
/// between NaN gaps as its lowest and its highest sample, in key order; the gaps as they are. Every
/// sample's value lies between the two kept of its stretch, so the lowest and highest of any run of
/// whole stretches are kept. Built on any thread.
QVector<QCPGraphData> coarseEnvelope(const QVector<QCPGraphData>& data, int bucket = kCoarseBucket);

/// A time series drawn as the screen can show it: QCustomPlot's adaptive sampling keeps, for each
/// pixel column holding several samples, its lowest and highest value (a one-sample spike is still
/// drawn when half an hour fits the row), and draws every sample once the view is zoomed in so far
/// that they are fewer than the pixels. Plain adaptive sampling bridges a NaN gap (a wrapped angle)
/// with a line through the whole row; here it runs on each stretch between gaps, and the gaps stay.
///
/// Given a coarse copy (setSeries), a view with at least two of its stretches a pixel column draws
/// from the copy: the same lowest and highest values, a column's own ones at most one stretch off
/// its edge, for an eighth of the points to go through (the state rows of a 30-minute walk were
/// 45 passes over 180,000 samples, 11 ms a replot).
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

    /// Sets the data (sorted by key) and its coarseEnvelope of stretches of kCoarseBucket samples.
    /// The copy is used only while the data is the vector given here, with its size and end keys
    /// (data set any other way is drawn without it); change the data only through here.
    void setSeries(const QVector<QCPGraphData>& data, const QVector<QCPGraphData>& coarse);

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

    /// The coarse copy, if it is still that of the data and the range drawn holds at least two of
    /// its stretches a pixel column: the copy's points from begin's key to end's; else nullopt.
    std::optional<std::pair<QCPGraphDataContainer::const_iterator, QCPGraphDataContainer::const_iterator>>
    coarseRange(const QCPGraphDataContainer::const_iterator& begin,
                const QCPGraphDataContainer::const_iterator& end) const;

    Reduction reduction_;
    QVector<QCPGraphData> coarse_;
    const QCPGraphData* coarseOfData_ = nullptr;  ///< the data's points, size and end keys the copy was made of
    int coarseOfSize_ = -1;
    double coarseOfFirst_s_ = 0.0, coarseOfLast_s_ = 0.0;
};

}  // namespace footpath
