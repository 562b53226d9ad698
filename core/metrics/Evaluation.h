#pragma once

#include "Recording.h"
#include "Result.h"

#include <Eigen/Core>

#include <vector>

namespace footpath {

/// The ARMSE of docs/accuracy.md: trajectory error against a reference position at every sample.
struct ArmseResult {
    double armse2d_m = 0.0;
    double armse3d_m = 0.0;
    std::size_t alignmentIndex = 0;  ///< sample used for the rotation about z
    double rotation_rad = 0.0;       ///< rotation applied to the estimate
};

/// estimate and reference must have the same length (>= 1). Mirroring of axes is the caller's job.
/// Both are translated to start at the origin; the estimate is rotated about z so that its horizontal
/// position at alignmentIndex (first sample >= 0.8 m from the start, else sample 300 clamped to the
/// last sample) points like the reference's there (no rotation if either vector has zero length).
/// Empty or mismatched input does not throw: armse2d_m, armse3d_m and rotation_rad are NaN.
ArmseResult computeArmse(const std::vector<Eigen::Vector3d>& estimate,
                         const std::vector<Eigen::Vector3d>& reference);

/// Section 2: loop closure (DBSE). The percentage uses referenceLength_m when > 0, else pathLength_m.
/// dbse_m is horizontal. dbsePct is 0 when the length used is 0; both are NaN when positions is empty.
struct LoopClosure {
    double dbse_m = 0.0;
    double dbsePct = 0.0;
    double lengthUsed_m = 0.0;
};
LoopClosure computeLoopClosure(const std::vector<Eigen::Vector3d>& positions, double pathLength_m,
                               double referenceLength_m = 0.0);

/// Section 3: path length as the sum of horizontal distances between consecutive stance positions.
double stancePathLength(const std::vector<Step>& steps);

/// The reference positions moved into the estimate's frame the way the ARMSE aligns the estimate
/// to the reference (same start, rotation about z fixed at the 0.8 m sample, via
/// computeArmse), so the distance between an estimate sample and its overlaid reference sample is
/// the error the ARMSE averages. Empty when the lengths differ or either is empty: no overlay is
/// better than a misleading one.
std::vector<Eigen::Vector3d> alignReferenceToEstimate(const std::vector<Eigen::Vector3d>& reference,
                                                      const std::vector<Eigen::Vector3d>& estimate);

struct DistanceError {
    double estimated_m = 0.0;
    double reference_m = 0.0;
    double error_m = 0.0;  ///< |estimated - reference|
    double errorPct = 0.0; ///< error_m / reference_m * 100; NaN when reference_m <= 0
};
DistanceError computeDistanceError(double estimatedPathLength_m, double referenceLength_m);

/// Section 4: stance detection against hand-labelled gait events. Compared over the samples from
/// the first labelled swing to the last (clipped to the trial boundaries when given), where every
/// sample is either in a swing or between two swings (reference stance).
struct StanceScore {
    double precision = 0.0;  ///< of the detected stance samples, the share that are reference stance
    double recall = 0.0;     ///< of the reference stance samples, the share detected
    double f1 = 0.0;
    std::size_t samplesCompared = 0;
    std::size_t detectedPhases = 0;   ///< stance runs that start inside the window
    std::size_t referencePhases = 0;  ///< gaps between consecutive swings
    long stepCountError = 0;          ///< detected - reference
};
StanceScore scoreStanceDetection(const std::vector<std::uint8_t>& stance, const std::vector<SampleRange>& swings,
                                 const SampleRange* trialBoundaries = nullptr);

/// Section 4's step-count error, on the strides the user sees (the steps after their merging, not
/// the detector's raw stance runs, which a flicker splits): the strides whose swing (the middle
/// between a step's stance and the one before) lies inside the trial, against the labelled swings
/// inside it. Without trial boundaries, the span of the labelled swings stands for the trial.
struct StrideCount {
    std::size_t detected = 0;
    std::size_t labelled = 0;
    long error = 0;  ///< detected - labelled
};
StrideCount countStrides(const Result& result, const std::vector<SampleRange>& swings,
                         const SampleRange* trialBoundaries = nullptr);

/// Section 4, gait events: how far detected events lie from hand-labelled ones. For every reference
/// event inside the window, the error is the distance to the nearest detected event (a missed
/// event counts with the distance to the next one found, so misses raise the figures).
struct EventTimingScore {
    std::size_t referenceEvents = 0;  ///< reference events inside the window
    double medianError_s = 0.0;       ///< NaN when there is no reference or no detected event
    double meanError_s = 0.0;
    double maxError_s = 0.0;
    std::size_t missed = 0;  ///< reference events with no detected one within missTolerance_s
};
/// detected_s and reference_s in any order; only reference events in [windowStart_s, windowEnd_s]
/// count (detected events outside the window still count as nearest).
EventTimingScore scoreEventTiming(const std::vector<double>& detected_s, const std::vector<double>& reference_s,
                                  double windowStart_s, double windowEnd_s, double missTolerance_s = 0.15);

/// Heel-strike and toe-off timing of result.gaitEvents against the labelled swings of reference
/// (a swing's first sample is a toe off, its last a heel strike; times from result.time_s), over
/// the trial boundaries when the reference has them.
struct GaitEventTiming {
    EventTimingScore heelStrike;
    EventTimingScore toeOff;
};
GaitEventTiming scoreGaitEventTiming(const Result& result, const Reference& reference);

}  // namespace footpath
