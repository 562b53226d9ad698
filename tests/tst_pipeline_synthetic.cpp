// The whole pipeline on simulated walks with known truth.
#include "metrics/Evaluation.h"
#include "nav/Pipeline.h"
#include "nav/Plausibility.h"
#include "sim/WalkSimulator.h"

#include <QtTest>

#include <algorithm>

using namespace footpath;

namespace {

/// The default detector with the 15-state filter: the simulated sensor has a constant gyro bias,
/// which only the bias states can take out (the default 9-state filter leaves it in the heading).
Parameters withBiasStates()
{
    Parameters params;
    params.filter_states = static_cast<int>(FilterStates::Fifteen);
    params.use_zaru = true;
    return params;
}

Result run(const Recording& recording, const Parameters& params = Parameters())
{
    PipelineOutput output = runPipeline(recording, params);
    if (!output.error.empty())
        qFatal("%s", output.error.c_str());
    return std::move(output.result);
}

/// A low-cost MEMS IMU: four times the MTi-class bias and twice its noise.
WalkSimulatorConfig lowCostSensor(std::uint32_t seed)
{
    WalkSimulatorConfig config = mtiClassSensor(100.0, seed);
    config.accNoiseStd_mps2 *= 2.0;
    config.gyrNoiseStd_radps *= 2.0;
    config.accBias_mps2 *= 4.0;
    config.gyrBias_radps *= 2.5;
    return config;
}

double rectangleClosurePct(const WalkSimulatorConfig& config)
{
    const SimulatedWalk walk = simulateWalk(closedRectanglePath(30.0, 20.0), config);
    const Result result = run(walk.recording);
    return computeLoopClosure(result.position_m, result.summary.pathLength_m, 100.0).dbsePct;
}


std::size_t countStancePhases(const std::vector<std::uint8_t>& stance)
{
    std::size_t phases = 0;
    for (std::size_t k = 0; k < stance.size(); ++k)
        phases += stance[k] && (k == 0 || !stance[k - 1]);
    return phases;
}

/// A result of 100 Hz samples at rest at the given x positions, stance where flagged.
Result restingResult(const std::vector<double>& x_m, const std::vector<std::uint8_t>& stance)
{
    Result result;
    for (std::size_t k = 0; k < x_m.size(); ++k) {
        result.time_s.push_back(0.01 * static_cast<double>(k));
        result.position_m.emplace_back(x_m[k], 0.0, 0.0);
    }
    result.flags.stance = stance;
    return result;
}

/// Samples whose angular rate about x is the given one (the rest zero): what fillStepsAndSummary
/// reads of the recording.
std::vector<ImuSample> samplesTurningAt(const std::vector<double>& rate_radps)
{
    std::vector<ImuSample> samples(rate_radps.size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
        samples[k].time_s = 0.01 * static_cast<double>(k);
        samples[k].gyr_radps.x() = rate_radps[k];
    }
    return samples;
}

bool sameGaitEvents(const Result& a, const Result& b)
{
    const auto sameEvent = [](const GaitEvent& x, const GaitEvent& y) {
        return x.kind == y.kind && x.sample == y.sample && x.time_s == y.time_s;
    };
    return std::equal(a.gaitEvents.begin(), a.gaitEvents.end(), b.gaitEvents.begin(), b.gaitEvents.end(), sameEvent);
}

}  // namespace

