// Self-tuning: on simulated walks whose best setting is known by an exhaustive scan, the search
// finds it; it rejects settings that trade a plausible path for a number; it is deterministic.
#include "metrics/Evaluation.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"
#include "tune/AutoTune.h"

#include <QtTest>

using namespace footpath;

namespace {

/// A simulated walk that carries its truth as reference positions (criterion "reference").
Recording walkWithTruth(std::uint32_t seed, double accNoiseFactor)
{
    WalkSimulatorConfig sensor = mtiClassSensor(100.0, seed);
    sensor.accNoiseStd_mps2 *= accNoiseFactor;
    sensor.gyrNoiseStd_radps *= accNoiseFactor;
    SimulatedWalk walk = simulateWalk(closedRectanglePath(8.0, 5.0), sensor);
    walk.recording.reference.positions_m = walk.truePosition_m;
    walk.recording.reference.closedLoop = true;
    return std::move(walk.recording);
}

/// A fixed threshold on SHOE's statistic: one dimension, whose best value a scan can find.
Parameters fixedThresholdBase()
{
    Parameters params;
    params.zv_adaptive = false;
    params.zv_log_threshold = 7.5;  // far too permissive: stances found in the swings
    params.estimator = static_cast<int>(EstimatorKind::Ekf);
    return params;
}

const std::vector<TuneDimension> kThresholdOnly{{"zv_log_threshold", 2.0, 8.0, false}};

double meanArmse(const std::vector<const Recording*>& walks, const Parameters& params)
{
    double sum = 0.0;
    for (const Recording* walk : walks)
        sum += tuneScore(*walk, runPipeline(*walk, params).result, TuneCriterion::Reference);
    return sum / static_cast<double>(walks.size());
}

}  // namespace

