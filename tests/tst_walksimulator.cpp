#include "sim/WalkSimulator.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace footpath;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

/// Swing phases (runs of zeros) in the true stance flags.
int countSwings(const std::vector<std::uint8_t>& stance)
{
    int swings = 0;
    for (std::size_t k = 1; k < stance.size(); ++k)
        swings += (stance[k - 1] == 1 && stance[k] == 0) ? 1 : 0;
    return swings;
}

/// Exact rotation for a rotation vector (Rodrigues), identity for a zero vector.
Matrix3d rotationFromVector(const Vector3d& rotation_rad)
{
    const double angle_rad = rotation_rad.norm();
    if (angle_rad == 0.0)
        return Matrix3d::Identity();
    return Eigen::AngleAxisd(angle_rad, rotation_rad / angle_rad).toRotationMatrix();
}

/// Integral of the rate over [t_k, t_k+1] by the cubic through the rates at k-1 .. k+2 (fourth
/// order); the trapezoid at the ends of the recording, where the foot is at rest anyway.
Vector3d integratedRate(const std::vector<ImuSample>& samples, std::size_t k, double dt_s)
{
    const Vector3d& w0 = samples[k].gyr_radps;
    const Vector3d& w1 = samples[k + 1].gyr_radps;
    if (k == 0 || k + 2 >= samples.size())
        return 0.5 * (w0 + w1) * dt_s;
    return (13.0 * (w0 + w1) - samples[k - 1].gyr_radps - samples[k + 2].gyr_radps) * (dt_s / 24.0);
}

/// Strapdown independent of the library. Attitude: the exact rotation of a fourth-order rotation
/// vector (rate integral plus the coning term (w0 x w1) dt^2 / 12, which matters at corners where
/// yaw and pitch turn together). The trapezoid rate of the brief leaves an attitude error of
/// dt^2 / 12 times the angular acceleration (up to 2e-3 rad at 100 Hz) during every swing, which
/// tilts gravity into a velocity error of several mm/s per stride; with this scheme the residual
/// falls as dt^4. Velocity and position: trapezoid, already accurate because the simulated
/// acceleration starts and ends every swing with zero jerk.
std::vector<Vector3d> integrateStrapdown(const std::vector<ImuSample>& samples, const Vector3d& start_m,
                                         double gravity_mps2)
{
    const Vector3d gravityVector_mps2(0.0, 0.0, -gravity_mps2);
    Matrix3d bodyToNav = Matrix3d::Identity();  // level, yaw 0: the helpers start along +x
    Vector3d velocity_mps = Vector3d::Zero();
    Vector3d position_m = start_m;
    std::vector<Vector3d> positions{position_m};
    for (std::size_t k = 0; k + 1 < samples.size(); ++k) {
        const ImuSample& before = samples[k];
        const ImuSample& after = samples[k + 1];
        const double dt_s = after.time_s - before.time_s;
        const Vector3d accBefore_mps2 = bodyToNav * before.acc_mps2 + gravityVector_mps2;
        const Vector3d rotation_rad = integratedRate(samples, k, dt_s)
            + before.gyr_radps.cross(after.gyr_radps) * (dt_s * dt_s / 12.0);
        bodyToNav = bodyToNav * rotationFromVector(rotation_rad);
        const Vector3d accAfter_mps2 = bodyToNav * after.acc_mps2 + gravityVector_mps2;
        const Vector3d newVelocity_mps = velocity_mps + 0.5 * (accBefore_mps2 + accAfter_mps2) * dt_s;
        position_m += 0.5 * (velocity_mps + newVelocity_mps) * dt_s;
        velocity_mps = newVelocity_mps;
        positions.push_back(position_m);
    }
    return positions;
}

double maxDistance(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b)
{
    double worst_m = 0.0;
    for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
        worst_m = std::max(worst_m, (a[k] - b[k]).norm());
    return worst_m;
}