class TestPipelineSynthetic : public QObject {
    Q_OBJECT
private slots:
    void stanceFlickerIsOneStanceNotAStride()
    {
        // Stance 0-0.29 s, a 0.05 s flicker out of it, stance again where the foot was, a real
        // 0.5 s swing of 0.8 m, stance: two stance phases and one stride, not three and two.
        std::vector<double> x(150, 0.0);
        std::vector<std::uint8_t> stance(150, 1);
        std::vector<double> rate(150, 0.0);
        for (std::size_t k = 30; k < 35; ++k)
            stance[k] = 0;
        for (std::size_t k = 60; k < 110; ++k) {
            stance[k] = 0;
            x[k] = 0.8 * static_cast<double>(k - 60) / 50.0;
            rate[k] = 6.0;  // a walking swing's angular rate
        }
        for (std::size_t k = 110; k < 150; ++k)
            x[k] = 0.8;
        Result result = restingResult(x, stance);
        fillStepsAndSummary(result, samplesTurningAt(rate));
        QCOMPARE(result.steps.size(), std::size_t(2));
        QCOMPARE(result.steps[0].stanceStart_s, 0.0);
        QCOMPARE(result.steps[0].stanceEnd_s, 0.59);
        QVERIFY(std::abs(result.steps[1].strideLength_m - 0.8) < 1e-12);
        QVERIFY(std::abs(result.summary.pathLength_m - 0.8) < 1e-12);
        QCOMPARE(result.mergedMovements.size(), std::size_t(1));  // the merge is said
        QCOMPARE(result.mergedMovements[0].start_s, 0.29);
        QCOMPARE(result.mergedMovements[0].end_s, 0.35);

        // A gap as short that moved the foot 0.3 m with a swing's rate is a step (a shuffle is
        // still a step).
        for (std::size_t k = 35; k < 150; ++k)
            x[k] += 0.3;
        for (std::size_t k = 30; k < 35; ++k)
            rate[k] = 3.0;
        Result moved = restingResult(x, stance);
        fillStepsAndSummary(moved, samplesTurningAt(rate));
        QCOMPARE(moved.steps.size(), std::size_t(3));
        QVERIFY(moved.mergedMovements.empty());
    }

    void weightShiftWhileStandingIsNoStride()
    {
        // Standing 4 s, the weight shifted for 0.5 s (the foot tilts at 0.8 rad/s and creeps
        // 7 mm), standing again, then a stride: one stride, not a 7 mm "stride" lasting 4 s
        // (the start of the shared IPOL walk 1-1_lf had one).
        std::vector<double> x(700, 0.0);
        std::vector<std::uint8_t> stance(700, 1);
        std::vector<double> rate(700, 0.0);
        for (std::size_t k = 400; k < 450; ++k) {
            stance[k] = 0;
            x[k] = 0.007 * static_cast<double>(k - 400) / 50.0;
            rate[k] = 0.8;
        }
        for (std::size_t k = 450; k < 700; ++k)
            x[k] = 0.007;
        for (std::size_t k = 550; k < 610; ++k) {
            stance[k] = 0;
            x[k] = 0.007 + 1.3 * static_cast<double>(k - 550) / 60.0;
            rate[k] = 8.0;
        }
        for (std::size_t k = 610; k < 700; ++k)
            x[k] = 1.307;
        Result result = restingResult(x, stance);
        fillStepsAndSummary(result, samplesTurningAt(rate));
        QCOMPARE(result.summary.steps, std::size_t(1));
        QCOMPARE(result.steps[0].stanceStart_s, 0.0);
        QCOMPARE(result.steps[0].stanceEnd_s, 5.49);
        QVERIFY(std::abs(result.steps[1].strideDuration_s - 6.1) < 1e-9);  // from the standing's start
        QCOMPARE(result.mergedMovements.size(), std::size_t(1));
        QVERIFY(std::abs(result.mergedMovements[0].displacement_m - 0.007 * 0.5) < 0.004);
        QCOMPARE(result.mergedMovements[0].peakRate_radps, 0.8);

        // The same creep of the foot at a swing's rate but no farther: still no stride.
        for (std::size_t k = 400; k < 450; ++k)
            rate[k] = 5.0;
        Result tapped = restingResult(x, stance);
        fillStepsAndSummary(tapped, samplesTurningAt(rate));
        QCOMPARE(tapped.summary.steps, std::size_t(1));
        // A real displacement without a swing's rate (the filter drifting while the foot shifts
        // slowly) is no stride either.
        for (std::size_t k = 450; k < 700; ++k)
            x[k] += 0.4;
        for (std::size_t k = 400; k < 450; ++k)
            rate[k] = 0.6;
        Result drifted = restingResult(x, stance);
        fillStepsAndSummary(drifted, samplesTurningAt(rate));
        QCOMPARE(drifted.summary.steps, std::size_t(1));
        QVERIFY(drifted.mergedMovements[0].displacement_m > kMinStrideDistance_m);
    }

