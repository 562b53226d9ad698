#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace footpath {

/// One inertial sample in SI units, as the core expects it after import.
/// Time comes from the recording and may have gaps: never assume a constant dt.
struct ImuSample {
    double time_s = 0.0;
    Eigen::Vector3d acc_mps2 = Eigen::Vector3d::Zero();   ///< specific force, body frame
    Eigen::Vector3d gyr_radps = Eigen::Vector3d::Zero();  ///< angular rate, body frame
    Eigen::Vector3d mag = Eigen::Vector3d::Constant(std::nan(""));  ///< any consistent unit; NaN if absent
    double pressure_pa = std::nan("");                    ///< NaN if absent

    bool hasMag() const { return !std::isnan(mag.x()); }
    bool hasPressure() const { return !std::isnan(pressure_pa); }
};

/// An inclusive range of sample indices.
struct SampleRange {
    std::size_t first = 0;
    std::size_t last = 0;
};

/// Reference data that may travel with a recording (for evaluation only).
struct Reference {
    std::vector<Eigen::Vector3d> positions_m;  ///< one per sample, empty if none
    bool closedLoop = false;                   ///< the walk ends where it started
    double knownLength_m = 0.0;                ///< 0 if unknown
    /// Hand-labelled gait events: each range spans one swing (toe-off to heel-strike); the samples
    /// between consecutive swings are stance. Indices refer to recording.samples.
    std::vector<SampleRange> swings;
    /// Stance by a reference, one flag per sample (1 = foot at rest), e.g. pyshoe's zv_vicon_opt
    /// column (zero velocity from the motion capture); empty if the file has none. Shown beside
    /// the detector's stance; gait events are in swings instead.
    std::vector<std::uint8_t> stance;
    bool hasTrialBoundaries = false;
    SampleRange trialBoundaries;  ///< the part of the recording the gait events cover
    std::vector<std::string> notes;  ///< where each piece came from ("known length 72 m from the file name")
};

/// A recording as the pipeline consumes it: samples plus what is known about them.
struct Recording {
    std::string source;  ///< file name or a description, for messages and reports
    std::vector<ImuSample> samples;
    Reference reference;
    std::vector<std::string> warnings;  ///< import warnings, shown to the user

    bool hasMag() const { return !samples.empty() && samples.front().hasMag(); }
    bool hasPressure() const { return !samples.empty() && samples.front().hasPressure(); }
    double duration_s() const
    {
        return samples.size() < 2 ? 0.0 : samples.back().time_s - samples.front().time_s;
    }
};

}  // namespace footpath