/// Worst strapdown error of the noiseless point samples against the truth (the test's integrator
/// is for instantaneous readings).
double strapdownError(const std::vector<Vector3d>& path, double rate_hz)
{
    WalkSimulatorConfig config;
    config.rate_hz = rate_hz;
    config.gyroIntervalAveraged = false;
    const SimulatedWalk walk = simulateWalk(path, config);
    const auto integrated = integrateStrapdown(walk.recording.samples, path.front(), config.gravity_mps2);
    return maxDistance(integrated, walk.truePosition_m);
}

}  // namespace

class TestWalkSimulator : public QObject {
    Q_OBJECT

private slots:
    void samplesFollowTheTimeline();
    void restSamplesReadGravityAndNoRate();
    void rectangleIsClosedAndThirtyMetresLong();
    void strapdownReproducesTheTruePath_data();
    void strapdownReproducesTheTruePath();
    void strapdownErrorIsIntegratorTruncation();
    void footPitchesToeDownThenToeUp();
    void biasShiftsEveryReadingByTheBias();
    void noiseIsRepeatableForOneSeed();
    void stairsClimbRisePerStride();
    void magnetometerSeesTheFieldInTheBodyFrame();
    void invalidConfigIsReportedNotSimulated();
};

void TestWalkSimulator::samplesFollowTheTimeline()
{
    WalkSimulatorConfig config;  // 100 Hz, 2 s still, 0.65 s swing, 0.45 s stance, 1 s still
    const SimulatedWalk walk = simulateWalk(straightLinePath(10.0), config);

    // 10 m / 1.4 m rounds to 7 strides: 2 + 7 * 1.1 + 1 = 10.7 s, samples at 0, 0.01, ..., 10.7.
    const auto& samples = walk.recording.samples;
    QCOMPARE(samples.size(), std::size_t(1071));
    QCOMPARE(walk.truePosition_m.size(), samples.size());
    QCOMPARE(walk.trueStance.size(), samples.size());
    QCOMPARE(walk.recording.reference.positions_m.size(), samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k)
        QVERIFY(std::abs(samples[k].time_s - static_cast<double>(k) * 0.01) < 1e-12);

    QCOMPARE(countSwings(walk.trueStance), 7);
    // A 0.65 s swing has 64 samples strictly inside it; its ends are at rest.
    QCOMPARE(std::count(walk.trueStance.begin(), walk.trueStance.end(), 0), std::ptrdiff_t(7 * 64));
    // The first swing starts when the 2 s still period ends.
    QCOMPARE(walk.trueStance[200], std::uint8_t(1));
    QCOMPARE(walk.trueStance[201], std::uint8_t(0));
    QVERIFY((walk.truePosition_m.back() - Vector3d(10.0, 0.0, 0.0)).norm() < 1e-12);
    QVERIFY(walk.recording.source.rfind("simulated", 0) == 0);
}

void TestWalkSimulator::restSamplesReadGravityAndNoRate()
{
    WalkSimulatorConfig config;
    const SimulatedWalk walk = simulateWalk(closedRectanglePath(4.0, 3.0), config);
    const Vector3d levelReading_mps2(0.0, 0.0, config.gravity_mps2);
    int restSamples = 0;
    for (std::size_t k = 0; k < walk.trueStance.size(); ++k) {
        // The gyro reading averages the preceding interval: the foot must have rested all of it.
        if (!walk.trueStance[k] || (k > 0 && !walk.trueStance[k - 1]))
            continue;
        ++restSamples;
        const ImuSample& sample = walk.recording.samples[k];
        // Exactly level at rest whatever the heading, so every axis is pinned, not just |f|.
        QVERIFY2((sample.acc_mps2 - levelReading_mps2).norm() < 1e-12, qPrintable(QString::number(k)));
        QVERIFY2(sample.gyr_radps.norm() < 1e-12, qPrintable(QString::number(k)));
    }
    QVERIFY(restSamples > 300);  // initial still alone is 201 samples
    QVERIFY(!walk.recording.hasMag());
    QVERIFY(!walk.recording.hasPressure());
}