    void aStrideWarningNamesTheStepTheTableShows()
    {
        // "Stride 2 is 11.66 m long" flagged the table's step 3: the warning counted strides from
        // 1 while the step table, the steps CSV and the report number steps (stances) from 1.
        const SimulatedWalk walk = simulateWalk(straightLinePath(20.0), WalkSimulatorConfig());
        Result result = run(walk.recording);
        QVERIFY(result.steps.size() > 5);
        const std::size_t index = 3;  // the table's step 4
        result.steps[index].strideLength_m = 11.66;
        const std::vector<PlausibilityWarning> warnings = checkPlausibility(result, Parameters());
        const auto found = std::find_if(warnings.begin(), warnings.end(), [](const PlausibilityWarning& w) {
            return w.kind == PlausibilityWarning::Kind::StrideLength;
        });
        QVERIFY(found != warnings.end());
        QVERIFY2(found->message.rfind("The stride to step 4 is 11.66 m long", 0) == 0, found->message.c_str());
        QCOMPARE(found->start_s, result.steps[index - 1].stanceEnd_s);
        QCOMPARE(found->end_s, result.steps[index].stanceStart_s);
    }

    void closedRectangleOfHundredMetresClosesWithinHalfPercent()
    {
        // Noise makes one walk a sample of a distribution: the bound applies to the mean of eight
        // seeds, and every seed is printed.
        double sum = 0.0;
        const int seeds = 8;
        for (std::uint32_t seed = 1; seed <= seeds; ++seed) {
            const SimulatedWalk walk = simulateWalk(closedRectanglePath(30.0, 20.0), mtiClassSensor(100.0, seed));
            QVERIFY(std::abs(walk.truePathLength_m - 100.0) < 1e-9);
            const Result result = run(walk.recording, withBiasStates());
            const LoopClosure closure = computeLoopClosure(result.position_m, result.summary.pathLength_m, 100.0);
            const ArmseResult armse = computeArmse(result.position_m, walk.truePosition_m);
            qInfo("simulated 100 m rectangle, MTi-class errors, seed %u: DBSE %.3f m = %.3f %%, path %.2f m, "
                  "ARMSE2D %.3f m, %zu steps",
                  seed, closure.dbse_m, closure.dbsePct, result.summary.pathLength_m, armse.armse2d_m,
                  result.summary.steps);
            QVERIFY(std::abs(result.summary.pathLength_m - 100.0) < 1.0);
            sum += closure.dbsePct;
        }
        const double mean = sum / seeds;
        qInfo("mean DBSE over %d seeds: %.3f %% (bound 0.5 %%)", seeds, mean);
        QVERIFY2(mean <= 0.5, qPrintable(QString("mean DBSE %1 %").arg(mean)));
    }

    void noiselessRectangleClosesWithinThreeTenthsOfAPercent()
    {
        // What the mechanization alone leaves at 100 Hz, so a regression there shows by itself.
        WalkSimulatorConfig perfect;
        const double pct = rectangleClosurePct(perfect);
        qInfo("noiseless 100 m rectangle at 100 Hz: DBSE %.3f %%", pct);
        QVERIFY(pct <= 0.3);
    }

    void lowCostSensorTablePrinted()
    {
        // Known weakness, printed for the next issues: a lateral accelerometer bias looks like roll
        // at rest, and while the foot pitches a yaw-axis gyro bias turns about the same axis, so
        // the filter learns a wrong yaw bias and the heading drifts.
        for (std::uint32_t seed = 1; seed <= 4; ++seed) {
            const double pct = rectangleClosurePct(lowCostSensor(seed));
            QVERIFY(std::isfinite(pct));
            qInfo("simulated 100 m rectangle, low-cost MEMS errors, seed %u: DBSE %.3f %%", seed, pct);
        }
    }

    void detectorFindsEveryStanceOfTheSimulatedWalk()
    {
        const SimulatedWalk walk = simulateWalk(straightLinePath(20.0), mtiClassSensor());
        const Result result = run(walk.recording);
        QCOMPARE(result.summary.stancePhases, countStancePhases(walk.trueStance));
        QCOMPARE(result.summary.steps, countStancePhases(walk.trueStance) - 1);
    }

