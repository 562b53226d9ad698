#pragma once

#include <qcustomplot.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace footpath {

/// Spans of consecutive set flags, each from its first sample to the sample after its last (as a
/// step plot draws them), so a one-sample flag still has a width.
std::vector<QCPRange> flaggedSpans(const std::vector<double>& times, const std::vector<std::uint8_t>& flags);

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