void TestWalkSimulator::rectangleIsClosedAndThirtyMetresLong()
{
    const SimulatedWalk rectangle = simulateWalk(closedRectanglePath(10.0, 5.0), WalkSimulatorConfig());
    QVERIFY(std::abs(rectangle.truePathLength_m - 30.0) < 1e-12);
    QVERIFY(std::abs(rectangle.recording.reference.knownLength_m - 30.0) < 1e-12);
    QVERIFY(rectangle.recording.reference.closedLoop);
    QVERIFY(rectangle.truePosition_m.back().norm() < 1e-12);
    // Counter-clockwise: the second corner is at (10, 5).
    const auto& truth = rectangle.truePosition_m;
    QVERIFY(std::any_of(truth.begin(), truth.end(),
                        [](const Vector3d& p) { return (p - Vector3d(10.0, 5.0, 0.0)).norm() < 1e-12; }));

    const SimulatedWalk line = simulateWalk(straightLinePath(10.0), WalkSimulatorConfig());
    QVERIFY(!line.recording.reference.closedLoop);
}

void TestWalkSimulator::strapdownReproducesTheTruePath_data()
{
    QTest::addColumn<std::vector<Vector3d>>("path");
    QTest::addColumn<double>("rate_hz");
    QTest::addColumn<double>("bound_m");
    // Measured worst errors: 3.2 mm at 100 Hz over 7 strides (the swing's pitch is fast for 100 Hz
    // and the integrator's own error dominates); at 400 Hz 0.034 mm, 0.17 mm and 0.022 mm, i.e.
    // under 0.01 mm per stride. Bounds are about twice to three times those. What they catch
    // (measured by breaking the simulator on purpose): the yaw-pitch coupling of the body rate
    // left out, 360 m; the pitch rate 0.1 % too large, 15 cm; the lift acceleration 1 % too
    // large, 1.2 mm.
    QTest::newRow("straight 10 m, 7 strides, 100 Hz") << straightLinePath(10.0) << 100.0 << 5e-3;
    QTest::newRow("straight 10 m, 7 strides, 400 Hz") << straightLinePath(10.0) << 400.0 << 0.1e-3;
    QTest::newRow("rectangle 10 x 5 m, 22 strides, 400 Hz") << closedRectanglePath(10.0, 5.0) << 400.0 << 0.5e-3;
    QTest::newRow("stairs 8 x 0.17 m, 400 Hz") << stairsPath(8, 0.17, 0.6) << 400.0 << 0.1e-3;
}

void TestWalkSimulator::strapdownReproducesTheTruePath()
{
    QFETCH(std::vector<Vector3d>, path);
    QFETCH(double, rate_hz);
    QFETCH(double, bound_m);
    const double error_m = strapdownError(path, rate_hz);
    qInfo("worst strapdown error: %.3g mm", error_m * 1e3);
    QVERIFY2(error_m < bound_m, qPrintable(QString("error %1 m").arg(error_m)));
}

void TestWalkSimulator::strapdownErrorIsIntegratorTruncation()
{
    // Signals that disagree with the truth leave an error floor that does not shrink with dt; the
    // test's fourth-order integrator cuts its own error 16 times from 200 to 400 Hz.
    const auto path = closedRectanglePath(10.0, 5.0);
    const double coarse_m = strapdownError(path, 200.0);
    const double fine_m = strapdownError(path, 400.0);
    qInfo("rectangle: %.3g mm at 200 Hz, %.3g mm at 400 Hz", coarse_m * 1e3, fine_m * 1e3);
    QVERIFY(fine_m < coarse_m / 10.0);
}

