#include "sim/WalkSimulator.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

namespace footpath {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

/// Below this a length counts as zero: a repeated waypoint or a purely vertical segment.
constexpr double kNegligibleLength_m = 1e-9;
/// The walk closes its loop when the last waypoint is this close to the first.
constexpr double kLoopClosureTolerance_m = 1e-3;
/// Sample times and phase boundaries are sums of decimals: this keeps a sample that falls on a
/// boundary from flipping phase through rounding.
constexpr double kTimeTolerance_s = 1e-9;

/// Earth field in the navigation frame (gauss): 0.2 horizontal towards +x (magnetic north, no
/// declination) and 0.45 downwards, a mid-latitude northern-hemisphere field.
const Vector3d kEarthField_n(0.2, 0.0, -0.45);

/// A polynomial in normalised swing time tau in [0, 1], lowest power first.
using Polynomial = std::array<double, 9>;

/// Progress 35 tau^4 - 84 tau^5 + 70 tau^6 - 20 tau^7 (minimum snap): 0 -> 1 with zero velocity,
/// acceleration and jerk at both ends. Zero acceleration keeps the accelerometer free of steps
/// where swing meets stance; zero jerk as well makes the walk integrate accurately at ordinary
/// sample rates, because a strapdown's second-order error term is the jump of the integrand's
/// derivative at the phase boundaries.
constexpr Polynomial kProgress = {0.0, 0.0, 0.0, 0.0, 35.0, -84.0, 70.0, -20.0, 0.0};

/// Lift bump 256 tau^4 (1 - tau)^4: peaks at 1 for tau = 0.5 and is as flat at both ends as the
/// progress, for the same reasons.
constexpr Polynomial kLiftBump = {0.0, 0.0, 0.0, 0.0, 256.0, -1024.0, 1536.0, -1024.0, 256.0};

/// Pitch wave k tau^3 (1 - tau)^3 (1 - 2 tau), expanded: positive (toe down) after push-off,
/// negative (toe up) before heel strike, zero rate and zero angular acceleration at both ends.
/// Its extremes are at tau (1 - tau) = 3/14 with |value| = (3/14)^3 / sqrt 7, hence k normalises
/// the peak to 1.
const double kPitchWaveScale = std::pow(14.0 / 3.0, 3) * std::sqrt(7.0);
const Polynomial kPitchWave = {0.0,
                               0.0,
                               0.0,
                               kPitchWaveScale,
                               -5.0 * kPitchWaveScale,
                               9.0 * kPitchWaveScale,
                               -7.0 * kPitchWaveScale,
                               2.0 * kPitchWaveScale,
                               0.0};

/// A profile and its first two derivatives with respect to tau.
struct Profile {
    double value = 0.0;
    double rate = 0.0;
    double accel = 0.0;
};

Profile evaluate(const Polynomial& coefficients, double tau)
{
    Profile profile;
    // Horner's scheme for the value and both derivatives, highest power first.
    for (std::size_t i = coefficients.size(); i-- > 0;) {
        profile.accel = profile.accel * tau + 2.0 * profile.rate;
        profile.rate = profile.rate * tau + profile.value;
        profile.value = profile.value * tau + coefficients[i];
    }
    return profile;
}

/// One swing from a footfall to the next, or an elevator ride; the foot rests before and after it
/// (and, in a ride, during it).
struct Swing {
    double start_s = 0.0;
    double duration_s = 0.0;
    bool elevatorRide = false;
    Vector3d from_m = Vector3d::Zero();
    Vector3d to_m = Vector3d::Zero();
    double fromYaw_rad = 0.0;
    double toYaw_rad = 0.0;
};

/// What the IMU needs of the foot at one instant, in the navigation frame. Roll is always 0.
struct FootState {
    Vector3d position_m = Vector3d::Zero();
    Vector3d acceleration_mps2 = Vector3d::Zero();
    double yaw_rad = 0.0;
    double yawRate_radps = 0.0;
    double pitch_rad = 0.0;
    double pitchRate_radps = 0.0;
    bool inSwing = false;
};

double wrapToPi(double angle_rad)
{
    return std::atan2(std::sin(angle_rad), std::cos(angle_rad));
}

double horizontalLength(const Vector3d& delta)
{
    return delta.head<2>().norm();
}

/// The foot starts facing along the first segment that moves horizontally.
double initialYaw(const std::vector<Vector3d>& waypoints)
{
    for (std::size_t i = 1; i < waypoints.size(); ++i) {
        const Vector3d delta = waypoints[i] - waypoints[i - 1];
        if (horizontalLength(delta) > kNegligibleLength_m)
            return std::atan2(delta.y(), delta.x());
    }
    return 0.0;
}

int stridesForSegment(double horizontalLength_m, double strideLength_m)
{
    if (strideLength_m <= 0.0)
        return 1;
    return std::max(1, static_cast<int>(std::lround(horizontalLength_m / strideLength_m)));
}

/// Peak of the progress profile's rate: 35/16 (at tau = 1/2).
constexpr double kProgressPeakRate = 35.0 / 16.0;

bool isElevatorSegment(std::size_t waypoint, const WalkSimulatorConfig& config)
{
    return std::find(config.elevatorWaypoints.begin(), config.elevatorWaypoints.end(), waypoint)
        != config.elevatorWaypoints.end();
}

/// The movements in time order and when the last one, with the stance after it, is over.
struct WalkPlan {
    std::vector<Swing> swings;
    double end_s = 0.0;
};

/// The ride waits, moves over the segment with the progress profile at the configured peak speed,
/// and waits again; the foot keeps its heading.
Swing planRide(const Vector3d& from_m, const Vector3d& to_m, double yaw_rad, double& start_s,
               const WalkSimulatorConfig& config)
{
    Swing ride;
    ride.elevatorRide = true;
    ride.start_s = start_s + config.elevatorWait_s;
    ride.duration_s = kProgressPeakRate * std::abs(to_m.z() - from_m.z()) / config.elevatorSpeed_mps;
    ride.from_m = from_m;
    ride.to_m = to_m;
    ride.fromYaw_rad = ride.toYaw_rad = yaw_rad;
    start_s = ride.start_s + ride.duration_s + config.elevatorWait_s;
    return ride;
}

/// Splits every segment into equal strides and gives each its swing's start time and headings.
/// The foot turns to a new segment's direction during that segment's first swing.
WalkPlan planSwings(const std::vector<Vector3d>& waypoints, const WalkSimulatorConfig& config)
{
    std::vector<Swing> swings;
    double yaw_rad = initialYaw(waypoints);
    double start_s = config.initialStill_s;
    for (std::size_t i = 1; i < waypoints.size(); ++i) {
        const Vector3d delta = waypoints[i] - waypoints[i - 1];
        if (delta.norm() < kNegligibleLength_m)
            continue;
        if (isElevatorSegment(i, config)) {
            swings.push_back(planRide(waypoints[i - 1], waypoints[i], yaw_rad, start_s, config));
            continue;
        }
        const double horizontal_m = horizontalLength(delta);
        // Shortest turn from the current heading; a vertical segment keeps the heading.
        const double segmentYaw_rad = horizontal_m > kNegligibleLength_m
            ? yaw_rad + wrapToPi(std::atan2(delta.y(), delta.x()) - yaw_rad)
            : yaw_rad;
        const int strides = stridesForSegment(horizontal_m, config.strideLength_m);
        for (int s = 0; s < strides; ++s) {
            Swing swing;
            swing.start_s = start_s;
            swing.duration_s = config.swingDuration_s;
            swing.from_m = waypoints[i - 1] + delta * (static_cast<double>(s) / strides);
            swing.to_m = waypoints[i - 1] + delta * (static_cast<double>(s + 1) / strides);
            swing.fromYaw_rad = yaw_rad;
            swing.toYaw_rad = segmentYaw_rad;
            swings.push_back(swing);
            yaw_rad = segmentYaw_rad;
            start_s += config.swingDuration_s + config.stanceDuration_s;
        }
    }
    return {swings, start_s};
}

FootState restingAt(const Vector3d& position_m, double yaw_rad)
{
    FootState state;
    state.position_m = position_m;
    state.yaw_rad = yaw_rad;
    return state;
}

/// The foot resting on the elevator's floor: only the height moves.
FootState rideState(const Swing& ride, double tau)
{
    const Profile progress = evaluate(kProgress, tau);
    const Vector3d delta_m = ride.to_m - ride.from_m;
    FootState state = restingAt(ride.from_m + progress.value * delta_m, ride.fromYaw_rad);
    state.acceleration_mps2 = progress.accel * delta_m / (ride.duration_s * ride.duration_s);
    return state;
}

/// The analytic swing: time derivatives are tau derivatives scaled by 1/T and 1/T^2.
FootState swingState(const Swing& swing, double tau, const WalkSimulatorConfig& config)
{
    const double duration_s = swing.duration_s;
    const Profile progress = evaluate(kProgress, tau);
    const Profile lift = evaluate(kLiftBump, tau);
    const Profile pitch = evaluate(kPitchWave, tau);
    const Vector3d delta_m = swing.to_m - swing.from_m;  // includes the climb, so stairs rise smoothly
    const Vector3d up = Vector3d::UnitZ() * config.footLift_m;
    const double turn_rad = swing.toYaw_rad - swing.fromYaw_rad;

    FootState state;
    state.position_m = swing.from_m + progress.value * delta_m + lift.value * up;
    state.acceleration_mps2 = (progress.accel * delta_m + lift.accel * up) / (duration_s * duration_s);
    state.yaw_rad = swing.fromYaw_rad + progress.value * turn_rad;
    state.yawRate_radps = progress.rate * turn_rad / duration_s;
    state.pitch_rad = config.swingPitch_rad * pitch.value;
    state.pitchRate_radps = config.swingPitch_rad * pitch.rate / duration_s;
    return state;
}

/// The foot's state at time t: in a swing, or at rest where the last swing ended.
FootState footStateAt(double time_s, const std::vector<Swing>& swings, const Vector3d& start_m,
                      double startYaw_rad, const WalkSimulatorConfig& config)
{
    const auto next = std::upper_bound(swings.begin(), swings.end(), time_s,
                                       [](double t, const Swing& s) { return t < s.start_s; });
    if (next == swings.begin())
        return restingAt(start_m, startYaw_rad);
    const Swing& latest = *(next - 1);
    const double sinceStart_s = time_s - latest.start_s;
    if (sinceStart_s >= latest.duration_s - kTimeTolerance_s)
        return restingAt(latest.to_m, latest.toYaw_rad);
    if (latest.elevatorRide)
        return rideState(latest, sinceStart_s / latest.duration_s);
    FootState state = swingState(latest, sinceStart_s / latest.duration_s, config);
    state.inSwing = sinceStart_s > kTimeTolerance_s;
    return state;
}

/// C = Rz(yaw) * Ry(pitch) * Rx(roll) with roll = 0.
Matrix3d bodyToNav(const FootState& state)
{
    return (Eigen::AngleAxisd(state.yaw_rad, Vector3d::UnitZ())
            * Eigen::AngleAxisd(state.pitch_rad, Vector3d::UnitY()))
        .toRotationMatrix();
}

/// Body rate with dC/dt = C skew(w) for C = Rz(yaw) Ry(pitch): the yaw rate about nav z seen in
/// the pitched body, plus the pitch rate about body y.
Vector3d bodyRate(const FootState& state)
{
    return {-state.yawRate_radps * std::sin(state.pitch_rad), state.pitchRate_radps,
            state.yawRate_radps * std::cos(state.pitch_rad)};
}

double barometricPressure_pa(double height_m)
{
    return 101325.0 * std::pow(1.0 - 2.25577e-5 * height_m, 5.25588);
}

/// The noiseless reading of a perfect IMU on the foot.
ImuSample idealSample(double time_s, const FootState& state, const WalkSimulatorConfig& config)
{
    const Matrix3d bodyToNavigation = bodyToNav(state);
    const Vector3d gravityReaction_mps2 = Vector3d::UnitZ() * config.gravity_mps2;
    ImuSample sample;
    sample.time_s = time_s;
    sample.acc_mps2 = bodyToNavigation.transpose() * (state.acceleration_mps2 + gravityReaction_mps2);
    sample.gyr_radps = bodyRate(state);
    if (config.withMagnetometer)
        sample.mag = bodyToNavigation.transpose() * kEarthField_n;
    if (config.withPressure)
        sample.pressure_pa = barometricPressure_pa(state.position_m.z());
    return sample;
}

/// The reading at time_s: instantaneous, or with the rate averaged over (time_s - 1/rate, time_s]
/// by three-point Gauss-Legendre quadrature (exact to fifth order for the smooth profiles).
ImuSample sensorReading(double time_s, const std::vector<Swing>& swings, const Vector3d& start_m, double startYaw_rad,
                        const WalkSimulatorConfig& config)
{
    ImuSample reading = idealSample(time_s, footStateAt(time_s, swings, start_m, startYaw_rad, config), config);
    if (!config.gyroIntervalAveraged)
        return reading;
    const double half_s = 0.5 / config.rate_hz;
    const double nodes[] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
    const double weights[] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    reading.gyr_radps.setZero();
    for (int i = 0; i < 3; ++i) {
        const double t = time_s - half_s + nodes[i] * half_s;
        const ImuSample point = idealSample(t, footStateAt(t, swings, start_m, startYaw_rad, config), config);
        reading.gyr_radps += weights[i] * point.gyr_radps;
    }
    return reading;
}

/// Adds the constant biases and white noise; draws nothing for a zero standard deviation because
/// std::normal_distribution requires a positive one. The barometer draws from its own generator,
/// so switching its noise on leaves the inertial samples as they were.
class SensorErrors {
public:
    explicit SensorErrors(const WalkSimulatorConfig& config)
        : config_(config), random_(config.seed), pressureRandom_(config.seed ^ 0x5bd1e995u)
    {
    }

