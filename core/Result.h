#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace footpath {

/// Per-sample outputs of the stance detector. Every flag is kept because the GUI plots all four.
struct StanceFlags {
    std::vector<std::uint8_t> c1;      ///< a_min < |a| < a_max
    std::vector<std::uint8_t> c2;      ///< std of |a| over the centred window below threshold
    std::vector<std::uint8_t> c3;      ///< |w| < w_max
    std::vector<std::uint8_t> c;       ///< c1 & c2 & c3
    std::vector<std::uint8_t> stance;  ///< the final decision: 1 = foot at rest
    /// The chosen detector's test statistic, log10, one per sample (for C1/C2/C3 the log10 of the
    /// C2 input, the std of |a|). Units depend on the detector (see detect/ZeroVelocityDetectors.h).
    std::vector<float> logStatistic;
    /// log10 of the threshold the statistic was compared against at each sample (adaptive
    /// detectors move it with the motion; fixed ones draw a flat line).
    std::vector<float> logThreshold;
};

/// What a plausibility check found wrong with a result, over the time span it concerns.
struct PlausibilityWarning {
    enum class Kind {
        NoInitialRest,      ///< the recording does not start with the foot at rest
        LongSwing,          ///< no stance for longer than a human swing (a missed stance)
        StrideLength,       ///< a stride longer than a human stride
        StrideDuration,     ///< a stride too quick for its length (a stance found mid-swing)
        StanceRatio,        ///< the share of stance time far from normal gait
        ImplausibleSpeed,   ///< the foot moved faster than a foot can (the filter ran away)
        FewStances,         ///< too few stance phases for the recording's length
        BarometerGap,       ///< stance heights far from the barometric ones (barometer not fused)
    };
    Kind kind = Kind::LongSwing;
    double start_s = 0.0;  ///< the span the finding concerns (recording time)
    double end_s = 0.0;
    std::string message;   ///< one sentence for the user, with the figures and why it matters
};

/// Stable identifier of a warning kind for JSON and CSV ("long_swing").
const char* warningKindName(PlausibilityWarning::Kind kind);

/// What a measurement method did or did not do over a span: "skipped: the field is 40 % stronger
/// than at alignment (steel nearby)", "not applied: the walk has no straight stretch along an axis".
/// Shown with the method's lane and listed in the summary, so a method that sat out says so.
struct MethodNote {
    std::string method;    ///< the source's short name ("mag", "iper")
    double start_s = 0.0;
    double end_s = 0.0;
    std::string message;
};

/// Zheng et al. 2016's per-step motion class, from the barometric height change and the pressure variance
/// between steps (Unknown without a barometer).
enum class MotionClass { Unknown, Level, StairsUp, StairsDown, ElevatorUp, ElevatorDown };

/// Stable identifier for JSON and CSV ("stairs_up").
const char* motionClassName(MotionClass motion);

/// One stance phase and the stride that led to it.
struct Step {
    double stanceStart_s = 0.0;
    double stanceEnd_s = 0.0;
    Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< mean position during the stance
    double strideLength_m = 0.0;    ///< horizontal distance from the previous stance (0 for the first)
    double strideDuration_s = 0.0;  ///< time since the previous stance started (0 for the first)
    MotionClass motion = MotionClass::Unknown;
    double baroHeight_m = std::nan("");  ///< barometric height at the stance against the first one; NaN without pressure
};

/// A movement between two stance phases that was no stride, so its two stances became one step: the
/// foot moved less than a stride's distance or never turned at a swing's rate (a weight shift while
/// standing, a moment the detector lost the stance). Listed so the merge is said, not hidden.
struct MergedMovement {
    double start_s = 0.0;         ///< the last stance sample before it
    double end_s = 0.0;           ///< the first stance sample after it
    double displacement_m = 0.0;  ///< between the mean positions of the two stances (3D: a stair rises)
    double peakRate_radps = 0.0;  ///< the highest |angular rate| measured between them
};

/// A gait event (gait-lab terms, not the ZUPT stance): found by core/gait/GaitEvents.h.
enum class GaitEventKind {
    HeelStrike,  ///< the foot meets the ground: stance begins
    FootFlat,    ///< the foot has come to rest: the quiet part of the stance begins
    HeelOff,     ///< the foot starts rolling over the toes: the quiet part ends
    ToeOff,      ///< the foot leaves the ground: swing begins
};

/// Stable identifier for JSON and CSV ("heel_strike").
const char* gaitEventKindName(GaitEventKind kind);

struct GaitEvent {
    GaitEventKind kind = GaitEventKind::HeelStrike;
    std::size_t sample = 0;  ///< the sample nearest the event
    double time_s = 0.0;     ///< interpolated between samples
};

/// Cadence, the one definition every figure uses: steps per minute for a stride time, counting both
/// feet (two steps per stride, the clinical convention). 0 for a stride time that is not positive.
inline double cadenceOf(double strideTime_s)
{
    return strideTime_s > 0.0 ? 2.0 * 60.0 / strideTime_s : 0.0;
}

