#pragma once

#include "Recording.h"

#include <string>
#include <vector>

namespace footpath {

/// Whether a sample can be estimated at all: finite time, accelerometer and gyroscope values.
/// (Magnetometer and pressure are NaN when absent, so they are not checked here.)
bool hasFiniteInertialValues(const ImuSample& sample);

/// Why the samples cannot be estimated, or empty: a time that is not finite or goes backwards
/// breaks every time window (the detector's queues assume order), and a single non-finite
/// accelerometer or gyroscope value makes every later state NaN. Names the first offending sample
/// (1-based, with its time) and how many more there are, so the user can find the damage.
std::string describeUnusableSamples(const std::vector<ImuSample>& samples);

/// A warning per sensor axis whose samples sit at one extreme value in runs, as a clipped sensor's
/// do (a MEMS accelerometer at +-16 g, a gyroscope at +-2000 deg/s): during those samples the
/// motion was larger than the sensor reports, so the path is too short or bends. Only values beyond
/// what a foot at rest gives (2 g, 3 rad/s) count, so a still, noise-free sensor is no finding.
std::vector<std::string> describeSaturation(const std::vector<ImuSample>& samples);

}  // namespace footpath