    void apply(ImuSample& sample)
    {
        sample.acc_mps2 += config_.accBias_mps2 + whiteNoise(config_.accNoiseStd_mps2);
        sample.gyr_radps += config_.gyrBias_radps + whiteNoise(config_.gyrNoiseStd_radps);
        if (sample.hasPressure())
            sample.pressure_pa = pressureReading(sample.pressure_pa);
    }

private:
    Vector3d whiteNoise(double stddev)
    {
        if (stddev <= 0.0)
            return Vector3d::Zero();
        std::normal_distribution<double> normal(0.0, stddev);
        const double x = normal(random_);  // named draws: argument order would be unspecified
        const double y = normal(random_);
        const double z = normal(random_);
        return {x, y, z};
    }

    double pressureReading(double pressure_pa)
    {
        if (config_.pressureNoiseStd_pa > 0.0)
            pressure_pa += std::normal_distribution<double>(0.0, config_.pressureNoiseStd_pa)(pressureRandom_);
        if (config_.pressureQuantum_pa > 0.0)
            pressure_pa = std::round(pressure_pa / config_.pressureQuantum_pa) * config_.pressureQuantum_pa;
        return pressure_pa;
    }

    const WalkSimulatorConfig& config_;
    std::mt19937 random_;
    std::mt19937 pressureRandom_;
};

/// Empty when the configuration can produce a walk, else what is wrong with it.
std::string configProblem(const WalkSimulatorConfig& config)
{
    if (!(config.rate_hz > 0.0))
        return "sample rate must be positive";
    if (!(config.swingDuration_s > 0.0))
        return "swing duration must be positive";
    if (!(config.stanceDuration_s >= 0.0 && config.initialStill_s >= 0.0 && config.finalStill_s >= 0.0))
        return "stance and still durations must not be negative";
    if (!(config.accNoiseStd_mps2 >= 0.0 && config.gyrNoiseStd_radps >= 0.0 && config.pressureNoiseStd_pa >= 0.0
          && config.pressureQuantum_pa >= 0.0))
        return "noise standard deviations and the pressure quantum must not be negative";
    if (!config.elevatorWaypoints.empty() && !(config.elevatorSpeed_mps > 0.0 && config.elevatorWait_s >= 0.0))
        return "elevator speed must be positive and its wait not negative";
    return {};
}

/// Empty when every elevator segment exists and is vertical.
std::string elevatorProblem(const std::vector<Vector3d>& waypoints, const WalkSimulatorConfig& config)
{
    for (const std::size_t i : config.elevatorWaypoints) {
        if (i == 0 || i >= waypoints.size())
            return "elevator waypoint " + std::to_string(i) + " does not end a segment";
        if (horizontalLength(waypoints[i] - waypoints[i - 1]) > kNegligibleLength_m)
            return "elevator segment to waypoint " + std::to_string(i) + " is not vertical";
    }
    return {};
}

double horizontalPathLength(const std::vector<Vector3d>& waypoints)
{
    double length_m = 0.0;
    for (std::size_t i = 1; i < waypoints.size(); ++i)
        length_m += horizontalLength(waypoints[i] - waypoints[i - 1]);
    return length_m;
}

std::string describe(const std::vector<Vector3d>& waypoints, std::size_t strides, double length_m)
{
    return "simulated walk: " + std::to_string(waypoints.size()) + " waypoints, "
        + std::to_string(strides) + " strides, " + std::to_string(length_m) + " m";
}

}  // namespace