    void everyGaitFindsEveryStance_data()
    {
        // One default detector for every gait: the stance statistic of a running foot is far
        // higher than a walking one's, and the threshold must follow it. Each case has its own
        // danger: running's 0.1 s stances (10 samples at 100 Hz), a long standstill before the
        // first step (the threshold sinks to the sensor noise), turning on the spot (90-degree
        // turns every stride), stairs.
        QTest::addColumn<double>("rate_hz");
        QTest::addColumn<double>("stance_s");
        QTest::addColumn<double>("swing_s");
        QTest::addColumn<double>("stride_m");
        QTest::addColumn<double>("still_s");
        QTest::addColumn<int>("path");  // 0 line, 1 turning on the spot (0.7 m square), 2 stairs
        QTest::newRow("walking 100 Hz") << 100.0 << 0.45 << 0.65 << 1.4 << 2.0 << 0;
        QTest::newRow("walking 200 Hz") << 200.0 << 0.45 << 0.65 << 1.4 << 2.0 << 0;
        QTest::newRow("fast walking 100 Hz") << 100.0 << 0.25 << 0.5 << 1.8 << 2.0 << 0;
        QTest::newRow("running 100 Hz") << 100.0 << 0.12 << 0.5 << 2.6 << 2.0 << 0;
        QTest::newRow("running 200 Hz") << 200.0 << 0.12 << 0.5 << 2.6 << 2.0 << 0;
        QTest::newRow("30 s standing, then walking") << 100.0 << 0.45 << 0.65 << 1.4 << 30.0 << 0;
        QTest::newRow("turning on the spot") << 100.0 << 0.45 << 0.65 << 0.7 << 2.0 << 1;
        QTest::newRow("stairs") << 100.0 << 0.45 << 0.65 << 0.6 << 2.0 << 2;
    }

    void everyGaitFindsEveryStance()
    {
        QFETCH(double, rate_hz);
        QFETCH(double, stance_s);
        QFETCH(double, swing_s);
        QFETCH(double, stride_m);
        QFETCH(double, still_s);
        QFETCH(int, path);
        WalkSimulatorConfig config = mtiClassSensor(rate_hz);
        config.gyrBias_radps.setZero();  // the default 9-state filter holds the biases at zero
        config.stanceDuration_s = stance_s;
        config.swingDuration_s = swing_s;
        config.strideLength_m = stride_m;
        config.initialStill_s = still_s;
        const std::vector<Eigen::Vector3d> waypoints = path == 0   ? straightLinePath(20.0)
                                                       : path == 1 ? closedRectanglePath(0.7, 0.7)
                                                                   : stairsPath(8, 0.17, 0.6);
        const SimulatedWalk walk = simulateWalk(waypoints, config);
        const Result result = run(walk.recording);
        const Eigen::Vector3d end = result.position_m.back() - walk.truePosition_m.back();
        qInfo("%zu stance phases (true %zu), end error %.3f m, %zu warnings", result.summary.stancePhases,
              countStancePhases(walk.trueStance), end.norm(), result.warnings.size());
        QCOMPARE(result.summary.stancePhases, countStancePhases(walk.trueStance));
        QVERIFY2(end.norm() < 0.02 * std::max(walk.truePathLength_m, 5.0), qPrintable(QString::number(end.norm())));
        for (const PlausibilityWarning& warning : result.warnings)
            qWarning("%s", warning.message.c_str());
        QVERIFY(result.warnings.empty());
    }

    void standingStillIsOneStance()
    {
        WalkSimulatorConfig config = mtiClassSensor(100.0);
        config.initialStill_s = 60.0;
        const SimulatedWalk walk = simulateWalk(straightLinePath(1.4), config);
        const Result result = run(walk.recording);
        std::size_t stillSamples = 0, stillAtRest = 0;
        for (std::size_t k = 0; k < walk.recording.samples.size() && walk.recording.samples[k].time_s < 59.0; ++k) {
            ++stillSamples;
            stillAtRest += result.flags.stance[k];
        }
        QCOMPARE(stillAtRest, stillSamples);  // the noise floor never leaves the "always at rest" bound
        QVERIFY(result.position_m[stillSamples - 1].norm() < 0.01);
    }

    void straightLineLengthWithinOnePercent()
    {
        const SimulatedWalk walk = simulateWalk(straightLinePath(50.0), mtiClassSensor());
        const Result result = run(walk.recording);
        const DistanceError error = computeDistanceError(result.summary.pathLength_m, 50.0);
        qInfo("simulated 50 m line: path %.3f m, error %.3f %%", result.summary.pathLength_m, error.errorPct);
        QVERIFY(error.errorPct < 1.0);
    }

