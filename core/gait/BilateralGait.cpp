#include "gait/BilateralGait.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace footpath {

namespace {

/// Length of the intersection of [a0, a1] and [b0, b1] (0 when they do not meet).
double overlap(double a0, double a1, double b0, double b1)
{
    return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

DoubleSupportSummary meansOf(const std::vector<CycleDoubleSupport>& cycles, std::size_t unpaired)
{
    DoubleSupportSummary summary;
    summary.cycles = cycles.size();
    summary.unpairedCycles = unpaired;
    if (cycles.empty())
        return summary;
    double total = 0.0, initial = 0.0, terminal = 0.0;
    for (const CycleDoubleSupport& cycle : cycles) {
        total += cycle.pct;
        initial += 100.0 * cycle.initial_s / cycle.cycle_s;
        terminal += 100.0 * cycle.terminal_s / cycle.cycle_s;
    }
    const auto n = static_cast<double>(cycles.size());
    summary.meanPct = total / n;
    summary.initialPct = initial / n;
    summary.terminalPct = terminal / n;
    return summary;
}

/// The walk's means of one foot's strides, NaN where that foot has no straight stride.
double walkMean(const GaitSummary& gait, double GaitSummary::*field)
{
    return gait.straightStrides > 0 ? gait.*field : std::numeric_limits<double>::quiet_NaN();
}

GaitSymmetry symmetryOf(const GaitSummary& left, const GaitSummary& right)
{
    GaitSymmetry symmetry;
    const auto index = [&](double GaitSummary::*field) {
        return symmetryIndexPct(walkMean(left, field), walkMean(right, field));
    };
    symmetry.strideTimePct = index(&GaitSummary::strideTime_s);
    symmetry.strideLengthPct = index(&GaitSummary::strideLength_m);
    symmetry.stancePct = index(&GaitSummary::stancePct);
    symmetry.swingPct = index(&GaitSummary::swingPct);
    return symmetry;
}

/// The share of the shorter recording's time the other one covers too.
double sharedTimeFraction(const Result& a, const Result& b)
{
    if (a.time_s.size() < 2 || b.time_s.size() < 2)
        return 0.0;
    const double shared = overlap(a.time_s.front(), a.time_s.back(), b.time_s.front(), b.time_s.back());
    const double shorter = std::min(a.time_s.back() - a.time_s.front(), b.time_s.back() - b.time_s.front());
    return shorter > 0.0 ? shared / shorter : 0.0;
}

/// other's position at time t, linear between samples; false outside its time span.
bool positionAt(const Result& other, double t, std::size_t& cursor, Eigen::Vector3d& position)
{
    const std::vector<double>& time = other.time_s;
    while (cursor + 1 < time.size() && time[cursor + 1] < t)
        ++cursor;
    if (cursor + 1 >= time.size() || t < time[cursor])
        return false;
    const double span = time[cursor + 1] - time[cursor];
    const double w = span > 0.0 ? (t - time[cursor]) / span : 0.0;
    position = (1.0 - w) * other.position_m[cursor] + w * other.position_m[cursor + 1];
    return true;
}

/// The detector's cycles of a result, counted when they lie inside the recording's labelled trial.
std::vector<GaitCycle> cyclesInsideTrial(const Recording& recording, const Result& result)
{
    std::vector<GaitCycle> cycles = cyclesOf(result.gaitStrides);
    const Reference& reference = recording.reference;
    const bool bounded = reference.hasTrialBoundaries && reference.trialBoundaries.last < recording.samples.size();
    const double first = bounded ? recording.samples[reference.trialBoundaries.first].time_s : -std::numeric_limits<double>::infinity();
    const double last = bounded ? recording.samples[reference.trialBoundaries.last].time_s : std::numeric_limits<double>::infinity();
    for (GaitCycle& cycle : cycles)
        cycle.counted = cycle.heelStrike_s >= first && cycle.nextHeelStrike_s <= last;
    return cycles;
}

/// Means over the strides of both lists whose heel strikes lie within 0.1 s of each other (a
/// tenth of a stride: the other foot strikes half a stride away).
void matchStrides(const std::vector<CycleDoubleSupport>& labelled, const std::vector<CycleDoubleSupport>& detected,
                  DoubleSupportCheck& check)
{
    constexpr double kMatch_s = 0.1;
    double labelledSum = 0.0, detectedSum = 0.0;
    for (const CycleDoubleSupport& label : labelled) {
        const auto found = std::find_if(detected.begin(), detected.end(), [&label](const CycleDoubleSupport& d) {
            return std::abs(d.heelStrike_s - label.heelStrike_s) < kMatch_s;
        });
        if (found == detected.end())
            continue;
        ++check.matchedStrides;
        labelledSum += label.pct;
        detectedSum += found->pct;
    }
    if (check.matchedStrides == 0)
        return;
    check.matchedLabelledPct = labelledSum / static_cast<double>(check.matchedStrides);
    check.matchedDetectedPct = detectedSum / static_cast<double>(check.matchedStrides);
}

}  // namespace

double symmetryIndexPct(double left, double right)
{
    const double sum = left + right;
    if (!std::isfinite(left) || !std::isfinite(right) || sum == 0.0)
        return std::numeric_limits<double>::quiet_NaN();
    return 200.0 * (left - right) / sum;
}

std::vector<FootSwing> swingsOf(const std::vector<GaitEvent>& events)
{
    std::vector<FootSwing> swings;
    double toeOff = std::numeric_limits<double>::quiet_NaN();  // NaN: no toe off since the last heel strike
    for (const GaitEvent& event : events) {
        if (event.kind == GaitEventKind::ToeOff)
            toeOff = event.time_s;
        else if (event.kind == GaitEventKind::HeelStrike && !std::isnan(toeOff)) {
            swings.push_back({toeOff, event.time_s});
            toeOff = std::numeric_limits<double>::quiet_NaN();
        }
    }
    return swings;
}

std::vector<FootSwing> referenceSwings(const Recording& recording)
{
    std::vector<FootSwing> swings;
    for (const SampleRange& swing : recording.reference.swings)
        if (swing.first <= swing.last && swing.last < recording.samples.size())
            swings.push_back({recording.samples[swing.first].time_s, recording.samples[swing.last].time_s});
    return swings;
}

std::vector<GaitCycle> cyclesBetween(const std::vector<FootSwing>& swings)
{
    std::vector<GaitCycle> cycles;
    for (std::size_t i = 0; i + 1 < swings.size(); ++i)
        cycles.push_back({swings[i].heelStrike_s, swings[i + 1].toeOff_s, swings[i + 1].heelStrike_s, true});
    return cycles;
}

std::vector<GaitCycle> cyclesOf(const std::vector<GaitStride>& strides)
{
    std::vector<GaitCycle> cycles;
    for (const GaitStride& stride : strides)
        cycles.push_back({stride.heelStrike.time_s, stride.toeOff.time_s, stride.nextHeelStrike.time_s,
                          !stride.turning && !stride.paused});
    return cycles;
}

namespace {

using SwingIterator = std::vector<FootSwing>::const_iterator;

/// doubleSupportIn over the other foot's swings [first, last).
std::optional<CycleDoubleSupport> doubleSupportAmong(const GaitCycle& cycle, SwingIterator first, SwingIterator last)
{
    const double start = cycle.heelStrike_s, end = cycle.nextHeelStrike_s;
    if (!(end > start) || cycle.toeOff_s < start || cycle.toeOff_s > end)
        return std::nullopt;
    // In walking and running alike the other foot lifts off once and strikes once in each cycle;
    // anything else is a swing missed or found twice on one of the feet.
    std::size_t toeOffs = 0, heelStrikes = 0;
    double otherHeelStrike = end;
    for (auto swing = first; swing != last; ++swing) {
        toeOffs += swing->toeOff_s > start && swing->toeOff_s <= end;
        if (swing->heelStrike_s > start && swing->heelStrike_s <= end) {
            ++heelStrikes;
            otherHeelStrike = swing->heelStrike_s;
        }
    }
    if (toeOffs != 1 || heelStrikes != 1)
        return std::nullopt;
    // Both feet are down where this foot stands (start to its toe off) and the other is in none of
    // its swings: before the other's heel strike that is the initial double support, after it the
    // terminal one.
    const auto together = [first, last](double from, double to) {
        double time = std::max(0.0, to - from);
        for (auto swing = first; swing != last; ++swing)
            time -= overlap(from, to, swing->toeOff_s, swing->heelStrike_s);
        return std::max(0.0, time);
    };
    CycleDoubleSupport support;
    support.heelStrike_s = start;
    support.cycle_s = end - start;
    support.initial_s = together(start, std::min(cycle.toeOff_s, otherHeelStrike));
    support.terminal_s = together(otherHeelStrike, cycle.toeOff_s);
    support.pct = 100.0 * (support.initial_s + support.terminal_s) / support.cycle_s;
    return support;
}

/// True if every swing's toe off comes no later than its heel strike and both times ascend along
/// the list (false for NaN), as swingsOf and referenceSwings give them.
bool inTimeOrder(const std::vector<FootSwing>& swings)
{
    for (std::size_t i = 0; i < swings.size(); ++i) {
        if (!(swings[i].toeOff_s <= swings[i].heelStrike_s))
            return false;
        if (i > 0
            && !(swings[i - 1].toeOff_s <= swings[i].toeOff_s && swings[i - 1].heelStrike_s <= swings[i].heelStrike_s))
            return false;
    }
    return true;
}

/// Of swings in time order, the run that can matter in the cycle: the others strike by its start
/// (so lift off by then too) or lift off after its end. They add no toe off or heel strike inside
/// the cycle and overlap none of its parts, so doubleSupportAmong gives over the run what it gives
/// over all, to the last bit (each swing left out subtracted zero).
std::pair<SwingIterator, SwingIterator> swingsMeeting(const GaitCycle& cycle, const std::vector<FootSwing>& swings)
{
    const auto first = std::partition_point(swings.begin(), swings.end(), [&cycle](const FootSwing& swing) {
        return swing.heelStrike_s <= cycle.heelStrike_s;
    });
    const auto last = std::partition_point(first, swings.end(), [&cycle](const FootSwing& swing) {
        return swing.toeOff_s <= cycle.nextHeelStrike_s;
    });
    return {first, last};
}

}  // namespace

std::optional<CycleDoubleSupport> doubleSupportIn(const GaitCycle& cycle, const std::vector<FootSwing>& otherSwings)
{
    return doubleSupportAmong(cycle, otherSwings.begin(), otherSwings.end());
}

DoubleSupportSummary summariseDoubleSupport(const std::vector<GaitCycle>& cycles,
                                            const std::vector<FootSwing>& otherSwings,
                                            std::vector<CycleDoubleSupport>* perCycle)
{
    // Each cycle looks at the few swings that meet it (two binary searches) instead of all of
    // them, which made a long walk's analysis quadratic in its strides.
    const bool ordered = inTimeOrder(otherSwings);
    std::vector<CycleDoubleSupport> values;
    std::size_t unpaired = 0;
    for (const GaitCycle& cycle : cycles) {
        if (!cycle.counted)
            continue;
        const auto [first, last] =
            ordered ? swingsMeeting(cycle, otherSwings) : std::make_pair(otherSwings.begin(), otherSwings.end());
        if (const std::optional<CycleDoubleSupport> support = doubleSupportAmong(cycle, first, last))
            values.push_back(*support);
        else
            ++unpaired;
    }
    if (perCycle)
        perCycle->insert(perCycle->end(), values.begin(), values.end());
    return meansOf(values, unpaired);
}

BilateralGait doubleSupportOfWalk(const std::vector<GaitCycle>& leftCycles, const std::vector<FootSwing>& leftSwings,
                                  const std::vector<GaitCycle>& rightCycles, const std::vector<FootSwing>& rightSwings)
{
    BilateralGait walk;
    walk.leftCycles = summariseDoubleSupport(leftCycles, rightSwings, &walk.perCycle);
    walk.rightCycles = summariseDoubleSupport(rightCycles, leftSwings, &walk.perCycle);
    std::sort(walk.perCycle.begin(), walk.perCycle.end(),
              [](const CycleDoubleSupport& a, const CycleDoubleSupport& b) { return a.heelStrike_s < b.heelStrike_s; });
    walk.doubleSupport = meansOf(walk.perCycle, walk.leftCycles.unpairedCycles + walk.rightCycles.unpairedCycles);
    const std::size_t paired = walk.doubleSupport.cycles, unpaired = walk.doubleSupport.unpairedCycles;
    if (paired + unpaired == 0)
        walk.warnings.push_back("no straight walking stride on both feet: no double support");
    else if (unpaired > paired)
        walk.warnings.push_back("in " + std::to_string(unpaired) + " of " + std::to_string(paired + unpaired)
                                + " strides the other foot did not swing once: the two files may not be one walk on "
                                  "one clock (their time stamps are taken as they are)");
    return walk;
}

BilateralGait analyseBilateralGait(const Result& left, const Result& right)
{
    BilateralGait walk = doubleSupportOfWalk(cyclesOf(left.gaitStrides), swingsOf(left.gaitEvents),
                                             cyclesOf(right.gaitStrides), swingsOf(right.gaitEvents));
    walk.left = left.gait;
    walk.right = right.gait;
    walk.symmetry = symmetryOf(left.gait, right.gait);
    if (sharedTimeFraction(left, right) < 0.5)
        walk.warnings.insert(walk.warnings.begin(),
                             "the two recordings share less than half their time: they may not be one walk");
    return walk;
}

std::optional<DoubleSupportCheck> checkDoubleSupportAgainstLabels(const Recording& leftRecording, const Result& left,
                                                                  const Recording& rightRecording, const Result& right)
{
    const std::vector<FootSwing> leftLabels = referenceSwings(leftRecording);
    const std::vector<FootSwing> rightLabels = referenceSwings(rightRecording);
    if (leftLabels.empty() || rightLabels.empty())
        return std::nullopt;
    const BilateralGait labelled =
        doubleSupportOfWalk(cyclesBetween(leftLabels), leftLabels, cyclesBetween(rightLabels), rightLabels);
    const BilateralGait detected =
        doubleSupportOfWalk(cyclesInsideTrial(leftRecording, left), swingsOf(left.gaitEvents),
                            cyclesInsideTrial(rightRecording, right), swingsOf(right.gaitEvents));
    DoubleSupportCheck check;
    check.labelled = labelled.doubleSupport;
    check.detected = detected.doubleSupport;
    matchStrides(labelled.perCycle, detected.perCycle, check);
    return check;
}

std::vector<Eigen::Vector3d> otherFootPathAligned(const Result& foot, const Result& other)
{
    // Two passes over the samples both paths cover, instead of copies of both (a long walk's
    // copies ran to hundreds of MB): their centres, then the fit.
    const auto forEachPair = [&foot, &other](const auto& visit) {
        std::size_t cursor = 0;
        for (std::size_t k = 0; k < foot.time_s.size() && k < foot.position_m.size(); ++k) {
            Eigen::Vector3d position;
            if (positionAt(other, foot.time_s[k], cursor, position))
                visit(foot.position_m[k], position);
        }
    };
    Eigen::Vector3d mineCentre = Eigen::Vector3d::Zero(), theirCentre = Eigen::Vector3d::Zero();
    std::size_t pairs = 0;
    forEachPair([&](const Eigen::Vector3d& mine, const Eigen::Vector3d& theirs) {
        mineCentre += mine;
        theirCentre += theirs;
        ++pairs;
    });
    if (pairs < 2)
        return {};
    mineCentre /= static_cast<double>(pairs);
    theirCentre /= static_cast<double>(pairs);
    // The rotation about z that best turns their centred horizontal positions onto mine (the 2D
    // Procrustes solution: the angle of the summed dot and cross products).
    double dot = 0.0, cross = 0.0;
    forEachPair([&](const Eigen::Vector3d& mine, const Eigen::Vector3d& theirs) {
        const Eigen::Vector3d a = theirs - theirCentre, b = mine - mineCentre;
        dot += a.x() * b.x() + a.y() * b.y();
        cross += a.x() * b.y() - a.y() * b.x();
    });
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(std::atan2(cross, dot), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d shift = mineCentre - turn * theirCentre;
    std::vector<Eigen::Vector3d> aligned;
    aligned.reserve(other.position_m.size());
    for (const Eigen::Vector3d& position : other.position_m)
        aligned.push_back(turn * position + shift);
    return aligned;
}

}  // namespace footpath
