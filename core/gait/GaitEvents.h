#pragma once

#include "Recording.h"
#include "Result.h"

#include <vector>

namespace footpath {

/// Finds the gait events of every stride and the gait parameters (Result::gaitEvents,
/// gaitStrides, gaitStance, gait) from the angular rate and the estimated foot motion.
///
/// Method (the sagittal angular rate of a foot-mounted IMU, as in the gait literature):
/// - the sagittal axis is the body axis the foot turns about most: the principal axis of the
///   angular rate averaged over 0.1 s (impacts ringing through the gyro must not tilt it), signed
///   so that the foot turns positively about it in mid-swing (toe rising while the estimated foot
///   moves forwards). The rate about it is then negative at push-off and after heel strike and
///   has one large positive peak per swing;
/// - a swing is a peak of the averaged rate above 1 rad/s while the estimated foot moves faster
///   than 0.3 m/s; peaks the rate does not go negative between are one swing, and a "swing"
///   shorter than 0.1 s is an impact;
/// - toe off is where the rate, rising from its push-off minimum before the swing, has recovered
///   half of that minimum; heel strike is where the rate after the swing, falling to its minimum
///   (the foot slapping flat), has reached half of it. Half the dip is where the rate changes
///   fastest between rest and swing; against the hand-labelled IPOL events it lies within about
///   a sample, where the minima themselves are 30 ms off;
/// - foot flat and heel off bound the quiet part of the stance: the samples whose |w| stays
///   within 0.5 rad/s of the stance's quietest.
/// Times are interpolated between samples, so the result does not depend on the rate (100-200 Hz);
/// a gyro reading is taken as the mean rate of the interval before its time stamp, as the
/// strapdown takes it (half an interval, 5 ms at 100 Hz, which the IPOL labels confirm).
/// Measured against the hand-labelled IPOL walks: gait-stance F1 0.97-0.99, median heel-strike
/// and toe-off errors 2-15 ms per trial (tests/tst_gaitevents.cpp).
void detectGaitEvents(const Recording& recording, Result& result);

/// What detectGaitEvents reads of the gyro alone, one pass over the samples that needs no estimate:
/// runPipeline computes it on the stance detector's thread while the filter runs. Reading the
/// samples (88 bytes each, long out of cache by then) was a third of the gait detection's time.
struct GaitRates {
    /// The rate about the principal axis of the rate averaged over 0.1 s, of each reading and of
    /// each average; unsigned: which way round the axis points needs the estimated motion.
    std::vector<double> rawAlongAxis, smoothedAlongAxis;
    std::vector<double> squaredNorm, l1Norm;  ///< |w|^2 and |w|_1 of each reading
};
GaitRates gaitRatesOf(const std::vector<ImuSample>& samples);

/// detectGaitEvents with the rates already computed (gaitRatesOf(recording.samples)).
void detectGaitEvents(const Recording& recording, GaitRates rates, Result& result);

/// For each of result.steps (ZUPT stances) the gait stride whose stance (heel strike to toe off)
/// holds the middle of the step's stance, or nullptr; each stride goes to the first such step only.
/// The steps CSV and the step table show the gait figures of a step through it.
std::vector<const GaitStride*> gaitStridesOfSteps(const Result& result);

/// The heading change above which a stride counts as turning (and leaves the walk's averages).
constexpr double kTurningStrideThreshold_rad = 0.349066;  // 20 degrees

}  // namespace footpath
