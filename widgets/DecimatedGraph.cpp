#include "DecimatedGraph.h"

#include "PixelCurve.h"

#include <algorithm>
#include <cmath>

namespace footpath {

DecimatedGraph::DecimatedGraph(QCPAxis* keyAxis, QCPAxis* valueAxis, Reduction reduction)
    : QCPGraph(keyAxis, valueAxis), reduction_(reduction)
{
    setAdaptiveSampling(true);
}

QVector<QCPGraphData> DecimatedGraph::drawnData() const
{
    QVector<QCPGraphData> drawn;
    if (mDataContainer->isEmpty())
        return drawn;
    QCPGraphDataContainer::const_iterator begin, end;
    getVisibleDataBounds(begin, end, QCPDataRange(0, dataCount()));
    getOptimizedLineData(&drawn, begin, end);
    return drawn;
}

void DecimatedGraph::getOptimizedLineData(QVector<QCPGraphData>* lineData,
                                          const QCPGraphDataContainer::const_iterator& begin,
                                          const QCPGraphDataContainer::const_iterator& end) const
{
    const auto isGap = [](const QCPGraphData& point) { return std::isnan(point.value); };
    auto stretch = begin;
    auto gap = std::find_if(stretch, end, isGap);
    if (gap == end && reduction_ == Reduction::LowestAndHighest) {
        QCPGraph::getOptimizedLineData(lineData, begin, end);
        return;
    }
    lineData->clear();
    while (true) {
        if (gap != stretch)
            appendReduced(lineData, stretch, gap);
        if (gap == end)
            return;
        lineData->append(*gap);  // the line breaks here
        stretch = gap + 1;
        gap = std::find_if(stretch, end, isGap);
    }
}

void DecimatedGraph::appendReduced(QVector<QCPGraphData>* lineData, const QCPGraphDataContainer::const_iterator& begin,
                                   const QCPGraphDataContainer::const_iterator& end) const
{
    if (reduction_ != Reduction::LowestAndHighest) {
        appendEnvelope(lineData, begin, end);
        return;
    }
    QVector<QCPGraphData> piece;
    QCPGraph::getOptimizedLineData(&piece, begin, end);
    lineData->append(piece);
}

void DecimatedGraph::appendEnvelope(QVector<QCPGraphData>* lineData, const QCPGraphDataContainer::const_iterator& begin,
                                    const QCPGraphDataContainer::const_iterator& end) const
{
    // A band filled between two edges: a column's fill spans from the lowest lower edge to the
    // highest upper edge of its samples, so one point a column draws it. Drawn with the zig-zag
    // of every sample (or adaptive sampling's four points a column) the fill polygon has
    // thousands of edges, and filling it costs tens of milliseconds a band.
    const PixelMap toPixels(mKeyAxis.data(), mValueAxis.data());
    const bool highest = reduction_ == Reduction::Highest;
    auto column = begin;
    double columnPixel = std::floor(toPixels.keyPixel(begin->key));
    for (auto it = begin + 1; it != end; ++it) {
        const double pixel = std::floor(toPixels.keyPixel(it->key));
        if (pixel != columnPixel) {
            lineData->append(*column);
            column = it;
            columnPixel = pixel;
        } else if (highest ? it->value > column->value : it->value < column->value) {
            column = it;
        }
    }
    lineData->append(*column);
}

}  // namespace footpath
