#pragma once

#include "Recording.h"
#include "nav/Parameters.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace footpath {

struct AlignmentResult {
    Eigen::Matrix3d bodyToNav = Eigen::Matrix3d::Identity();
    double roll_rad = 0.0;
    double pitch_rad = 0.0;
    double yaw_rad = 0.0;
    std::size_t samplesUsed = 0;
    bool headingFromMagnetometer = false;
};

/// Guo 2015 section 2.1: roll/pitch from the mean specific force (eq. 1-2), heading from the
/// tilt-compensated magnetometer minus the declination (the printed eq. 3-5 are garbled; this is
/// the standard tilt compensation), heading 0 without a magnetometer.
/// Averages the samples in the first params.alignment_s seconds that the detector calls stance,
/// so a walk that starts moving before alignment_s ends does not tilt the start; if none of them
/// is at rest, all samples in the period are used. (Starting the gyro bias at the mean rate of
/// this period was tried and measured worse on the real recordings; ZARU estimates it instead.)
AlignmentResult alignInitialAttitude(const std::vector<ImuSample>& samples, const std::vector<std::uint8_t>& stance,
                                     const Parameters& params);

/// Heading (yaw about z up, counter-clockwise from x = north) from one magnetometer reading and the
/// level attitude, minus the declination (positive east).
double magneticHeading(const Eigen::Vector3d& magBody, double roll, double pitch, double declination_rad);

}  // namespace footpath
