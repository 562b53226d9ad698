#pragma once

#include "Result.h"
#include "nav/Parameters.h"

#include <vector>

namespace footpath {

/// Limits of human gait that a result is checked against. Generous on purpose: a warning must mean
/// that something is wrong, not that someone walked briskly.
struct PlausibilityLimits {
    double maxSwing_s = 2.0;          ///< no stance for longer than this while moving: a missed stance
    double maxStrideLength_m = 3.0;   ///< a running stride is 2-3 m; more is a missed stance or drift
    double minStrideDuration_s = 0.4; ///< a sprinter's stride takes 0.6 s; a quicker one that still
    double minStrideLength_m = 0.5;   ///< covers this much had a stance found in its swing
    double maxFootSpeed_mps = 12.0;   ///< a running foot peaks near 10 m/s
    double minStanceShare = 0.10;     ///< walking keeps the foot still 25-60 % of the time, running 15-30 %
    double maxStanceShare = 0.90;     ///< of the time between the first and the last stance while moving
    double minInitialRestShare = 0.5; ///< of the samples of the alignment period
    double maxQuietHold_s = 0.25;     ///< samples held before a late first stance without a warning:
                                      ///< a few at the start are the detector's window edge, not a walk
    double movingSpeed_mps = 0.3;     ///< a span is "moving" when the estimated speed exceeds this
    double maxBarometerGap_m = 2.0;   ///< stance heights this far from the barometer's: two thirds of
                                      ///< a 3 m floor (the shared walks' gaps are 0.2-1.5 m or 2.2-6.7 m)
};

/// Checks a result for what cannot be human gait: the recording does not start at rest, swings
/// without a stance, strides too long, the filter running away (foot speed), a stance share far
/// from gait, too few stances, and stance heights far from the barometer's when it is not fused.
/// Each finding names its time span and what blocked the detector where a stance was missed. The
/// result must hold its samples, flags and steps (with their barometric heights, MotionClasses).
std::vector<PlausibilityWarning> checkPlausibility(const Result& result, const Parameters& params,
                                                   const PlausibilityLimits& limits = PlausibilityLimits());

}  // namespace footpath