    void stairsClimbTheirHeight()
    {
        const SimulatedWalk walk = simulateWalk(stairsPath(10, 0.34, 0.6), mtiClassSensor());
        const Result result = run(walk.recording);
        const double climbed = result.steps.back().position_m.z() - result.steps.front().position_m.z();
        qInfo("simulated stairs: climbed %.3f m of %.3f m", climbed, walk.truePosition_m.back().z());
        QVERIFY(std::abs(climbed - walk.truePosition_m.back().z()) < 0.05 * walk.truePosition_m.back().z());
    }

    void rateDoesNotChangeTheEstimate()
    {
        // Windows and noise are given per second, so 200 Hz must give the same walk as 100 Hz.
        const Result at100 = run(simulateWalk(closedRectanglePath(10.0, 5.0), mtiClassSensor(100.0)).recording);
        const Result at200 = run(simulateWalk(closedRectanglePath(10.0, 5.0), mtiClassSensor(200.0)).recording);
        QCOMPARE(at200.summary.steps, at100.summary.steps);
        QVERIFY(std::abs(at200.summary.pathLength_m - at100.summary.pathLength_m) < 0.1);
    }

    void everySampleHasEveryOutput()
    {
        const SimulatedWalk walk = simulateWalk(straightLinePath(5.0), mtiClassSensor());
        const Result result = run(walk.recording);
        const std::size_t n = walk.recording.samples.size();
        QCOMPARE(result.summary.samples, n);
        for (std::size_t size : {result.time_s.size(), result.position_m.size(), result.velocity_mps.size(),
                                 result.rollPitchYaw_rad.size(), result.gyroBias_radps.size(),
                                 result.accBias_mps2.size(), result.flags.c1.size(), result.flags.c2.size(),
                                 result.flags.c3.size(), result.flags.c.size(), result.flags.stance.size()})
            QCOMPARE(size, n);
        QCOMPARE(result.position_m.front().norm(), 0.0);
    }