SimulatedWalk simulateWalk(const std::vector<Eigen::Vector3d>& waypoints, const WalkSimulatorConfig& config)
{
    SimulatedWalk walk;
    walk.truePathLength_m = horizontalPathLength(waypoints);
    const WalkPlan plan = planSwings(waypoints, config);
    const std::vector<Swing>& swings = plan.swings;
    walk.recording.source = describe(waypoints, swings.size(), walk.truePathLength_m);
    std::string problem = configProblem(config);
    if (problem.empty())
        problem = elevatorProblem(waypoints, config);
    if (!problem.empty()) {
        walk.recording.warnings.push_back("walk simulator: " + problem);
        return walk;
    }

    const double duration_s = plan.end_s + config.finalStill_s;
    // Samples at k / rate up to and including the end (tolerance for a product such as 10.7 * 100).
    const auto sampleCount = static_cast<std::size_t>(std::floor(duration_s * config.rate_hz + 1e-9)) + 1;
    const Vector3d start_m = waypoints.empty() ? Vector3d::Zero() : waypoints.front();
    const double startYaw_rad = initialYaw(waypoints);

    SensorErrors errors(config);
    walk.recording.samples.reserve(sampleCount);
    walk.truePosition_m.reserve(sampleCount);
    walk.trueStance.reserve(sampleCount);
    for (std::size_t k = 0; k < sampleCount; ++k) {
        const double time_s = static_cast<double>(k) / config.rate_hz;
        const FootState state = footStateAt(time_s, swings, start_m, startYaw_rad, config);
        ImuSample sample = sensorReading(time_s, swings, start_m, startYaw_rad, config);
        errors.apply(sample);
        walk.recording.samples.push_back(sample);
        walk.truePosition_m.push_back(state.position_m);
        walk.trueStance.push_back(state.inSwing ? 0 : 1);
    }

    walk.recording.reference.positions_m = walk.truePosition_m;
    walk.recording.reference.closedLoop = waypoints.size() >= 2
        && (waypoints.back() - waypoints.front()).norm() <= kLoopClosureTolerance_m;
    walk.recording.reference.knownLength_m = walk.truePathLength_m;
    return walk;
}