class TestAutoTune : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        for (std::uint32_t seed = 1; seed <= 3; ++seed)
            walks_.push_back(walkWithTruth(seed, 3.0));
        for (const Recording& walk : walks_)
            pointers_.push_back(&walk);
    }

    void findsTheBestThresholdAScanFinds()
    {
        // The exhaustive scan: every 0.1 decade.
        double scanBest = 1e9, scanBestThreshold = 0.0;
        for (double threshold = 2.0; threshold <= 8.0001; threshold += 0.1) {
            Parameters params = fixedThresholdBase();
            params.zv_log_threshold = threshold;
            const double score = meanArmse(pointers_, params);
            if (score < scanBest) {
                scanBest = score;
                scanBestThreshold = threshold;
            }
        }
        TuneOptions options;
        options.criterion = TuneCriterion::Reference;
        options.evaluations = 30;
        options.space = kThresholdOnly;
        const TuneOutcome outcome = tuneParameters(pointers_, fixedThresholdBase(), options);
        QVERIFY2(outcome.error.empty(), outcome.error.c_str());
        qInfo("scan: best threshold 10^%.1f, ARMSE %.4f m; tuner: 10^%.2f, %.4f m (start %.4f m), %d evaluations",
              scanBestThreshold, scanBest, outcome.best.zv_log_threshold, outcome.bestScore, outcome.baseScore,
              outcome.evaluations);
        QCOMPARE(outcome.evaluations, 30);
        QVERIFY(outcome.baseScore > 2.0 * scanBest);  // the start is clearly wrong
        QVERIFY2(outcome.bestScore <= scanBest * 1.05 + 1e-3, "the tuner should reach the scan's best");
        // The reported score is the score of the returned parameters.
        QVERIFY(std::abs(meanArmse(pointers_, outcome.best) - outcome.bestScore) < 1e-9);
    }

    void isDeterministicForASeedWhateverTheThreads()
    {
        TuneOptions options;
        options.criterion = TuneCriterion::ClosedLoop;
        options.evaluations = 17;
        options.threads = 1;
        const TuneOutcome one = tuneParameters(pointers_, Parameters(), options);
        options.threads = 3;
        const TuneOutcome three = tuneParameters(pointers_, Parameters(), options);
        QVERIFY(one.error.empty());
        QVERIFY(one.best == three.best);
        QCOMPARE(one.bestScore, three.bestScore);
        QVERIFY(one.bestScore <= one.baseScore);
    }

    void closedLoopTuningKeepsThePathLength()
    {
        // A shrunken path closes better without being better: closed-loop candidates may not
        // change a walk's path length by more than 10 %.
        TuneOptions options;
        options.criterion = TuneCriterion::ClosedLoop;
        options.evaluations = 40;
        const TuneOutcome outcome = tuneParameters(pointers_, Parameters(), options);
        QVERIFY(outcome.error.empty());
        for (const Recording* walk : pointers_) {
            const double before = runPipeline(*walk, Parameters()).result.summary.pathLength_m;
            const double after = runPipeline(*walk, outcome.best).result.summary.pathLength_m;
            QVERIFY2(std::abs(after - before) <= 0.1 * before, qPrintable(QString("%1 -> %2 m").arg(before).arg(after)));
        }
    }

    void rejectsSettingsThatAddWarnings()
    {
        // A threshold range that only holds settings which miss stances (long swings): nothing
        // in it may be returned, however small its closure comes out.
        TuneOptions options;
        options.criterion = TuneCriterion::ClosedLoop;
        options.evaluations = 12;
        options.space = {{"zv_log_threshold", -4.0, -3.0, false}};
        Parameters base = fixedThresholdBase();
        base.zv_log_threshold = 5.0;
        const TuneOutcome outcome = tuneParameters(pointers_, base, options);
        QVERIFY(outcome.error.empty());
        QVERIFY(outcome.best == base);
        QCOMPARE(outcome.bestScore, outcome.baseScore);
    }

    void searchSpaceHoldsOnlyAFootsRest()
    {
        // "Tune for this recording" set the shortest stance to 0.00096 s (strides 23 -> 29): the
        // default space may not reach below a foot's rest.
        for (const Parameters& base : {Parameters(), fixedThresholdBase()})
            for (const TuneDimension& dimension : defaultTuneSpace(base))
                if (dimension.name == "zv_min_stance_s")
                    QVERIFY2(dimension.low >= kMinTunedStance_s, qPrintable(QString::number(dimension.low)));
        const TuneOutcome outcome = tuneParameters(pointers_, Parameters(), TuneOptions{});
        QVERIFY(outcome.error.empty());
        QVERIFY(outcome.best.zv_min_stance_s >= kMinTunedStance_s);
        // On these simulated walks the strides hold, and nothing is cautioned about.
        QVERIFY2(outcome.cautions.empty(), outcome.cautions.empty() ? "" : outcome.cautions.front().c_str());
    }

    void stridesThatJumpAreCautionedAbout()
    {
        QCOMPARE(strideCaution({23, 0.05}, {29, 0.31}),
                 std::string("strides 23 -> 29, stride length spread 0.05 -> 0.31 m"));
        QCOMPARE(strideCaution({23, 0.05}, {24, 0.06}), std::string());  // within what tuning may change
        QCOMPARE(strideCaution({10, 0.05}, {12, 0.05}), std::string("strides 10 -> 12"));
        QCOMPARE(strideCaution({10, 0.10}, {10, 0.30}), std::string("stride length spread 0.1 -> 0.3 m"));
    }

    void saysWhenNothingCanBeScored()
    {
        Recording open = walks_.front();
        open.reference = Reference();
        TuneOptions options;
        options.criterion = TuneCriterion::KnownLength;
        const TuneOutcome outcome = tuneParameters({&open}, Parameters(), options);
        QVERIFY(outcome.error.find("known length") != std::string::npos);
        options.space = {{"no_such_parameter", 0.0, 1.0, false}};
        QVERIFY(tuneParameters({&open}, Parameters(), options).error.find("no_such_parameter") != std::string::npos);
    }

    void cancelStopsWithTheBestSoFar()
    {
        std::atomic<bool> cancel{false};
        TuneOptions options;
        options.criterion = TuneCriterion::Reference;
        options.evaluations = 200;
        options.space = kThresholdOnly;
        int calls = 0;
        const TuneOutcome outcome = tuneParameters(pointers_, fixedThresholdBase(), options, [&](const TuneProgress& p) {
            ++calls;
            QVERIFY(p.bestScore <= 1e9);
            if (p.evaluations >= 100)
                cancel = true;
        }, &cancel);
        QVERIFY(outcome.cancelled);
        QVERIFY(outcome.evaluations < 200);
        QVERIFY(calls > 1);
    }

private:
    std::vector<Recording> walks_;
    std::vector<const Recording*> pointers_;
};

QTEST_GUILESS_MAIN(TestAutoTune)
#include "tst_autotune.moc"
