// The Rauch-Tung-Striebel smoother against the filter on simulated walks with known truth.
#include "detect/StanceDetector.h"
#include "metrics/Evaluation.h"
#include "nav/Alignment.h"
#include "nav/BulkAllocator.h"
#include "nav/Pipeline.h"
#include "nav/RtsSmoother.h"
#include "sim/WalkSimulator.h"

#include <QtTest>

#include <cstring>
#include <memory>

using namespace footpath;

namespace {

Result run(const Recording& recording, Parameters params, EstimatorKind estimator)
{
    params.estimator = static_cast<int>(estimator);
    PipelineOutput output = runPipeline(recording, params);
    if (!output.error.empty())
        qFatal("%s", output.error.c_str());
    return std::move(output.result);
}

/// Root mean square of the height error over every sample: the heading drift of the unobservable
/// gyro bias dominates the horizontal error of both, the height shows what smoothing does.
double heightRms(const Result& result, const std::vector<Eigen::Vector3d>& truth)
{
    double sum = 0.0;
    for (std::size_t k = 0; k < truth.size(); ++k)
        sum += std::pow(result.position_m[k].z() - truth[k].z(), 2);
    return std::sqrt(sum / static_cast<double>(truth.size()));
}

/// The largest error of one sample's displacement: the filter's path jumps where a ZUPT corrects
/// the velocity error a swing accumulated; the smoother spreads that correction over the swing.
double largestStepError(const Result& result, const std::vector<Eigen::Vector3d>& truth)
{
    double largest = 0.0;
    for (std::size_t k = 1; k < truth.size(); ++k)
        largest = std::max(largest,
                           ((result.position_m[k] - result.position_m[k - 1]) - (truth[k] - truth[k - 1])).norm());
    return largest;
}

/// The filter run by hand over a walk with a smoother capturing it, the ZUPT made either by the
/// block update (H selects the velocity) or as a general update through updateRows with the same H
/// written out, which the smoother stores and runs backwards as a dense matrix. The result holds
/// the filtered states, ready for the backward pass.
struct HandRun {
    Parameters params;
    std::unique_ptr<ErrorStateEkf> ekf;
    std::unique_ptr<RtsSmoother> smoother;
    Result result;
};

std::unique_ptr<HandRun> filterByHand(const Recording& recording, bool zuptAsGeneralUpdate)
{
    auto run = std::make_unique<HandRun>();
    const Parameters& params = run->params;
    const StanceFlags flags = detectStance(recording.samples, params);
    run->ekf = std::make_unique<ErrorStateEkf>(params, alignInitialAttitude(recording.samples, flags.stance, params).bodyToNav);
    ErrorStateEkf& ekf = *run->ekf;
    run->smoother = std::make_unique<RtsSmoother>(params, ekf);
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(3, ErrorStateEkf::kStates);
    h.middleCols<3>(ErrorStateEkf::kVel).setIdentity();
    const Eigen::VectorXd variance = Eigen::VectorXd::Constant(3, params.r_zupt_mps * params.r_zupt_mps);
    for (std::size_t k = 0; k < recording.samples.size(); ++k) {
        const ImuSample& sample = recording.samples[k];
        if (k > 0)
            ekf.propagate(sample.acc_mps2, sample.gyr_radps, sample.time_s - recording.samples[k - 1].time_s);
        if (flags.stance[k] && zuptAsGeneralUpdate)
            ekf.updateRows(h, ekf.state().velocity_mps, variance);
        else if (flags.stance[k])
            ekf.updateZeroVelocity();
        recordState(run->result, sample.time_s, ekf.state());
        run->result.errorStd.emplace_back();
        run->smoother->capture(ekf);
    }
    return run;
}

Result smoothByHand(const Recording& recording, bool zuptAsGeneralUpdate)
{
    const std::unique_ptr<HandRun> run = filterByHand(recording, zuptAsGeneralUpdate);
    run->smoother->smooth(run->result);
    return std::move(run->result);
}

/// Whether a and b hold the same states and standard deviations to the last bit.
bool sameToTheBit(const Result& a, const Result& b)
{
    const auto same = [](const auto& x, const auto& y) {
        return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
    };
    return same(a.position_m, b.position_m) && same(a.velocity_mps, b.velocity_mps)
           && same(a.rollPitchYaw_rad, b.rollPitchYaw_rad) && same(a.errorStd, b.errorStd);
}

Parameters fifteenStates()
{
    Parameters params;
    params.filter_states = static_cast<int>(FilterStates::Fifteen);
    params.use_zaru = true;
    return params;
}

}  // namespace