std::vector<Eigen::Vector3d> straightLinePath(double length_m)
{
    return {Vector3d::Zero(), Vector3d(length_m, 0.0, 0.0)};
}

std::vector<Eigen::Vector3d> closedRectanglePath(double sideX_m, double sideY_m)
{
    return {Vector3d::Zero(), Vector3d(sideX_m, 0.0, 0.0), Vector3d(sideX_m, sideY_m, 0.0),
            Vector3d(0.0, sideY_m, 0.0), Vector3d::Zero()};
}

std::vector<Eigen::Vector3d> elevatorPath(double walkBefore_m, double rise_m, double walkAfter_m)
{
    return {Vector3d::Zero(), Vector3d(walkBefore_m, 0.0, 0.0), Vector3d(walkBefore_m, 0.0, rise_m),
            Vector3d(walkBefore_m + walkAfter_m, 0.0, rise_m)};
}

WalkSimulatorConfig mtiClassSensor(double rate_hz, std::uint32_t seed)
{
    WalkSimulatorConfig config;
    config.rate_hz = rate_hz;
    config.accNoiseStd_mps2 = 0.01;
    config.gyrNoiseStd_radps = 0.0015;
    config.accBias_mps2 = Eigen::Vector3d(0.0075, -0.005, 0.01);
    config.gyrBias_radps = Eigen::Vector3d(0.0016, -0.0012, 0.002);
    config.seed = seed;
    return config;
}

WalkSimulatorConfig ecgXmuBarometer(WalkSimulatorConfig config)
{
    config.withPressure = true;
    config.pressureNoiseStd_pa = 2.0;
    config.pressureQuantum_pa = 0.01;
    return config;
}

std::vector<Eigen::Vector3d> stairsPath(int strides, double rise_m, double run_m)
{
    // One waypoint per stair so that each segment is one stride (for runs up to 1.5 stride lengths).
    std::vector<Vector3d> path{Vector3d::Zero()};
    for (int i = 1; i <= strides; ++i)
        path.emplace_back(i * run_m, 0.0, i * rise_m);
    return path;
}

}  // namespace footpath