void TestWalkSimulator::footPitchesToeDownThenToeUp()
{
    WalkSimulatorConfig config;
    config.rate_hz = 1000.0;  // fine enough that the sampled extremes are the true ones
    const SimulatedWalk walk = simulateWalk(straightLinePath(1.4), config);
    // On a straight line only the pitch turns, so its angle is the integral of the y rate.
    double pitch_rad = 0.0;
    double highest_rad = 0.0;
    double lowest_rad = 0.0;
    std::size_t highestAt = 0;
    std::size_t lowestAt = 0;
    const auto& samples = walk.recording.samples;
    for (std::size_t k = 1; k < samples.size(); ++k) {
        const double dt_s = samples[k].time_s - samples[k - 1].time_s;
        pitch_rad += 0.5 * (samples[k - 1].gyr_radps.y() + samples[k].gyr_radps.y()) * dt_s;
        if (pitch_rad > highest_rad) { highest_rad = pitch_rad; highestAt = k; }
        if (pitch_rad < lowest_rad) { lowest_rad = pitch_rad; lowestAt = k; }
    }
    QVERIFY(std::abs(highest_rad - config.swingPitch_rad) < 1e-3);  // toe down (positive pitch)
    QVERIFY(std::abs(lowest_rad + config.swingPitch_rad) < 1e-3);   // toe up
    QVERIFY(highestAt < lowestAt);                                  // push-off before heel strike
    QVERIFY(std::abs(pitch_rad) < 1e-9);                            // level again at rest
}

void TestWalkSimulator::biasShiftsEveryReadingByTheBias()
{
    const auto path = closedRectanglePath(3.0, 2.0);
    WalkSimulatorConfig config;
    const SimulatedWalk clean = simulateWalk(path, config);
    config.accBias_mps2 = Vector3d(0.1, -0.2, 0.3);
    config.gyrBias_radps = Vector3d(0.01, 0.02, -0.03);
    const SimulatedWalk biased = simulateWalk(path, config);

    Vector3d accShift_mps2 = Vector3d::Zero();
    Vector3d gyrShift_radps = Vector3d::Zero();
    int restSamples = 0;
    for (std::size_t k = 0; k < clean.trueStance.size(); ++k) {
        if (!clean.trueStance[k])
            continue;
        accShift_mps2 += biased.recording.samples[k].acc_mps2 - clean.recording.samples[k].acc_mps2;
        gyrShift_radps += biased.recording.samples[k].gyr_radps - clean.recording.samples[k].gyr_radps;
        ++restSamples;
    }
    QVERIFY(restSamples > 0);
    QVERIFY((accShift_mps2 / restSamples - config.accBias_mps2).norm() < 1e-12);
    QVERIFY((gyrShift_radps / restSamples - config.gyrBias_radps).norm() < 1e-12);
    // The bias is constant in the body frame, so it shifts swing samples equally.
    const std::size_t midSwing = 201 + 32;
    QVERIFY(!clean.trueStance[midSwing]);
    QVERIFY((biased.recording.samples[midSwing].acc_mps2 - clean.recording.samples[midSwing].acc_mps2
             - config.accBias_mps2).norm() < 1e-12);
}