class TestRtsSmoother : public QObject {
    Q_OBJECT
private slots:
    void smootherFollowsTheTruthBetterThanTheFilter_data()
    {
        QTest::addColumn<int>("states");
        QTest::addColumn<double>("heightRatio");  // the smoother's height error at most this of the filter's
        // The 15-state filter's accelerometer bias states already take out most of the vertical drift.
        QTest::newRow("9 states") << static_cast<int>(FilterStates::Nine) << 0.8;
        QTest::newRow("15 states") << static_cast<int>(FilterStates::Fifteen) << 1.0;
    }

    void smootherFollowsTheTruthBetterThanTheFilter()
    {
        QFETCH(int, states);
        QFETCH(double, heightRatio);
        Parameters params = states == static_cast<int>(FilterStates::Nine) ? Parameters() : fifteenStates();
        double heightFilter = 0.0, heightSmoother = 0.0, jumpFilter = 0.0, jumpSmoother = 0.0;
        for (std::uint32_t seed = 1; seed <= 4; ++seed) {
            WalkSimulatorConfig sensor = mtiClassSensor(100.0, seed);
            sensor.accNoiseStd_mps2 *= 5.0;  // a low-cost accelerometer: more drift within each swing
            const SimulatedWalk walk = simulateWalk(straightLinePath(12.0), sensor);
            const Result filter = run(walk.recording, params, EstimatorKind::Ekf);
            const Result smoother = run(walk.recording, params, EstimatorKind::Smoother);
            const double hf = heightRms(filter, walk.truePosition_m), hs = heightRms(smoother, walk.truePosition_m);
            const double jf = largestStepError(filter, walk.truePosition_m);
            const double js = largestStepError(smoother, walk.truePosition_m);
            qInfo("seed %u: height RMS filter %.4f m, smoother %.4f m; largest step error %.4f / %.4f m", seed, hf, hs,
                  jf, js);
            heightFilter += hf;
            heightSmoother += hs;
            jumpFilter = std::max(jumpFilter, jf);
            jumpSmoother = std::max(jumpSmoother, js);
        }
        QVERIFY2(heightSmoother < heightRatio * heightFilter,
                 qPrintable(QString("height: filter %1, smoother %2").arg(heightFilter).arg(heightSmoother)));
        QVERIFY2(jumpSmoother < 0.7 * jumpFilter,
                 qPrintable(QString("jumps: filter %1, smoother %2").arg(jumpFilter).arg(jumpSmoother)));
    }

    void smoothedUncertaintyIsNeverAboveTheFilters()
    {
        const SimulatedWalk walk = simulateWalk(straightLinePath(10.0), mtiClassSensor(100.0, 3));
        const Result filter = run(walk.recording, fifteenStates(), EstimatorKind::Ekf);
        const Result smoother = run(walk.recording, fifteenStates(), EstimatorKind::Smoother);
        QCOMPARE(smoother.errorStd.size(), filter.errorStd.size());
        std::size_t smaller = 0;
        for (std::size_t k = 0; k < filter.errorStd.size(); ++k) {
            for (int i = 0; i < 15; ++i)
                QVERIFY2(smoother.errorStd[k](i) <= filter.errorStd[k](i) * 1.001f + 1e-9f,
                         qPrintable(QString("sample %1 state %2: %3 > %4").arg(k).arg(i)
                                        .arg(smoother.errorStd[k](i)).arg(filter.errorStd[k](i))));
            smaller += smoother.errorStd[k](ErrorStdIndex::velocity) < 0.9f * filter.errorStd[k](ErrorStdIndex::velocity);
        }
        // ZUPT observes the velocity: within a swing the next stance tightens it (the position,
        // a random walk under ZUPT alone, barely changes).
        QVERIFY2(smaller > filter.errorStd.size() / 4, "the smoother should tighten the velocity in the swings");
        // The last sample has no future: smoothed and filtered agree.
        QVERIFY((smoother.position_m.back() - filter.position_m.back()).norm() < 1e-12);
    }

    void smootherCanBeCancelled()
    {
        const SimulatedWalk walk = simulateWalk(straightLinePath(30.0), mtiClassSensor(100.0, 1));
        Parameters params;
        params.estimator = static_cast<int>(EstimatorKind::Smoother);
        double last = 0.0;
        const PipelineOutput output = runPipeline(walk.recording, params, [&](double fraction) {
            last = fraction;
            return fraction < 0.6;  // into the backward pass
        });
        QVERIFY(output.result.cancelled);
        QVERIFY(last >= 0.6);
    }