    void gyroBiasIsEstimated()
    {
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(30.0, 20.0), mtiClassSensor());
        const Result result = run(walk.recording, withBiasStates());
        const Eigen::Vector3d error = result.gyroBias_radps.back() - mtiClassSensor().gyrBias_radps;
        QVERIFY2(error.norm() < 1e-3, qPrintable(QString::number(error.norm())));
    }

    void cancelStopsTheRun()
    {
        const SimulatedWalk walk = simulateWalk(straightLinePath(200.0), mtiClassSensor());  // > 8192 samples
        int calls = 0;
        PipelineOutput output = runPipeline(walk.recording, Parameters(), [&](double) { return ++calls < 2; });
        QVERIFY(output.result.cancelled);
        QVERIFY(output.result.time_s.size() < walk.recording.samples.size());
        QCOMPARE(calls, 2);
    }

    void theDetectorsThreadChangesNoDigit()
    {
        // runPipeline decides the stance flags on a second thread while the filter follows them
        // (Threads::Two); decided first (Threads::One) they must give the same bits, for every
        // detector and estimator, and for a walk that starts mid-swing (the alignment waits for
        // its first stance).
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), mtiClassSensor(100.0, 7));
        Recording midSwing = walk.recording;
        midSwing.samples.erase(midSwing.samples.begin(), midSwing.samples.begin() + 260);  // 2 s still, a stance, 0.15 s
        std::vector<std::pair<const char*, Parameters>> settings{{"defaults", Parameters()},
                                                                  {"15 states, ZARU", withBiasStates()}};
        for (const DetectorKind detector : {DetectorKind::PaperC1C2C3, DetectorKind::Mbgtd}) {
            Parameters params;
            params.detector = static_cast<int>(detector);
            settings.emplace_back(detector == DetectorKind::Mbgtd ? "MBGTD" : "paper detector", params);
        }
        for (const EstimatorKind estimator : {EstimatorKind::Ekf, EstimatorKind::Feliz}) {
            Parameters params;
            params.estimator = static_cast<int>(estimator);
            settings.emplace_back(estimator == EstimatorKind::Ekf ? "filter alone" : "Feliz", params);
        }
        for (const Recording* recording : {&walk.recording, static_cast<const Recording*>(&midSwing)}) {
            for (const auto& [setting, params] : settings) {
                const Result two = runPipeline(*recording, params, {}, RtsSmoother::Threads::Two).result;
                const Result one = runPipeline(*recording, params, {}, RtsSmoother::Threads::One).result;
                QVERIFY2(!two.steps.empty(), setting);
                QVERIFY2(recording == &walk.recording || !two.flags.stance.front(), setting);
                QVERIFY2(two.flags.stance == one.flags.stance && two.flags.logStatistic == one.flags.logStatistic,
                         setting);
                QVERIFY2(two.position_m == one.position_m && two.velocity_mps == one.velocity_mps, setting);
                QVERIFY2(two.rollPitchYaw_rad == one.rollPitchYaw_rad && two.errorStd == one.errorStd, setting);
                QVERIFY2(two.steps.size() == one.steps.size() && two.warnings.size() == one.warnings.size(), setting);
                QCOMPARE(two.summary.pathLength_m, one.summary.pathLength_m);
                // The gait rates, computed on the detector's thread, are what the gait detection
                // computes itself from the samples.
                Result recomputed = two;
                detectGaitEvents(*recording, recomputed);
                QVERIFY2(!two.gaitEvents.empty(), setting);
                for (const Result* other : {&one, static_cast<const Result*>(&recomputed)}) {
                    QVERIFY2(sameGaitEvents(two, *other), setting);
                    QVERIFY2(two.gaitStance == other->gaitStance, setting);
                    QCOMPARE(two.gait.strideLength_m, other->gait.strideLength_m);
                }
            }
        }
    }

    void skippingTheSmoothedVariancesChangesNoState()
    {
        // The command line, the self-tuning and the comparisons ask for no standard deviations: the
        // smoother then runs its states' pass alone. Every state, step and warning is the same bit
        // for bit, on one thread and on two; only errorStd is left empty. The filter alone keeps its
        // own standard deviations.
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), mtiClassSensor(100.0, 5));
        Parameters filterAlone;
        filterAlone.estimator = static_cast<int>(EstimatorKind::Ekf);
        const std::vector<std::pair<const char*, Parameters>> settings{
            {"defaults", Parameters()}, {"15 states, ZARU", withBiasStates()}, {"filter alone", filterAlone}};
        for (const auto& [setting, params] : settings) {
            const Result full = runPipeline(walk.recording, params).result;
            QVERIFY2(full.errorStd.size() == full.position_m.size(), setting);
            for (const RtsSmoother::Threads threads : {RtsSmoother::Threads::One, RtsSmoother::Threads::Two}) {
                const Result statesOnly =
                    runPipeline(walk.recording, params, {}, threads, {}, RtsSmoother::Variances::Skip).result;
                QVERIFY2(!statesOnly.steps.empty() && statesOnly.steps.size() == full.steps.size(), setting);
                QVERIFY2(statesOnly.position_m == full.position_m && statesOnly.velocity_mps == full.velocity_mps,
                         setting);
                QVERIFY2(statesOnly.rollPitchYaw_rad == full.rollPitchYaw_rad
                             && statesOnly.gyroBias_radps == full.gyroBias_radps
                             && statesOnly.accBias_mps2 == full.accBias_mps2,
                         setting);
                QVERIFY2(statesOnly.forwardSpeed_mps == full.forwardSpeed_mps, setting);
                QVERIFY2(statesOnly.warnings.size() == full.warnings.size(), setting);
                QCOMPARE(statesOnly.summary.pathLength_m, full.summary.pathLength_m);
                if (params.estimatorKind() == EstimatorKind::Smoother)
                    QVERIFY2(statesOnly.errorStd.empty(), setting);
                else
                    QVERIFY2(statesOnly.errorStd == full.errorStd, setting);
            }
        }
    }

    void aUsedResultsMemoryChangesNoDigit()
    {
        // A run into the memory of an older result (a slider's re-runs in the window) gives the
        // same bits as a run into new memory, and fills that memory instead of asking for more.
        const SimulatedWalk walk = simulateWalk(straightLinePath(12.0), mtiClassSensor(100.0, 3));
        const SimulatedWalk otherWalk = simulateWalk(straightLinePath(14.0), mtiClassSensor(100.0, 7));
        Parameters paper, filterAlone, feliz;
        paper.detector = static_cast<int>(DetectorKind::PaperC1C2C3);
        filterAlone.estimator = static_cast<int>(EstimatorKind::Ekf);
        feliz.estimator = static_cast<int>(EstimatorKind::Feliz);
        for (const Parameters& params : {Parameters(), withBiasStates(), paper, filterAlone, feliz}) {
            const Result fresh = run(walk.recording, params);
            Result used = run(otherWalk.recording, withBiasStates());  // other numbers, a little longer
            const double* const usedTimes = used.time_s.data();
            const auto* const usedStd = used.errorStd.data();
            const auto* const usedStance = used.flags.stance.data();
            const Result reused =
                runPipeline(walk.recording, params, {}, RtsSmoother::Threads::Two, std::move(used)).result;
            QCOMPARE(reused.time_s.data(), usedTimes);
            QCOMPARE(reused.errorStd.data(), usedStd);
            if (params.detectorKind() != DetectorKind::PaperC1C2C3)  // the paper's flags are made anew
                QCOMPARE(reused.flags.stance.data(), usedStance);
            QVERIFY(reused.time_s == fresh.time_s && reused.position_m == fresh.position_m);
            QVERIFY(reused.velocity_mps == fresh.velocity_mps && reused.rollPitchYaw_rad == fresh.rollPitchYaw_rad);
            QVERIFY(reused.gyroBias_radps == fresh.gyroBias_radps && reused.accBias_mps2 == fresh.accBias_mps2);
            QVERIFY(reused.errorStd == fresh.errorStd && reused.forwardSpeed_mps == fresh.forwardSpeed_mps);
            QVERIFY(reused.flags.stance == fresh.flags.stance && reused.flags.c == fresh.flags.c);
            QVERIFY(reused.flags.c1 == fresh.flags.c1 && reused.flags.c2 == fresh.flags.c2
                    && reused.flags.c3 == fresh.flags.c3);
            QVERIFY(reused.flags.logStatistic == fresh.flags.logStatistic
                    && reused.flags.logThreshold == fresh.flags.logThreshold);
            QVERIFY(reused.gaitStance == fresh.gaitStance && sameGaitEvents(reused, fresh));
            QCOMPARE(reused.steps.size(), fresh.steps.size());
            QCOMPARE(reused.warnings.size(), fresh.warnings.size());
            QCOMPARE(reused.methodNotes.size(), fresh.methodNotes.size());
            QCOMPARE(reused.summary.pathLength_m, fresh.summary.pathLength_m);
            QCOMPARE(reused.gait.strides, fresh.gait.strides);
        }
        // A used result over twice the size is let go, not held on to.
        const SimulatedWalk longWalk = simulateWalk(closedRectanglePath(20.0, 10.0), mtiClassSensor(100.0, 7));
        Result large = run(longWalk.recording);
        QVERIFY(large.time_s.size() > 2 * walk.recording.samples.size());
        const double* const largeTimes = large.time_s.data();
        const Result small = runPipeline(walk.recording, Parameters(), {}, RtsSmoother::Threads::Two, std::move(large)).result;
        QVERIFY(small.time_s.data() != largeTimes);
        QVERIFY(small.time_s.capacity() < 2 * walk.recording.samples.size());
    }

    void progressReachesOne()
    {
        const SimulatedWalk walk = simulateWalk(straightLinePath(5.0), mtiClassSensor());
        double last = -1.0;
        const PipelineOutput output = runPipeline(walk.recording, Parameters(), [&](double f) {
            last = f;
            return true;
        });
        QVERIFY(!output.result.cancelled);
        QCOMPARE(last, 1.0);
    }

    void invalidInputIsAnErrorNotACrash()
    {
        Parameters bad;
        bad.acc_min_mps2 = 12.0;
        const SimulatedWalk walk = simulateWalk(straightLinePath(2.0), mtiClassSensor());
        QVERIFY(QString::fromStdString(runPipeline(walk.recording, bad).error).contains("acc_min_mps2"));
        QVERIFY(QString::fromStdString(runPipeline(Recording(), Parameters()).error).contains("at least 2"));
    }
};

QTEST_APPLESS_MAIN(TestPipelineSynthetic)
#include "tst_pipeline_synthetic.moc"