/// One gait cycle of this foot: heel strike, its stance (foot flat, heel off, toe off) and the
/// swing up to the next heel strike.
struct GaitStride {
    GaitEvent heelStrike, footFlat, heelOff, toeOff, nextHeelStrike;
    double strideLength_m = 0.0;   ///< horizontal, between the quiet parts of the two stances
    double strideTime_s = 0.0;     ///< heel strike to the next heel strike
    double cadence_spm = 0.0;      ///< steps per minute (two steps per stride)
    double stancePct = 0.0;        ///< heel strike to toe off, % of the stride time
    double swingPct = 0.0;         ///< toe off to the next heel strike, % of the stride time
    double clearance_m = 0.0;      ///< highest point of the swing above the stance before it
    double headingChange_rad = 0.0;  ///< between the quiet parts of the two stances, signed (left +)
    bool turning = false;          ///< |headingChange_rad| above kTurningStrideThreshold_rad
    bool paused = false;           ///< the stance lasted longer than walking does (the walker stood)
};

/// Per-walk gait parameters: means over the strides that are neither turning nor paused.
struct GaitSummary {
    std::size_t strides = 0;         ///< all detected strides
    std::size_t straightStrides = 0; ///< the strides the means are over
    std::size_t turningStrides = 0;
    double strideLength_m = 0.0;
    double strideTime_s = 0.0;
    double cadence_spm = 0.0;        ///< cadenceOf(strideTime_s): of the mean stride time shown with it
    double stancePct = 0.0;
    double swingPct = 0.0;
    double clearance_m = 0.0;
};

struct Summary {
    std::size_t samples = 0;
    double duration_s = 0.0;
    std::size_t stancePhases = 0;
    std::size_t steps = 0;           ///< strides: stance phases after the first
    double pathLength_m = 0.0;       ///< horizontal, between consecutive stance positions
    double endToStart_m = 0.0;       ///< horizontal distance between first and last position
    double endToStartPct = 0.0;      ///< endToStart_m as % of pathLength_m (0 if no path)
    double runtime_s = 0.0;          ///< estimation alone, without file I/O
    // Zheng et al. 2016's motion classes, counted over the steps (all zero without a barometer)
    std::size_t stairStepsUp = 0;
    std::size_t stairStepsDown = 0;
    std::size_t elevatorRides = 0;      ///< consecutive elevator steps count as one ride
    double stairsClimb_m = 0.0;         ///< height gained on stairs (positive) ...
    double stairsDescent_m = 0.0;       ///< ... and lost (positive)
};

/// Where each 3-block starts in Result::errorStd (the order of ErrorStateEkf's error state).
struct ErrorStdIndex {
    static constexpr int attitude = 0;
    static constexpr int gyroBias = 3;
    static constexpr int position = 6;
    static constexpr int velocity = 9;
    static constexpr int accBias = 12;
};

/// Everything the views, exporters and the CLI need, so none of them recomputes estimation.
struct Result {
    std::vector<double> time_s;
    std::vector<Eigen::Vector3d> position_m;   ///< navigation frame, z up, relative to start
    std::vector<Eigen::Vector3d> velocity_mps;
    std::vector<Eigen::Vector3d> rollPitchYaw_rad;
    std::vector<Eigen::Vector3d> gyroBias_radps;
    std::vector<Eigen::Vector3d> accBias_mps2;
    /// One standard deviation of the estimate per sample, from the filter's covariance (or the
    /// smoother's), in the error-state order of ErrorStateEkf: attitude (rad, about the navigation
    /// axes), gyro bias, position, velocity, accelerometer bias; see ErrorStdIndex. Float: it is
    /// drawn as a band, not computed with. Empty when the estimator has no covariance (Feliz).
    std::vector<Eigen::Matrix<float, 15, 1>> errorStd;
    /// The forward filter's speed per sample when a smoother replaced velocity_mps (empty
    /// otherwise): a filter that ran away is flagged from it, however smooth the final path looks.
    std::vector<float> forwardSpeed_mps;
    StanceFlags flags;
    std::vector<Step> steps;
    /// The movements between stance phases that were merged instead of counted as strides, in time
    /// order (see appendStep in nav/Pipeline.h).
    std::vector<MergedMovement> mergedMovements;
    /// Gait events (core/gait/GaitEvents.h) of every stride, in time order, including the first
    /// toe off and the last heel strike that have no complete stride around them.
    std::vector<GaitEvent> gaitEvents;
    std::vector<GaitStride> gaitStrides;
    /// Per sample: 1 from heel strike to toe off (the gait lab's stance: the foot on the ground,
    /// longer than the ZUPT stance, which is the foot at rest), else 0. The event samples
    /// themselves count as swing, as in the IPOL labels. Before the first toe off and after the
    /// last heel strike the foot stands: 1.
    std::vector<std::uint8_t> gaitStance;
    GaitSummary gait;
    Summary summary;
    /// Findings of the plausibility checks (core/nav/Plausibility.h), in time order. Empty when the
    /// result looks like human walking or running.
    std::vector<PlausibilityWarning> warnings;
    /// What the optional measurement methods did or skipped, in time order per method.
    std::vector<MethodNote> methodNotes;
    bool cancelled = false;  ///< the progress callback asked to stop; the vectors are partial
};

}  // namespace footpath