    void generalUpdatesRunBackwardsAsSelectingOnes()
    {
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), mtiClassSensor(100.0, 5));
        const Result selecting = smoothByHand(walk.recording, false);
        const Result general = smoothByHand(walk.recording, true);
        double position = 0.0, sigma = 0.0, correction = 0.0;
        const Result filtered = run(walk.recording, Parameters(), EstimatorKind::Ekf);
        for (std::size_t k = 0; k < selecting.position_m.size(); ++k) {
            position = std::max(position, (selecting.position_m[k] - general.position_m[k]).norm());
            sigma = std::max(sigma, double((selecting.errorStd[k] - general.errorStd[k]).norm()));
            correction = std::max(correction, (selecting.position_m[k] - filtered.position_m[k]).norm());
        }
        QVERIFY2(correction > 1e-3, "the smoother should move the path");  // so agreeing means something
        QVERIFY2(position < 1e-9, qPrintable(QString::number(position)));
        QVERIFY2(sigma < 1e-6, qPrintable(QString::number(sigma)));
    }

    void theVariancesThreadChangesNoDigit()
    {
        // smooth() runs the variances on a second thread beside the states and afterStates; one
        // pass after the other, and both in one pass, must give the same bits, and afterStates
        // sees the smoothed states.
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), mtiClassSensor(100.0, 5));
        for (const bool general : {false, true}) {
            const std::unique_ptr<HandRun> parallel = filterByHand(walk.recording, general);
            const std::unique_ptr<HandRun> sequential = filterByHand(walk.recording, general);
            QVERIFY(sequential->smoother->smoothStates(sequential->result));
            QVERIFY(sequential->smoother->smoothVariances(sequential->result.errorStd));
            int afterStatesRuns = 0;
            bool statesFinalThen = false;
            QVERIFY(parallel->smoother->smooth(parallel->result, {}, [&] {
                ++afterStatesRuns;
                statesFinalThen = parallel->result.position_m == sequential->result.position_m
                                  && parallel->result.rollPitchYaw_rad == sequential->result.rollPitchYaw_rad;
            }));
            QCOMPARE(afterStatesRuns, 1);
            QVERIFY(statesFinalThen);
            QVERIFY(sameToTheBit(parallel->result, sequential->result));
            // One thread: one pass carrying mu and L together.
            const std::unique_ptr<HandRun> together = filterByHand(walk.recording, general);
            QVERIFY(together->smoother->smooth(together->result, {}, {}, RtsSmoother::Threads::One));
            QVERIFY(sameToTheBit(together->result, sequential->result));
            QVERIFY2(parallel->result.position_m != filterByHand(walk.recording, general)->result.position_m,
                     "the backward pass should change the states");
        }
    }

    void smoothedVariancesStayFiniteOnALongWalk()
    {
        // Six laps of a 40 x 25 m rectangle (about 9 minutes at 100 Hz): the information matrix's
        // antisymmetric rounding error grew to overflow within a minute of such a walk's end.
        std::vector<Eigen::Vector3d> path{Eigen::Vector3d::Zero()};
        const std::vector<Eigen::Vector3d> lap = closedRectanglePath(40.0, 25.0);
        for (int i = 0; i < 6; ++i)
            path.insert(path.end(), lap.begin() + 1, lap.end());
        const SimulatedWalk walk = simulateWalk(path, mtiClassSensor(100.0, 3));
        const Result smoothed = run(walk.recording, Parameters(), EstimatorKind::Smoother);
        const Result filtered = run(walk.recording, Parameters(), EstimatorKind::Ekf);
        QVERIFY(smoothed.errorStd.size() > 50000);
        for (std::size_t k = 0; k < smoothed.errorStd.size(); ++k) {
            const Eigen::Matrix<float, 15, 1>& sigma = smoothed.errorStd[k];
            QVERIFY2(sigma.allFinite(), qPrintable(QStringLiteral("sample %1").arg(k)));
            // Smoothing only adds information (a little slack for rounding in float).
            QVERIFY2((sigma.array() <= filtered.errorStd[k].array() * 1.0001f + 1e-6f).all(),
                     qPrintable(QStringLiteral("sample %1").arg(k)));
        }
    }

    void aRecordingBeyondTheMemoryBudgetIsFilteredWithANote()
    {
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), mtiClassSensor(100.0, 5));
        const Parameters params;  // the smoother
        const StanceFlags flags = detectStance(walk.recording.samples, params);
        ErrorStateEkf ekf(params, Eigen::Matrix3d::Identity());
        std::vector<MethodNote> notes;
        QVERIFY(smootherFor(walk.recording.samples, params, flags, ekf, notes).has_value());
        QVERIFY(notes.empty());
        const RtsSmoother probe(params, ekf);
        const std::size_t needed = probe.projectedBytes(walk.recording.samples.size(),
                                                        std::size_t(std::count(flags.stance.begin(), flags.stance.end(), 1)));
        QVERIFY(!smootherFor(walk.recording.samples, params, flags, ekf, notes, needed - 1).has_value());
        QCOMPARE(notes.size(), std::size_t(1));
        QCOMPARE(notes.front().method, std::string("rts"));
        QVERIFY2(notes.front().message.find("not applied") == 0, notes.front().message.c_str());
        // The budget's figures: ten hours at 100 Hz with stance half the time fit, at 200 Hz not.
        const std::size_t tenHours100Hz = 10 * 3600 * 100;
        QVERIFY(probe.projectedBytes(tenHours100Hz, tenHours100Hz / 2) < RtsSmoother::kMemoryBudget_bytes);
        QVERIFY(probe.projectedBytes(2 * tenHours100Hz, tenHours100Hz) > RtsSmoother::kMemoryBudget_bytes);
    }

    void largeBlocksAreReusedByTheNextRun()
    {
        bulk::releaseCached();
        using Bulk = std::vector<double, BulkAllocator<double>>;
        const std::size_t doubles = 3 * (bulk::kHugePage_bytes / sizeof(double)) + 5;  // 6 MB and a bit
        const double* first = nullptr;
        {
            Bulk block(doubles);
            first = block.data();
            QCOMPARE(reinterpret_cast<std::uintptr_t>(first) % bulk::kHugePage_bytes, std::uintptr_t(0));
        }
        QCOMPARE(bulk::cachedBytes(), 4 * bulk::kHugePage_bytes);  // rounded up to whole huge pages
        {
            Bulk again(doubles - 1000);
            QCOMPARE(again.data(), first);  // the freed block, not a fresh one the kernel must zero
            QCOMPARE(bulk::cachedBytes(), std::size_t(0));
            Bulk another(doubles);
            QVERIFY(another.data() != first);
        }
        {
            Bulk muchSmaller(bulk::kHugePage_bytes / sizeof(double));  // 2 MB: would waste half of either
            QVERIFY(muchSmaller.data() != first);
        }
        // Never more than the bound, and nothing once released.
        std::vector<Bulk> many;
        for (std::size_t i = 0; i < bulk::kMaxCachedBlocks + 3; ++i)
            many.emplace_back(doubles);
        many.clear();
        QVERIFY(bulk::cachedBytes() <= bulk::kMaxCachedBlocks * 4 * bulk::kHugePage_bytes);
        bulk::releaseCached();
        QCOMPARE(bulk::cachedBytes(), std::size_t(0));
    }

    void aRerunReusingTheBlocksGivesTheSameResult()
    {
        // Two laps of a 40 x 25 m rectangle store about 15 MB: blocks the next run takes over with
        // the last run's numbers still in them, which it must overwrite before reading.
        const std::vector<Eigen::Vector3d> lap = closedRectanglePath(40.0, 25.0);
        std::vector<Eigen::Vector3d> path = lap;
        path.insert(path.end(), lap.begin() + 1, lap.end());
        const SimulatedWalk walk = simulateWalk(path, mtiClassSensor(100.0, 7));
        QVERIFY(walk.recording.samples.size() > 20000);
        bulk::releaseCached();
        const Result fresh = run(walk.recording, Parameters(), EstimatorKind::Smoother);
        QVERIFY(bulk::cachedBytes() > 0);
        Parameters other;
        other.r_zupt_mps *= 2.0;  // a different run leaves different numbers in the blocks
        run(walk.recording, other, EstimatorKind::Smoother);
        const Result reused = run(walk.recording, Parameters(), EstimatorKind::Smoother);
        QCOMPARE(reused.position_m.size(), fresh.position_m.size());
        for (std::size_t k = 0; k < fresh.position_m.size(); ++k) {
            QCOMPARE(reused.position_m[k], fresh.position_m[k]);
            QCOMPARE(reused.errorStd[k], fresh.errorStd[k]);
        }
    }

    void storageIsWhatTheHeaderSays()
    {
        Parameters nine;
        ErrorStateEkf ekf9(nine, Eigen::Matrix3d::Identity());
        const RtsSmoother smoother9(nine, ekf9);
        QCOMPARE(smoother9.bytesPerSample(), std::size_t(54 * 8));
        QCOMPARE(smoother9.bytesPerUpdate(3), std::size_t(45 * 8));
        const Parameters fifteen = fifteenStates();
        ErrorStateEkf ekf15(fifteen, Eigen::Matrix3d::Identity());
        const RtsSmoother smoother15(fifteen, ekf15);
        QCOMPARE(smoother15.bytesPerSample(), std::size_t(133 * 8));
        QCOMPARE(smoother15.bytesPerUpdate(6), std::size_t(141 * 8));
    }
};

QTEST_GUILESS_MAIN(TestRtsSmoother)
#include "tst_rtssmoother.moc"
