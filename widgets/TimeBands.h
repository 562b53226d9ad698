#pragma once

#include <qcustomplot.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

namespace footpath {

/// Spans of consecutive set flags, each from its first sample to the sample after its last (as a
/// step plot draws them), so a one-sample flag still has a width.
std::vector<QCPRange> flaggedSpans(const std::vector<double>& times, const std::vector<std::uint8_t>& flags);

/// Makes an axis rect a lane of labelled bars: its name as the one tick on the left, no grid and
/// no time ticks (the rows above carry the time axis).
void setUpLane(QCPAxisRect* lane, const QString& name);

/// The smaller font lane labels are drawn in.
QFont laneLabelFont(const QCustomPlot* plot);

/// How many spans overlap in time at most (0 for none); Span has start_s and end_s. A lane needs
/// that many levels for every bar to have its own.
template <class Span>
std::size_t overlapDepth(const std::vector<Span>& spans)
{
    std::size_t deepest = 0;
    for (const Span& span : spans) {
        const auto depth = std::count_if(spans.begin(), spans.end(), [&span](const Span& other) {
            return other.start_s <= span.start_s && span.start_s <= other.end_s;
        });
        deepest = std::max(deepest, static_cast<std::size_t>(depth));
    }
    return deepest;
}

/// Filled bands over time spans in one axis rect: the full height of the rect, or between two
/// levels of its left axis (a lane). Drawn as pixel rectangles, merged where they touch: as a
/// filled step curve (a QCPGraph with a brush) the stance phases of half an hour cost Qt's
/// rasteriser about a second per row, since the polygon has thousands of edges.
class TimeBands : public QCPLayerable {
public:
    TimeBands(QCPAxisRect* rect, const QBrush& brush);

    /// Sorted, disjoint spans.
    void setSpans(std::vector<QCPRange> spans) { spans_ = std::move(spans); }
    /// Fill only between these values of the left axis instead of the full height.
    void setLevels(double bottom, double top) { levels_ = QCPRange(bottom, top); }
    bool isEmpty() const { return spans_.empty(); }
    bool contains(double time_s) const;

protected:
    void applyDefaultAntialiasingHint(QCPPainter* painter) const override { painter->setAntialiasing(false); }
    QRect clipRect() const override { return rect_->rect(); }
    void draw(QCPPainter* painter) override;

private:
    void fillBand(QCPPainter* painter, double left, double right) const;

    QCPAxisRect* rect_;
    QBrush brush_;
    std::optional<QCPRange> levels_;
    std::vector<QCPRange> spans_;
};

}  // namespace footpath
