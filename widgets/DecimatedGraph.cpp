#include "DecimatedGraph.h"

#include "PixelCurve.h"

#include <algorithm>
#include <cmath>

namespace footpath {

QVector<QCPGraphData> coarseEnvelope(const QVector<QCPGraphData>& data, int bucket)
{
    QVector<QCPGraphData> coarse;
    coarse.reserve(2 * data.size() / std::max(1, bucket) + 16);
    for (qsizetype i = 0; i < data.size();) {
        if (std::isnan(data[i].value)) {
            coarse.append(data[i++]);
            continue;
        }
        qsizetype lowest = i, highest = i, next = i + 1;
        for (; next < data.size() && next - i < bucket && !std::isnan(data[next].value); ++next) {
            if (data[next].value < data[lowest].value)
                lowest = next;
            if (data[next].value > data[highest].value)
                highest = next;
        }
        coarse.append(data[std::min(lowest, highest)]);
        if (highest != lowest)
            coarse.append(data[std::max(lowest, highest)]);
        i = next;
    }
    return coarse;
}

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

void DecimatedGraph::setSeries(const QVector<QCPGraphData>& data, const QVector<QCPGraphData>& coarse)
{
    mDataContainer->set(data, true);  // shares the vector
    coarse_ = coarse;
    coarseOfData_ = data.constData();
    coarseOfSize_ = static_cast<int>(data.size());
    coarseOfFirst_s_ = data.isEmpty() ? 0.0 : data.front().key;
    coarseOfLast_s_ = data.isEmpty() ? 0.0 : data.back().key;
}

std::optional<std::pair<QCPGraphDataContainer::const_iterator, QCPGraphDataContainer::const_iterator>>
DecimatedGraph::coarseRange(const QCPGraphDataContainer::const_iterator& begin,
                            const QCPGraphDataContainer::const_iterator& end) const
{
    const bool ofThisData = !coarse_.isEmpty() && coarseOfSize_ == mDataContainer->size() && coarseOfSize_ > 0
                            && &*mDataContainer->constBegin() == coarseOfData_
                            && mDataContainer->constBegin()->key == coarseOfFirst_s_
                            && (mDataContainer->constEnd() - 1)->key == coarseOfLast_s_;
    if (!ofThisData || end - begin < 2)
        return std::nullopt;
    const double columns = std::abs(mKeyAxis->coordToPixel((end - 1)->key) - mKeyAxis->coordToPixel(begin->key)) + 1.0;
    if (static_cast<double>(end - begin) < 2.0 * kCoarseBucket * columns)
        return std::nullopt;
    const auto byKey = [](const QCPGraphData& point, double key) { return point.key < key; };
    const auto first = std::lower_bound(coarse_.constBegin(), coarse_.constEnd(), begin->key, byKey);
    const auto last = std::lower_bound(first, coarse_.constEnd(), std::nextafter((end - 1)->key, HUGE_VAL), byKey);
    return std::make_pair(first, last);
}

void DecimatedGraph::getOptimizedLineData(QVector<QCPGraphData>* lineData,
                                          const QCPGraphDataContainer::const_iterator& dataBegin,
                                          const QCPGraphDataContainer::const_iterator& dataEnd) const
{
    // Zoomed out, the coarse copy's points stand for the data's (coarseEnvelope).
    const auto coarse = coarseRange(dataBegin, dataEnd);
    const QCPGraphDataContainer::const_iterator begin = coarse ? coarse->first : dataBegin;
    const QCPGraphDataContainer::const_iterator end = coarse ? coarse->second : dataEnd;
    if (begin == end) {
        lineData->clear();
        return;
    }
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
