#pragma once

#include "Recording.h"
#include "Result.h"

#include <Eigen/Core>

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace footpath {

/// Both feet of one walk: double support and left/right symmetry from the two feet's gait events
/// (core/gait/GaitEvents.h), each foot estimated from its own recording.
///
/// Time base: the two feet's event times must be on one clock. Footpath takes each file's own time
/// stamps as they are; the IPOL MTw files are on one clock (PacketCounter / rate, both sensors of a
/// trial counted by one Awinda station and starting together at 0). Files whose clocks differ (two
/// loggers started by hand) give unpaired cycles, which BilateralGait::warnings reports.

/// One swing of a foot: toe off to the next heel strike (seconds on the common clock).
struct FootSwing {
    double toeOff_s = 0.0;
    double heelStrike_s = 0.0;
};

/// One gait cycle of a foot: heel strike, toe off, the next heel strike.
struct GaitCycle {
    double heelStrike_s = 0.0;
    double toeOff_s = 0.0;
    double nextHeelStrike_s = 0.0;
    bool counted = true;  ///< enters the walk's means (false for turning and paused strides)
};

/// The double support of one cycle of a foot: both feet on the ground after its heel strike (until
/// the other foot's toe off) and before its toe off (from the other foot's heel strike).
struct CycleDoubleSupport {
    double heelStrike_s = 0.0;  ///< the cycle's
    double cycle_s = 0.0;       ///< heel strike to the next heel strike
    double initial_s = 0.0;
    double terminal_s = 0.0;
    double pct = 0.0;  ///< (initial + terminal) as % of the cycle time
};

struct DoubleSupportSummary {
    static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    double meanPct = kNone;          ///< mean over the counted, paired cycles
    double initialPct = kNone;       ///< its two parts, means of % of the cycle
    double terminalPct = kNone;
    std::size_t cycles = 0;          ///< counted cycles with a value
    std::size_t unpairedCycles = 0;  ///< counted cycles the other foot did not make exactly one swing in
};

/// Robinson's symmetry index, 100 (left - right) / ((left + right) / 2) %: 0 is symmetric, positive
/// means the left value is larger. NaN when either is not finite or both sum to zero.
double symmetryIndexPct(double left, double right);

struct GaitSymmetry {
    static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    double strideTimePct = kNone;    ///< symmetry indices of the per-foot means (GaitSummary)
    double strideLengthPct = kNone;
    double stancePct = kNone;
    double swingPct = kNone;
};

/// What the two feet of one walk give together.
struct BilateralGait {
    DoubleSupportSummary doubleSupport;  ///< over both feet's cycles
    DoubleSupportSummary leftCycles;     ///< over the left foot's cycles (against the right's swings)
    DoubleSupportSummary rightCycles;
    std::vector<CycleDoubleSupport> perCycle;  ///< both feet's counted paired cycles, in time order
    GaitSymmetry symmetry;
    GaitSummary left, right;
    std::vector<std::string> warnings;  ///< one sentence each: why figures are missing or doubtful
};

/// Each toe off with the heel strike that follows it (events in time order).
std::vector<FootSwing> swingsOf(const std::vector<GaitEvent>& events);
/// The hand-labelled swings of a recording's reference (toe-off and heel-strike samples) as times.
std::vector<FootSwing> referenceSwings(const Recording& recording);
/// The cycles between consecutive swings: heel strike of one, toe off and heel strike of the next.
std::vector<GaitCycle> cyclesBetween(const std::vector<FootSwing>& swings);
/// A result's strides as cycles; turning and paused strides are not counted.
std::vector<GaitCycle> cyclesOf(const std::vector<GaitStride>& strides);

/// The double support in one cycle, or nothing unless the other foot has exactly one toe off and
/// one heel strike in it (a missed or extra swing would make the figure meaningless).
std::optional<CycleDoubleSupport> doubleSupportIn(const GaitCycle& cycle, const std::vector<FootSwing>& otherSwings);
/// The counted cycles of one foot against the other foot's swings; perCycle gets each value.
DoubleSupportSummary summariseDoubleSupport(const std::vector<GaitCycle>& cycles,
                                            const std::vector<FootSwing>& otherSwings,
                                            std::vector<CycleDoubleSupport>* perCycle = nullptr);
/// Double support of a walk from both feet's cycles and swings (the mean over both feet's cycles).
BilateralGait doubleSupportOfWalk(const std::vector<GaitCycle>& leftCycles, const std::vector<FootSwing>& leftSwings,
                                  const std::vector<GaitCycle>& rightCycles, const std::vector<FootSwing>& rightSwings);

/// Double support (straight, not paused strides) and symmetry of the two feet's results.
BilateralGait analyseBilateralGait(const Result& left, const Result& right);

/// Double support against the hand-labelled swings both recordings carry (IPOL: the JSON's
/// LeftFootEvents and RightFootEvents): the labels' figure and the detector's over the same span,
/// every cycle inside each recording's labelled trial, turning ones included (the labels do not
/// mark turns). Nothing when either recording has no labelled swings.
/// matched*: the strides both have (heel strikes within 0.1 s of each other), where the two
/// figures differ only by the event timing, not by which strides count.
struct DoubleSupportCheck {
    DoubleSupportSummary labelled;
    DoubleSupportSummary detected;
    std::size_t matchedStrides = 0;
    double matchedLabelledPct = DoubleSupportSummary::kNone;
    double matchedDetectedPct = DoubleSupportSummary::kNone;
};
std::optional<DoubleSupportCheck> checkDoubleSupportAgainstLabels(const Recording& leftRecording, const Result& left,
                                                                  const Recording& rightRecording, const Result& right);

/// The other foot's path turned about z and shifted onto this foot's (least squares over the times
/// both cover, positions interpolated in time): each sensor's heading starts at its own zero, so
/// without this the two paths of one walk point in different directions. Empty when the two share
/// less than two samples of time.
std::vector<Eigen::Vector3d> otherFootPathAligned(const Result& foot, const Result& other);

}  // namespace footpath
