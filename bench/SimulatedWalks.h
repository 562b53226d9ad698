#pragma once

// Walks the benchmarks share, simulated once per process.
#include "Recording.h"
#include "sim/WalkSimulator.h"

#include <algorithm>
#include <vector>

namespace footpath {

/// Laps of a 40 x 25 m rectangle until the walk lasts 30 minutes (180,000 samples at 100 Hz), with
/// MTi-class sensor errors.
inline const Recording& thirtyMinuteWalk()
{
    static const Recording recording = [] {
        std::vector<Eigen::Vector3d> path{Eigen::Vector3d::Zero()};
        const std::vector<Eigen::Vector3d> lap = closedRectanglePath(40.0, 25.0);
        for (int i = 0; i < 20; ++i)  // about 93 s per lap
            path.insert(path.end(), lap.begin() + 1, lap.end());
        SimulatedWalk walk = simulateWalk(path, mtiClassSensor());
        walk.recording.samples.resize(std::min<std::size_t>(walk.recording.samples.size(), 30 * 60 * 100));
        return walk.recording;
    }();
    return recording;
}

}  // namespace footpath
