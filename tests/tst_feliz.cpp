// Feliz et al. 2009, estimator=feliz: per-swing velocity de-drift without a Kalman filter,
// on simulated walks with known truth and on the pyshoe-vicon recordings.
#include "TestData.h"
#include "io/Import.h"
#include "metrics/Evaluation.h"
#include "nav/Attitude.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include <QDir>
#include <QtTest>

#include <cmath>

using namespace footpath;

namespace {

Parameters felizParameters()
{
    Parameters params;
    params.estimator = static_cast<int>(EstimatorKind::Feliz);
    return params;
}

Result runFeliz(const Recording& recording)
{
    PipelineOutput output = runPipeline(recording, felizParameters());
    if (!output.error.empty())
        qFatal("%s", output.error.c_str());
    return std::move(output.result);
}

/// What the de-drift is compared with: the same attitudes, C f - g integrated and simply reset to
/// zero at each stance (no linear removal over the swing). Written here, apart from the product.
std::vector<Eigen::Vector3d> resetOnlyPath(const Recording& recording, const Result& result, double gravity_mps2)
{
    const std::vector<ImuSample>& samples = recording.samples;
    std::vector<Eigen::Vector3d> path(samples.size(), Eigen::Vector3d::Zero());
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
    for (std::size_t k = 1; k < samples.size(); ++k) {
        const double dt = samples[k].time_s - samples[k - 1].time_s;
        const Eigen::Vector3d rpy = result.rollPitchYaw_rad[k];
        const Eigen::Matrix3d bodyToNav = rotationFromRollPitchYaw(rpy.x(), rpy.y(), rpy.z());
        const Eigen::Vector3d previous = velocity;
        velocity += (bodyToNav * samples[k].acc_mps2 - Eigen::Vector3d(0.0, 0.0, gravity_mps2)) * dt;
        if (result.flags.stance[k])
            velocity.setZero();
        path[k] = path[k - 1] + 0.5 * (previous + velocity) * dt;
    }
    return path;
}

double endError3d(const std::vector<Eigen::Vector3d>& estimate, const SimulatedWalk& walk)
{
    return (estimate.back() - walk.truePosition_m.back()).norm();
}

QStringList pyshoeTrials()
{
    return QDir(datasetPath("pyshoe-vicon")).entryList({"*.csv"}, QDir::Files, QDir::Name);
}

}  // namespace

class TestFeliz : public QObject {
    Q_OBJECT
private slots:
    void straightWalkLengthWithinTwoPercent()
    {
        const SimulatedWalk walk = simulateWalk(straightLinePath(30.0), mtiClassSensor());
        const Result result = runFeliz(walk.recording);
        const double errorPct = 100.0 * (result.summary.pathLength_m / walk.truePathLength_m - 1.0);
        // The gyro's yaw bias bends the line (no filter estimates it), so the end lies to the side;
        // the distance walked and the straight distance from the start are what the de-drift gets right.
        const double reach_m = result.position_m.back().head<2>().norm();
        const double reachErrorPct = 100.0 * (reach_m / walk.truePosition_m.back().head<2>().norm() - 1.0);
        qInfo("simulated 30 m line, MTi-class errors: path %.3f m (error %.2f %%), end %.3f m from the start "
              "(error %.2f %%), end error %.3f m",
              result.summary.pathLength_m, errorPct, reach_m, reachErrorPct, endError3d(result.position_m, walk));
        QVERIFY2(std::abs(errorPct) < 2.0, qPrintable(QString::number(errorPct)));
        QVERIFY2(std::abs(reachErrorPct) < 2.0, qPrintable(QString::number(reachErrorPct)));
    }

