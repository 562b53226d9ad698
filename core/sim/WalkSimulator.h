#pragma once

#include "Recording.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace footpath {

/// How the simulated foot moves and how the simulated sensor errs.
struct WalkSimulatorConfig {
    double rate_hz = 100.0;
    double gravity_mps2 = 9.81;
    double strideLength_m = 1.4;   ///< target; each segment is split into equal strides near this
    double stanceDuration_s = 0.45;
    double swingDuration_s = 0.65;
    double initialStill_s = 2.0;   ///< foot at rest before the first stride (alignment period)
    double finalStill_s = 1.0;
    double footLift_m = 0.12;      ///< peak height of the foot above the straight line during swing
    double swingPitch_rad = 0.6;   ///< peak foot pitch during swing
    double accNoiseStd_mps2 = 0.0; ///< white noise per sample
    double gyrNoiseStd_radps = 0.0;
    Eigen::Vector3d accBias_mps2 = Eigen::Vector3d::Zero();  ///< constant, body frame
    Eigen::Vector3d gyrBias_radps = Eigen::Vector3d::Zero();
    /// The gyro reading is the mean rate over the preceding sample period (a rate-integrating
    /// output, like Xsens' delta-q or a decimating MEMS gyro) while the accelerometer is sampled
    /// at the instant. The paper's mechanization is consistent with this model (see
    /// strapdownStep), and the real recordings measure best with it. false: both instantaneous.
    bool gyroIntervalAveraged = true;
    bool withMagnetometer = false;  ///< adds a constant Earth field rotated into the body frame
    bool withPressure = false;      ///< adds pressure from height by the standard barometric formula
    /// Barometer errors. The ecg-xmu barometer at rest: about 2 Pa white noise (1.5-2.5 Pa, 0.1-0.2 m)
    /// in steps of 0.01 Pa (see ecgXmuBarometer()). 0: exact readings.
    double pressureNoiseStd_pa = 0.0;
    double pressureQuantum_pa = 0.0;
    /// Segments ridden in an elevator: index i makes waypoints[i - 1] -> waypoints[i], which must be
    /// vertical, a ride during which the foot rests (true stance) while the height changes. The car
    /// waits elevatorWait_s before and after moving, and moves with a smooth speed profile
    /// (zero acceleration and jerk at both ends) that peaks at elevatorSpeed_mps.
    std::vector<std::size_t> elevatorWaypoints;
    double elevatorSpeed_mps = 1.0;
    double elevatorWait_s = 3.0;
    std::uint32_t seed = 1;         ///< fixed seed: runs are repeatable
};

/// The ecg-xmu barometer's noise and resolution, measured on the files at rest (pressure_pa of
/// Height.txt, data.txt, shanglou041601.TXT, mage_*_1.txt: 1.5-2.5 Pa standard deviation, values in
/// 0.01 Pa), added to config with pressure switched on.
WalkSimulatorConfig ecgXmuBarometer(WalkSimulatorConfig config);

/// An Xsens MTi-class IMU, the device the product targets: white noise of its data-sheet density
/// over a 50 Hz bandwidth (about 120 ug/sqrt(Hz) and 0.01 deg/s/sqrt(Hz)) and constant biases of
/// about 1 mg and 0.1 deg/s left after factory calibration.
WalkSimulatorConfig mtiClassSensor(double rate_hz = 100.0, std::uint32_t seed = 1);

/// A simulated walk: the recording a sensor would produce plus the truth behind it.
struct SimulatedWalk {
    Recording recording;
    std::vector<Eigen::Vector3d> truePosition_m;  ///< per sample, navigation frame, z up, start at 0
    std::vector<std::uint8_t> trueStance;         ///< per sample, 1 while the foot is at rest
    double truePathLength_m = 0.0;                ///< horizontal length of the walked path
};

/// Turns a polyline of foot positions (metres, z up; waypoints[0] is the start) into foot-mounted
/// IMU signals with stance and swing phases. The foot starts level with yaw 0, so the first
/// segment should point along +x for the truth to share the estimate's frame.
SimulatedWalk simulateWalk(const std::vector<Eigen::Vector3d>& waypoints, const WalkSimulatorConfig& config);

/// Path helpers: all start at the origin heading along +x.
std::vector<Eigen::Vector3d> straightLinePath(double length_m);
std::vector<Eigen::Vector3d> closedRectanglePath(double sideX_m, double sideY_m);  ///< counter-clockwise
std::vector<Eigen::Vector3d> stairsPath(int strides, double rise_m, double run_m);  ///< climbs rise_m per stride
/// Walks walkBefore_m along +x into an elevator, rides rise_m (negative: down) and walks walkAfter_m
/// further along +x. The ride is the segment that ends at kElevatorPathRideWaypoint: put that index
/// in WalkSimulatorConfig::elevatorWaypoints.
std::vector<Eigen::Vector3d> elevatorPath(double walkBefore_m, double rise_m, double walkAfter_m);
constexpr std::size_t kElevatorPathRideWaypoint = 2;

}  // namespace footpath
