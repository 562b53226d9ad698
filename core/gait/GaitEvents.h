#pragma once

#include "Recording.h"
#include "Result.h"

#include <vector>

namespace footpath {

/// Finds the gait events of every stride and the gait parameters (Result::gaitEvents,
/// gaitStrides, gaitStance, gait) from the angular rate and the estimated foot motion.
///
/// Method (the sagittal angular rate of a foot-mounted IMU, as in the gait literature):
/// - the sagittal axis is the body axis the foot turns about most (the principal axis of the
///   angular rate), signed so that the foot turns positively about it in mid-swing (toe rising
///   while the estimated foot moves forwards): the rate is then negative at push-off and after
///   heel strike and has one large positive peak per swing;
/// - a swing is a positive peak that stands clear of the quiet stance and during which the
///   estimated foot moves; peaks without a push-off dip between them belong to one swing;
/// - toe off is where the rate, rising from its push-off minimum before the swing, has recovered
///   half of that minimum; heel strike is where the rate after the swing, falling to its minimum
///   (the foot slapping flat), has reached half of it. Half the dip puts the event where the
///   rate changes fastest between rest and swing, and measured against the hand-labelled IPOL
///   events this half-way point is unbiased where the minima themselves are 30 ms off;
/// - foot flat and heel off bound the quiet part of the stance: the samples whose |w| stays
///   within kQuietMargin of the stance's quietest.
/// Times are interpolated between samples, so the result does not depend on the rate (100-200 Hz).
void detectGaitEvents(const Recording& recording, Result& result);

/// The heading change above which a stride counts as turning (and leaves the walk's averages).
constexpr double kTurningStrideThreshold_rad = 0.349066;  // 20 degrees

}  // namespace footpath
