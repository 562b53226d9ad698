#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Parameters.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace footpath {

class ErrorStateEkf;
class StanceFlagsAhead;

struct AlignmentResult {
    Eigen::Matrix3d bodyToNav = Eigen::Matrix3d::Identity();
    double roll_rad = 0.0;
    double pitch_rad = 0.0;
    double yaw_rad = 0.0;
    std::size_t samplesUsed = 0;
    bool headingFromMagnetometer = false;
};

/// Where the filter starts: sample 0 when the recording starts in stance (or has no stance at all);
/// otherwise the recording starts mid-walk and the filter waits for the first stance sample, as
/// starting on a moving foot would assume zero velocity where there is none and integrate a swing
/// from the wrong attitude. The samples before it are held at the start state (holdAtStart) and
/// the NoInitialRest warning says so. The first stance is used even when it is shorter than
/// alignment_s: waiting for a long rest would drop a whole walk that never stops.
std::size_t alignmentStart(const std::vector<std::uint8_t>& stance);

/// Guo 2015 section 2.1: roll/pitch from the mean specific force (eq. 1-2), heading from the
/// tilt-compensated magnetometer minus the declination (the printed eq. 3-5 are garbled; this is
/// the standard tilt compensation), heading 0 without a magnetometer.
/// Averages the samples in the params.alignment_s seconds from alignmentStart() on that the detector calls stance,
/// so a walk that starts moving before alignment_s ends does not tilt the start; if none of them
/// is at rest, all samples in the period are used. (Starting the gyro bias at the mean rate of
/// this period was tried and measured worse on the real recordings; ZARU estimates it instead.)
AlignmentResult alignInitialAttitude(const std::vector<ImuSample>& samples, const std::vector<std::uint8_t>& stance,
                                     const Parameters& params);

/// While ahead decides the flags of stance on another thread, waits for those alignInitialAttitude
/// reads: up to the first stance sample and over the alignment period after it. Returns that
/// sample, alignmentStart(stance).
std::size_t waitForAlignmentFlags(StanceFlagsAhead& ahead, const std::vector<ImuSample>& samples,
                                  const std::vector<std::uint8_t>& stance, double alignment_s);

/// The state a sample before alignmentStart() gets: the initial one (start position, at rest, the
/// aligned attitude), recorded as filterSample records a filtered one.
void holdAtStart(const ErrorStateEkf& ekf, double time_s, Result& result);

/// Heading (yaw about z up, counter-clockwise from x = north) from one magnetometer reading and the
/// level attitude, minus the declination (positive east).
double magneticHeading(const Eigen::Vector3d& magBody, double roll, double pitch, double declination_rad);

}  // namespace footpath