    void everySampleFilledAndVelocityExactlyZeroAtStance()
    {
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(6.0, 4.0), mtiClassSensor());
        const Result result = runFeliz(walk.recording);
        const std::size_t n = walk.recording.samples.size();
        QCOMPARE(result.time_s.size(), n);
        QCOMPARE(result.position_m.size(), n);
        QCOMPARE(result.velocity_mps.size(), n);
        QCOMPARE(result.rollPitchYaw_rad.size(), n);
        QCOMPARE(result.gyroBias_radps.size(), n);
        QCOMPARE(result.accBias_mps2.size(), n);
        std::size_t stanceSamples = 0, movingSwingSamples = 0;
        for (std::size_t k = 0; k < n; ++k) {
            QVERIFY(result.position_m[k].allFinite());
            QVERIFY(result.gyroBias_radps[k] == Eigen::Vector3d::Zero());
            QVERIFY(result.accBias_mps2[k] == Eigen::Vector3d::Zero());
            if (result.flags.stance[k]) {
                ++stanceSamples;
                QVERIFY(result.velocity_mps[k] == Eigen::Vector3d::Zero());  // exactly, not nearly
            } else {
                movingSwingSamples += result.velocity_mps[k].norm() > 0.1;
            }
        }
        QVERIFY(stanceSamples > n / 4);
        QVERIFY(movingSwingSamples > n / 4);  // the swings do move
        QVERIFY(result.summary.steps > 5);
    }

    void noiseFreeRectangleClosesWithinATenthOfAPercent()
    {
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(30.0, 20.0), WalkSimulatorConfig());
        const Result result = runFeliz(walk.recording);
        const LoopClosure closure = computeLoopClosure(result.position_m, result.summary.pathLength_m, 100.0);
        const ArmseResult armse = computeArmse(result.position_m, walk.truePosition_m);
        qInfo("noise-free 100 m rectangle: DBSE %.4f m = %.4f %%, path %.2f m, ARMSE2D %.4f m", closure.dbse_m,
              closure.dbsePct, result.summary.pathLength_m, armse.armse2d_m);
        QVERIFY2(closure.dbsePct < 0.1, qPrintable(QString::number(closure.dbsePct)));
        QVERIFY(std::abs(result.summary.pathLength_m - 100.0) < 1.0);
    }

    void deDriftRemovesTheLinearDriftThatResettingLeaves()
    {
        // An accelerometer bias along the foot's vertical axis (no gyro error): the vertical velocity
        // of each swing drifts nearly linearly; resetting it at the stance leaves half of b T^2 of
        // height per stride, the linear removal takes it out. (A bias along a horizontal body axis
        // would be indistinguishable from a tilt at rest and tilts each stride instead: not drift.)
        WalkSimulatorConfig config;
        config.accBias_mps2 = Eigen::Vector3d(0.0, 0.0, 0.2);
        const SimulatedWalk walk = simulateWalk(straightLinePath(30.0), config);
        const Result result = runFeliz(walk.recording);
        const std::vector<Eigen::Vector3d> resetOnly = resetOnlyPath(walk.recording, result, config.gravity_mps2);
        const Eigen::Vector3d deDriftedError = result.position_m.back() - walk.truePosition_m.back();
        const Eigen::Vector3d resetOnlyError = resetOnly.back() - walk.truePosition_m.back();
        qInfo("30 m line, vertical accelerometer bias 0.2 m/s^2: end error de-drifted %.3f m (height %.3f m), "
              "reset only %.3f m (height %.3f m)",
              deDriftedError.norm(), deDriftedError.z(), resetOnlyError.norm(), resetOnlyError.z());
        QVERIFY(std::abs(resetOnlyError.z()) > 0.5);  // the bias does matter
        QVERIFY2(std::abs(deDriftedError.z()) < 0.05 * std::abs(resetOnlyError.z()),
                 qPrintable(QString::number(deDriftedError.z())));
        QVERIFY2(deDriftedError.norm() < 0.25 * resetOnlyError.norm(), qPrintable(QString::number(deDriftedError.norm())));
    }

    void relevellingKeepsALongWalkWithGyroBiasOnTrack()
    {
        // 0.3 deg/s on the roll and pitch axes tilts a gyro-only attitude by about 25 degrees in the
        // 80 s walk; re-levelled at each stance the path stays near the truth.
        WalkSimulatorConfig config;
        config.gyrBias_radps = Eigen::Vector3d(0.005, -0.005, 0.0);
        const SimulatedWalk walk = simulateWalk(straightLinePath(100.0), config);
        const Result result = runFeliz(walk.recording);
        const double end_m = endError3d(result.position_m, walk);
        qInfo("100 m line, roll/pitch gyro bias 0.3 deg/s: end error %.3f m, path %.2f m", end_m,
              result.summary.pathLength_m);
        QVERIFY2(end_m < 2.0, qPrintable(QString::number(end_m)));
        QVERIFY(std::abs(result.summary.pathLength_m - 100.0) < 2.0);
    }

    void swingThatNoStanceEndsIsNoted()
    {
        SimulatedWalk walk = simulateWalk(straightLinePath(10.0), WalkSimulatorConfig());
        std::vector<ImuSample>& samples = walk.recording.samples;
        std::size_t cut = samples.size() - 1;
        while (cut > 0 && !(walk.trueStance[cut - 1] && !walk.trueStance[cut]))
            --cut;
        samples.resize(cut + 30);  // 0.3 s into the last swing
        const Result result = runFeliz(walk.recording);
        QCOMPARE(result.position_m.size(), samples.size());
        QCOMPARE(result.methodNotes.size(), std::size_t(1));
        QCOMPARE(result.methodNotes.front().method, std::string("feliz"));
        QVERIFY(result.velocity_mps.back().norm() > 0.1);
    }

    void cancelStopsTheRun()
    {
        const SimulatedWalk walk = simulateWalk(straightLinePath(200.0), mtiClassSensor());  // > 8192 samples
        std::vector<double> fractions;
        const PipelineOutput finished = runPipeline(walk.recording, felizParameters(), [&](double fraction) {
            fractions.push_back(fraction);
            return true;
        });
        QVERIFY(!finished.result.cancelled);
        QVERIFY(fractions.size() >= 3);
        QVERIFY(std::is_sorted(fractions.begin(), fractions.end()));
        QCOMPARE(fractions.back(), 1.0);

        int calls = 0;
        const PipelineOutput cancelled = runPipeline(walk.recording, felizParameters(), [&](double) {
            ++calls;
            return false;
        });
        QVERIFY(cancelled.result.cancelled);
        QCOMPARE(calls, 1);
        QVERIFY(cancelled.result.position_m.size() < walk.recording.samples.size());
    }

    void pyshoeViconEveryTrialFinite()
    {
        FOOTPATH_REQUIRE_DATASETS();
        const QStringList trials = pyshoeTrials();
        QCOMPARE(trials.size(), 12);
        double sum = 0.0;
        for (const QString& trial : trials) {
            const ImportResult read = importRecording(datasetPath("pyshoe-vicon/" + trial).toStdString());
            QVERIFY2(read.ok(), qPrintable(trial));
            const Result result = runFeliz(read.recording);
            for (const Eigen::Vector3d& p : result.position_m)
                QVERIFY2(p.allFinite(), qPrintable(trial));
            const double armse = computeArmse(result.position_m, read.recording.reference.positions_m).armse2d_m;
            qInfo("pyshoe-vicon %s: Feliz 2D ARMSE %.4f m, path %.1f m", qPrintable(trial), armse,
                  result.summary.pathLength_m);
            sum += armse;
        }
        const double mean = sum / static_cast<double>(trials.size());
        qInfo("pyshoe-vicon mean 2D ARMSE, Feliz: %.4f m (bound %.3f m)", mean, kPyshoeMeanBound_m);
        QVERIFY2(mean < kPyshoeMeanBound_m, qPrintable(QString::number(mean)));
    }

private:
    static constexpr double kPyshoeMeanBound_m = 0.08;  // measured 0.0625 m (default EKF 0.0628 m)
};

QTEST_GUILESS_MAIN(TestFeliz)
#include "tst_feliz.moc"
