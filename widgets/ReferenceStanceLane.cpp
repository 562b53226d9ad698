#include "ReferenceStanceLane.h"

#include "StanceFlagsPlotAxes.h"
#include "TimeBands.h"

#include <qcustomplot.h>

#include <algorithm>

namespace footpath {

namespace {

constexpr double kReferenceLow = 0.2, kReferenceHigh = 0.8;  // the reference lane's step curve, on its 0..1 axis

/// The recording's reference stance: the spans of stance within the time the reference covers.
struct ReferenceStance {
    std::vector<QCPRange> spans;
    QCPRange covered;
};

/// From the recording's reference stance flags when it has them (pyshoe's zv_vicon_opt: the whole
/// recording), else from the gaps between its hand-labelled swings (IPOL gait events: from the
/// first labelled swing to the last, the window evaluation compares; outside it nothing is known).
ReferenceStance referenceStanceOf(const Recording& recording, const std::vector<double>& times)
{
    const Reference& reference = recording.reference;
    ReferenceStance out;
    if (times.empty())
        return out;
    if (!reference.stance.empty()) {
        out.spans = flaggedSpans(times, reference.stance);
        out.covered = QCPRange(times.front(), times.back());
        return out;
    }
    for (std::size_t s = 1; s < reference.swings.size(); ++s) {
        const std::size_t from = reference.swings[s - 1].last + 1, to = reference.swings[s].first;
        if (from < to && to < times.size())
            out.spans.emplace_back(times[from], times[to]);
    }
    if (!out.spans.empty())
        out.covered = QCPRange(times[std::min(reference.swings.front().first, times.size() - 1)],
                               times[std::min(reference.swings.back().last, times.size() - 1)]);
    return out;
}

}  // namespace

ReferenceStanceLane::ReferenceStanceLane(QCustomPlot* plot, QCPAxisRect* rect)
{
    setUpLane(rect, tr("Reference\nstance"));
    // As high as its two-line label: a lane of one flag needs no more.
    const int height = 2 * QFontMetrics(valueAxis(rect)->tickLabelFont()).height() + 6;
    rect->setMinimumSize(0, height);
    rect->setMaximumSize(QWIDGETSIZE_MAX, height);
    fill_ = new TimeBands(rect, QColor(240, 170, 60, 150));
    fill_->setLevels(kReferenceLow, kReferenceHigh);
    fill_->setLayer(QStringLiteral("main"));
    curve_ = plot->addGraph(timeAxis(rect), valueAxis(rect));
    curve_->setName(tr("Reference stance"));
    curve_->setLineStyle(QCPGraph::lsStepLeft);
    curve_->setPen(QPen(QColor(40, 40, 40), 1.0));
    curve_->setSelectable(QCP::stNone);
}

void ReferenceStanceLane::setRecording(const Recording* recording, const std::vector<double>& times)
{
    const ReferenceStance reference = recording ? referenceStanceOf(*recording, times) : ReferenceStance();
    const std::vector<QCPRange>& spans = reference.spans;
    fill_->setSpans(spans);
    QVector<double> keys, values;
    if (!spans.empty()) {  // a step curve over the covered time: up at each span, down after it
        keys << reference.covered.lower;
        values << (spans.front().lower <= reference.covered.lower ? kReferenceHigh : kReferenceLow);
        for (const QCPRange& span : spans) {
            keys << span.lower << span.upper;
            values << kReferenceHigh << kReferenceLow;
        }
        if (keys.back() < reference.covered.upper) {
            keys << reference.covered.upper;
            values << kReferenceLow;
        }
    }
    curve_->setData(keys, values, true);
    source_.clear();
    if (recording && !recording->reference.stance.empty())
        source_ = tr("from the recording's reference stance column (zero velocity by motion capture)");
    else if (!spans.empty())
        source_ = tr("between the hand-labelled gait events (toe-off, heel-strike)");
}

bool ReferenceStanceLane::hasStance() const { return !fill_->isEmpty(); }
bool ReferenceStanceLane::isStance(double time_s) const { return fill_->contains(time_s); }

std::optional<QString> ReferenceStanceLane::readout(const QCPGraph* graph, double value) const
{
    if (graph != curve_)
        return std::nullopt;
    return value > kReferenceLow ? tr("stance") : tr("swing");
}

}  // namespace footpath
