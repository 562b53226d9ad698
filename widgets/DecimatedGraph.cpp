#include "DecimatedGraph.h"

#include <algorithm>
#include <cmath>

namespace footpath {

DecimatedGraph::DecimatedGraph(QCPAxis* keyAxis, QCPAxis* valueAxis) : QCPGraph(keyAxis, valueAxis)
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
    if (gap == end) {
        QCPGraph::getOptimizedLineData(lineData, begin, end);
        return;
    }
    lineData->clear();
    QVector<QCPGraphData> piece;
    while (true) {
        if (gap != stretch) {
            piece.clear();
            QCPGraph::getOptimizedLineData(&piece, stretch, gap);
            lineData->append(piece);
        }
        if (gap == end)
            return;
        lineData->append(*gap);  // the line breaks here
        stretch = gap + 1;
        gap = std::find_if(stretch, end, isGap);
    }
}

}  // namespace footpath