void TestWalkSimulator::noiseIsRepeatableForOneSeed()
{
    const auto path = straightLinePath(5.0);
    WalkSimulatorConfig config;
    const SimulatedWalk clean = simulateWalk(path, config);
    config.accNoiseStd_mps2 = 0.05;
    config.gyrNoiseStd_radps = 0.005;
    config.seed = 7;
    const SimulatedWalk first = simulateWalk(path, config);
    const SimulatedWalk again = simulateWalk(path, config);
    config.seed = 8;
    const SimulatedWalk other = simulateWalk(path, config);

    bool otherDiffers = false;
    double accSquares = 0.0;
    double gyrSquares = 0.0;
    const std::size_t n = first.recording.samples.size();
    for (std::size_t k = 0; k < n; ++k) {
        const ImuSample& a = first.recording.samples[k];
        const ImuSample& b = again.recording.samples[k];
        QVERIFY(a.acc_mps2 == b.acc_mps2 && a.gyr_radps == b.gyr_radps);
        otherDiffers = otherDiffers || a.acc_mps2 != other.recording.samples[k].acc_mps2;
        accSquares += (a.acc_mps2 - clean.recording.samples[k].acc_mps2).squaredNorm();
        gyrSquares += (a.gyr_radps - clean.recording.samples[k].gyr_radps).squaredNorm();
    }
    QVERIFY(otherDiffers);
    // 3 n draws estimate each standard deviation to about 1 / sqrt(6 n) = 1.5 %: 6 % is 4 sigma.
    const double draws = 3.0 * static_cast<double>(n);
    QVERIFY(std::abs(std::sqrt(accSquares / draws) / 0.05 - 1.0) < 0.06);
    QVERIFY(std::abs(std::sqrt(gyrSquares / draws) / 0.005 - 1.0) < 0.06);
}

void TestWalkSimulator::stairsClimbRisePerStride()
{
    WalkSimulatorConfig config;
    config.withPressure = true;
    const SimulatedWalk walk = simulateWalk(stairsPath(8, 0.17, 0.6), config);
    QCOMPARE(countSwings(walk.trueStance), 8);
    QVERIFY(std::abs(walk.truePosition_m.back().z() - 8 * 0.17) < 1e-12);
    QVERIFY(std::abs(walk.truePathLength_m - 8 * 0.6) < 1e-12);
    // The foot clears each stair edge: mid-swing it is footLift above the linear climb.
    const std::size_t midFirstSwing = 232;  // tau = 0.49: lift 0.9993 of its peak
    QVERIFY(walk.truePosition_m[midFirstSwing].z() > 0.5 * 0.17 + 0.95 * config.footLift_m);
    // Near sea level pressure falls by 101325 * 5.25588 * 2.25577e-5 = 12.013 Pa per metre.
    const double drop_pa = walk.recording.samples.front().pressure_pa - walk.recording.samples.back().pressure_pa;
    QVERIFY(std::abs(drop_pa - 1.36 * 12.013) < 0.01);
}

void TestWalkSimulator::magnetometerSeesTheFieldInTheBodyFrame()
{
    WalkSimulatorConfig config;
    config.withMagnetometer = true;
    const SimulatedWalk walk = simulateWalk(closedRectanglePath(2.8, 2.8), config);
    QVERIFY(walk.recording.hasMag());
    const auto& samples = walk.recording.samples;
    // Facing +x (north) at the start the body reads the navigation field as it is.
    QVERIFY((samples.front().mag - Vector3d(0.2, 0.0, -0.45)).norm() < 1e-12);
    // Two strides per side: the third swing turns onto the second side and ends at
    // 2 + 2 * 1.1 + 0.65 = 4.85 s; at 5 s the foot rests facing +y, where north is along body -y.
    const std::size_t onSecondSide = 500;
    QVERIFY(walk.trueStance[onSecondSide]);
    QVERIFY((samples[onSecondSide].mag - Vector3d(0.0, -0.2, -0.45)).norm() < 1e-12);
    const double fieldStrength = Vector3d(0.2, 0.0, -0.45).norm();
    for (const ImuSample& sample : samples)
        QVERIFY(std::abs(sample.mag.norm() - fieldStrength) < 1e-12);
}

void TestWalkSimulator::invalidConfigIsReportedNotSimulated()
{
    WalkSimulatorConfig config;
    config.rate_hz = 0.0;
    const SimulatedWalk walk = simulateWalk(straightLinePath(3.0), config);
    QVERIFY(walk.recording.samples.empty());
    QCOMPARE(walk.recording.warnings.size(), std::size_t(1));
}

QTEST_APPLESS_MAIN(TestWalkSimulator)
#include "tst_walksimulator.moc"
