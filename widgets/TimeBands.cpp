#include "TimeBands.h"

#include <algorithm>
#include <cmath>

namespace footpath {

std::vector<QCPRange> flaggedSpans(const std::vector<double>& times, const std::vector<std::uint8_t>& flags)
{
    std::vector<QCPRange> spans;
    const std::size_t n = std::min(times.size(), flags.size());
    for (std::size_t k = 0; k < n; ++k) {
        if (!flags[k] || (k > 0 && flags[k - 1]))
            continue;
        std::size_t end = k;
        while (end < n && flags[end])
            ++end;
        // A run up to the last sample reaches one sample interval past it, like any other run.
        const double lastInterval_s = n >= 2 ? times[n - 1] - times[n - 2] : 0.0;
        spans.emplace_back(times[k], end < n ? times[end] : times[n - 1] + lastInterval_s);
    }
    return spans;
}

void setUpLane(QCPAxisRect* lane, const QString& name)
{
    auto ticker = QSharedPointer<QCPAxisTickerText>::create();
    ticker->addTick(0.5, name);
    QCPAxis* levels = lane->axis(QCPAxis::atLeft);
    levels->setTicker(ticker);
    levels->setRange(0.0, 1.0);
    levels->setTickLength(0, 0);
    levels->setSubTicks(false);
    levels->grid()->setVisible(false);
    lane->axis(QCPAxis::atBottom)->grid()->setVisible(false);
    lane->axis(QCPAxis::atBottom)->setTicks(false);
}

QFont laneLabelFont(const QCustomPlot* plot)
{
    QFont font = plot->font();
    font.setPointSizeF(font.pointSizeF() * 0.85);
    return font;
}

TimeBands::TimeBands(QCPAxisRect* rect, const QBrush& brush)
    : QCPLayerable(rect->parentPlot(), QString(), rect), rect_(rect), brush_(brush)
{
}

bool TimeBands::contains(double time_s) const
{
    const auto after = std::upper_bound(spans_.cbegin(), spans_.cend(), time_s,
                                        [](double t, const QCPRange& span) { return t < span.lower; });
    return after != spans_.cbegin() && time_s < (after - 1)->upper;
}

void TimeBands::draw(QCPPainter* painter)
{
    const QCPAxis* axis = rect_->axis(QCPAxis::atBottom);
    const QRect area = rect_->rect();
    auto span = std::lower_bound(spans_.cbegin(), spans_.cend(), axis->range().lower,
                                 [](const QCPRange& s, double t) { return s.upper < t; });
    double left = 0.0, right = -1.0;  // the band being merged, in pixels; empty while right < left
    for (; span != spans_.cend() && span->lower <= axis->range().upper; ++span) {
        const double from = std::max(std::floor(axis->coordToPixel(span->lower)), area.left() - 1.0);
        const double to = std::min(std::max(from + 1.0, std::ceil(axis->coordToPixel(span->upper))), area.right() + 1.0);
        if (from <= right) {
            right = std::max(right, to);
            continue;
        }
        fillBand(painter, left, right);
        left = from;
        right = to;
    }
    fillBand(painter, left, right);
}

void TimeBands::fillBand(QCPPainter* painter, double left, double right) const
{
    if (right <= left)
        return;
    if (!levels_) {
        painter->fillRect(QRectF(left, rect_->top(), right - left, rect_->height()), brush_);
        return;
    }
    const QCPAxis* values = rect_->axis(QCPAxis::atLeft);
    const double top = values->coordToPixel(levels_->upper);
    painter->fillRect(QRectF(left, top, right - left, values->coordToPixel(levels_->lower) - top), brush_);
}

}  // namespace footpath
