// Gait events (core/gait/GaitEvents.h): on simulated strides whose events follow from the motion
// model, and against the hand-labelled events of the IPOL MTw walks.

#include "TestData.h"
#include "gait/ApproximateRotation.h"
#include "gait/GaitEvents.h"
#include "nav/Attitude.h"
#include "io/Import.h"
#include "io/ResultWriters.h"
#include "metrics/Evaluation.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include <QtTest>

#include <algorithm>
#include <random>
#include <cmath>
#include <sstream>
#include <vector>

using namespace footpath;

namespace {

/// The simulator's foot has no heel or toe roll: it leaves rest flat (toe off and heel off at
/// once) and lands flat (heel strike and foot flat at once). Each swing as the samples from the
/// first one off rest to the last one before rest again.
std::vector<SampleRange> trueSwings(const std::vector<std::uint8_t>& trueStance)
{
    std::vector<SampleRange> swings;
    for (std::size_t k = 1; k < trueStance.size(); ++k) {
        if (trueStance[k - 1] && !trueStance[k])
            swings.push_back({k, k});
        else if (!trueStance[k - 1] && trueStance[k] && !swings.empty())
            swings.back().last = k - 1;
    }
    return swings;
}

std::vector<double> eventTimes(const Result& result, GaitEventKind kind)
{
    std::vector<double> times;
    for (const GaitEvent& event : result.gaitEvents)
        if (event.kind == kind)
            times.push_back(event.time_s);
    return times;
}

struct SimulatedGait {
    SimulatedWalk walk;
    Result result;
    std::vector<SampleRange> swings;
};

SimulatedGait simulateGait(const std::vector<Eigen::Vector3d>& path, double rate_hz)
{
    SimulatedGait gait;
    gait.walk = simulateWalk(path, mtiClassSensor(rate_hz));
    gait.result = runPipeline(gait.walk.recording, Parameters()).result;
    gait.swings = trueSwings(gait.walk.trueStance);
    return gait;
}

const double kSampleTolerance_s = 1e-9;

}  // namespace

class TestGaitEvents : public QObject {
    Q_OBJECT

private slots:
    void approximateSineAndCosineStayWithinTheirBound()
    {
        // The gait events' axis sign relies on this bound (rateAgreesWithMotion).
        std::mt19937 random(7);
        std::uniform_real_distribution<double> angle(-25.0, 25.0);
        double worst = 0.0;
        for (int i = 0; i < 200000; ++i) {
            const double x = i < 1000 ? -7.0 + 0.014 * i : angle(random);  // a sweep over the quadrants, then random
            double sine = 0.0, cosine = 0.0;
            approximateSinCos(x, sine, cosine);
            worst = std::max({worst, std::abs(sine - std::sin(x)), std::abs(cosine - std::cos(x))});
        }
        qInfo("largest error %.3g", worst);
        QVERIFY2(worst <= 2e-9, qPrintable(QString::number(worst)));
        double sine = 0.0, cosine = 0.0;
        approximateSinCos(2e3, sine, cosine);
        QVERIFY(std::isnan(sine) && std::isnan(cosine));
    }

    void approximateRateRightOfMotionStaysWithinItsBound()
    {
        // Each entry of the approximate rotation within 12e-9 of the exact one, so the rate is
        // within 12e-9 |w|_1 |v_h|_1 of the exact rotation's.
        std::mt19937 random(11);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        double worstShare = 0.0;
        for (int i = 0; i < 100000; ++i) {
            const Eigen::Vector3d rpy(M_PI * unit(random), 0.5 * M_PI * unit(random), M_PI * unit(random));
            const Eigen::Vector3d gyr = 10.0 * Eigen::Vector3d(unit(random), unit(random), unit(random));
            const Eigen::Vector3d velocity = 4.0 * Eigen::Vector3d(unit(random), unit(random), unit(random));
            const double exact =
                rateRightOfMotion(rotationFromRollPitchYaw(rpy.x(), rpy.y(), rpy.z()), gyr, velocity);
            const double bound = gyr.lpNorm<1>() * (std::abs(velocity.x()) + std::abs(velocity.y()));
            worstShare = std::max(worstShare, std::abs(approximateRateRightOfMotion(rpy, gyr, velocity) - exact) / bound);
        }
        qInfo("largest error %.3g of the bound", worstShare);
        QVERIFY2(worstShare <= 12e-9, qPrintable(QString::number(worstShare)));
    }

    void eventTimingTakesTheNearestDetectedEvent();
    void simulatedStridesAtEitherRate_data();
    void simulatedStridesAtEitherRate();
    void eventsDoNotDependOnTheRate();
    void ratesGivenAreTheRatesUsed();
    void turningStridesAreTheCorners();
    void csvColumns();
    void ipolTrials_data();
    void ipolTrials();
};

void TestGaitEvents::eventTimingTakesTheNearestDetectedEvent()
{
    // Reference 1.0 -> nearest 1.02 (0.02); 2.0 -> 1.97 (0.03); 3.0 -> 3.05 (0.05); 9.0 is outside.
    const EventTimingScore score = scoreEventTiming({3.05, 1.02, 1.97, 8.0}, {1.0, 2.0, 3.0, 9.0}, 0.5, 3.5);
    QCOMPARE(score.referenceEvents, std::size_t(3));
    QVERIFY(std::abs(score.medianError_s - 0.03) < 1e-12);
    QVERIFY(std::abs(score.meanError_s - 0.1 / 3.0) < 1e-12);
    QVERIFY(std::abs(score.maxError_s - 0.05) < 1e-12);
    QCOMPARE(score.missed, std::size_t(0));
    QCOMPARE(scoreEventTiming({1.02, 1.97}, {1.0, 2.0, 3.0}, 0.5, 3.5, 0.1).missed, std::size_t(1));
    // Nothing detected: no error to report, not a zero one.
    QVERIFY(std::isnan(scoreEventTiming({}, {1.0}, 0.0, 2.0).medianError_s));
}

void TestGaitEvents::simulatedStridesAtEitherRate_data()
{
    QTest::addColumn<double>("rate_hz");
    QTest::newRow("100 Hz") << 100.0;
    QTest::newRow("200 Hz") << 200.0;
}

void TestGaitEvents::simulatedStridesAtEitherRate()
{
    QFETCH(double, rate_hz);
    const WalkSimulatorConfig config = mtiClassSensor(rate_hz);
    const SimulatedGait gait = simulateGait(straightLinePath(14.0), rate_hz);
    const Result& result = gait.result;
    const std::vector<double>& time_s = result.time_s;
    QCOMPARE(gait.swings.size(), std::size_t(10));
    // One stride from each heel strike to the next: one fewer than swings.
    QCOMPARE(result.gaitStrides.size(), gait.swings.size() - 1);
    for (std::size_t i = 0; i < result.gaitStrides.size(); ++i) {
        const GaitStride& stride = result.gaitStrides[i];
        const SampleRange& swing = gait.swings[i];
        const SampleRange& nextSwing = gait.swings[i + 1];
        const double landed_s = time_s[swing.last + 1], leaves_s = time_s[nextSwing.first - 1];
        const double nextLanded_s = time_s[nextSwing.last + 1];
        // The foot flat and heel off bound the rest within 30 ms (|w| must rise past the quiet margin).
        QVERIFY2(std::abs(stride.footFlat.time_s - landed_s) <= 0.03, qPrintable(QString::number(stride.footFlat.time_s - landed_s)));
        QVERIFY2(std::abs(stride.heelOff.time_s - leaves_s) <= 0.03, qPrintable(QString::number(stride.heelOff.time_s - leaves_s)));
        // Without a roll, the half-dip points lie inside the simulated swing, before its middle.
        const double swingMiddle_s = 0.5 * (time_s[nextSwing.first] + time_s[nextSwing.last]);
        if (i == 0)
            qInfo("simulated at %g Hz: toe off %.0f ms after the foot leaves rest, heel strike %.0f ms before it lands",
                  rate_hz, 1000.0 * (stride.toeOff.time_s - leaves_s), 1000.0 * (landed_s - stride.heelStrike.time_s));
        QVERIFY(stride.toeOff.time_s > leaves_s && stride.toeOff.time_s < swingMiddle_s);
        QVERIFY(stride.heelStrike.time_s < landed_s
                && stride.heelStrike.time_s > 0.5 * (time_s[swing.first] + time_s[swing.last]));
        QVERIFY(stride.heelStrike.time_s < stride.footFlat.time_s && stride.footFlat.time_s <= stride.heelOff.time_s
                && stride.heelOff.time_s < stride.toeOff.time_s && stride.toeOff.time_s < stride.nextHeelStrike.time_s);
        // The stride's time is the simulated one: the same offset at both heel strikes.
        QVERIFY2(std::abs(stride.strideTime_s - (nextLanded_s - landed_s)) < 0.5 / rate_hz + kSampleTolerance_s,
                 qPrintable(QString::number(stride.strideTime_s)));
        QVERIFY(std::abs(stride.cadence_spm - 120.0 / stride.strideTime_s) < 1e-9);
        QVERIFY(std::abs(stride.stancePct + stride.swingPct - 100.0) < 1e-9);
        QVERIFY2(std::abs(stride.strideLength_m - config.strideLength_m) < 0.05, qPrintable(QString::number(stride.strideLength_m)));
        QVERIFY2(std::abs(stride.clearance_m - config.footLift_m) < 0.02, qPrintable(QString::number(stride.clearance_m)));
        QVERIFY(!stride.turning && !stride.paused);
    }
    // Every stride alike: the stance share varies by less than two samples' worth.
    const auto [least, most] = std::minmax_element(result.gaitStrides.begin(), result.gaitStrides.end(),
                                                   [](const GaitStride& a, const GaitStride& b) { return a.stancePct < b.stancePct; });
    QVERIFY2(most->stancePct - least->stancePct < 100.0 * 2.0 / rate_hz / 1.1, qPrintable(QString::number(most->stancePct - least->stancePct)));
    const GaitSummary& walk = result.gait;
    QCOMPARE(walk.strides, result.gaitStrides.size());
    QCOMPARE(walk.straightStrides, walk.strides);
    QVERIFY(std::abs(walk.strideTime_s - (config.stanceDuration_s + config.swingDuration_s)) < 0.01);
    // The gait stance holds the ZUPT stance: every sample at rest is in the gait stance.
    QCOMPARE(result.gaitStance.size(), time_s.size());
    for (std::size_t k = 0; k < time_s.size(); ++k)
        QVERIFY2(!gait.walk.trueStance[k] || result.gaitStance[k], qPrintable(QString::number(time_s[k])));
    // The events list: per inner stance heel strike, foot flat, heel off, toe off, in time order.
    QCOMPARE(eventTimes(result, GaitEventKind::ToeOff).size(), gait.swings.size());
    QCOMPARE(eventTimes(result, GaitEventKind::HeelStrike).size(), gait.swings.size());
    QVERIFY(std::is_sorted(result.gaitEvents.begin(), result.gaitEvents.end(),
                           [](const GaitEvent& a, const GaitEvent& b) { return a.time_s < b.time_s; }));
}

void TestGaitEvents::eventsDoNotDependOnTheRate()
{
    const SimulatedGait at100 = simulateGait(straightLinePath(14.0), 100.0);
    const SimulatedGait at200 = simulateGait(straightLinePath(14.0), 200.0);
    for (GaitEventKind kind : {GaitEventKind::HeelStrike, GaitEventKind::ToeOff}) {
        const std::vector<double> a = eventTimes(at100.result, kind), b = eventTimes(at200.result, kind);
        QCOMPARE(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i)
            QVERIFY2(std::abs(a[i] - b[i]) < 0.005, qPrintable(QStringLiteral("%1 %2: %3 s at 100 Hz, %4 s at 200 Hz")
                                                                  .arg(gaitEventKindName(kind)).arg(i).arg(a[i]).arg(b[i])));
    }
}

void TestGaitEvents::ratesGivenAreTheRatesUsed()
{
    // runPipeline hands over the rates the detector's thread computed (gaitRatesOf): the detection
    // must use them, not quietly compute its own (only rates of the wrong length are replaced).
    const SimulatedGait gait = simulateGait(straightLinePath(14.0), 100.0);
    const Recording& recording = gait.walk.recording;
    Result own = gait.result, given = gait.result, flat = gait.result;
    detectGaitEvents(recording, own);
    detectGaitEvents(recording, gaitRatesOf(recording.samples), given);
    QVERIFY(!own.gaitEvents.empty());
    QCOMPARE(given.gaitEvents.size(), own.gaitEvents.size());
    QVERIFY(given.gaitStance == own.gaitStance);
    GaitRates still = gaitRatesOf(recording.samples);  // a foot that never turns: no swing
    std::fill(still.rawAlongAxis.begin(), still.rawAlongAxis.end(), 0.0);
    std::fill(still.smoothedAlongAxis.begin(), still.smoothedAlongAxis.end(), 0.0);
    detectGaitEvents(recording, still, flat);
    QVERIFY(flat.gaitEvents.empty());
    GaitRates truncated = gaitRatesOf(recording.samples);
    truncated.l1Norm.pop_back();
    detectGaitEvents(recording, truncated, flat);
    QCOMPARE(flat.gaitEvents.size(), own.gaitEvents.size());
}

void TestGaitEvents::turningStridesAreTheCorners()
{
    // 7 x 4.2 m: 5 strides along x, 3 along y and so on; the foot turns 90 degrees in the first
    // swing of each new side, which is the second swing of a stride that starts before the corner.
    const SimulatedGait gait = simulateGait(closedRectanglePath(7.0, 4.2), 100.0);
    const std::vector<GaitStride>& strides = gait.result.gaitStrides;
    QCOMPARE(strides.size(), gait.swings.size() - 1);
    std::vector<std::size_t> turning;
    for (std::size_t i = 0; i < strides.size(); ++i)
        if (strides[i].turning)
            turning.push_back(i);
    // Swings 5, 8 and 13 (0-based) start a new side; stride i ends with swing i + 1.
    QCOMPARE(turning, (std::vector<std::size_t>{4, 7, 12}));
    for (std::size_t i : turning)
        QVERIFY2(std::abs(std::abs(strides[i].headingChange_rad) - M_PI / 2) < 0.05,
                 qPrintable(QString::number(strides[i].headingChange_rad)));
    QCOMPARE(gait.result.gait.turningStrides, std::size_t(3));
    QCOMPARE(gait.result.gait.straightStrides, strides.size() - 3);
}

void TestGaitEvents::csvColumns()
{
    const SimulatedGait gait = simulateGait(straightLinePath(14.0), 100.0);
    const Result& result = gait.result;
    std::ostringstream trajectory, steps;
    writeTrajectoryCsv(trajectory, result);
    writeStepsCsv(steps, result);

    // The trajectory's gait_stance column, beside stance, is the per-sample flag.
    const QStringList trajectoryRows = QString::fromStdString(trajectory.str()).split('\n', Qt::SkipEmptyParts);
    const qsizetype column = trajectoryRows[0].split(',').indexOf(QStringLiteral("gait_stance"));
    QCOMPARE(trajectoryRows[0].split(',').indexOf(QStringLiteral("stance")), column - 1);
    QCOMPARE(std::size_t(trajectoryRows.size() - 1), result.gaitStance.size());
    for (int r = 1; r < trajectoryRows.size(); ++r)
        QCOMPARE(trajectoryRows[r].split(',')[column].toInt(), int(result.gaitStance[std::size_t(r - 1)]));

    // Steps: each stance between two swings carries its stride's gait figures; the standing
    // stances at either end belong to no stride (the last one's heel strike ends the last stride).
    const QStringList stepRows = QString::fromStdString(steps.str()).split('\n', Qt::SkipEmptyParts);
    const QStringList header = stepRows[0].split(',');
    const qsizetype heelStrike = header.indexOf(QStringLiteral("heel_strike_s"));
    QCOMPARE(header.mid(heelStrike), (QStringList{"heel_strike_s", "toe_off_s", "gait_stance_pct", "swing_pct",
                                                  "clearance_m", "turning"}));
    QCOMPARE(std::size_t(stepRows.size() - 1), result.steps.size());
    int withGait = 0;
    for (int r = 1; r < stepRows.size(); ++r) {
        const QStringList cells = stepRows[r].split(',');
        QCOMPARE(cells.size(), header.size());
        if (cells[heelStrike].isEmpty())
            continue;
        ++withGait;
        const GaitStride& stride = result.gaitStrides[std::size_t(withGait - 1)];
        QVERIFY(cells[heelStrike].toDouble() <= cells[1].toDouble() && cells[2].toDouble() <= cells[heelStrike + 1].toDouble());
        QVERIFY(std::abs(cells[heelStrike + 2].toDouble() - stride.stancePct) < 1e-6);
        QVERIFY(std::abs(cells[heelStrike + 4].toDouble() - stride.clearance_m) < 1e-6);
        QCOMPARE(cells[heelStrike + 5], QStringLiteral("0"));
    }
    QCOMPARE(std::size_t(withGait), result.gaitStrides.size());
}

void TestGaitEvents::ipolTrials_data()
{
    // The trials whose time base has no gap inside the trial boundaries (1-1 and 3-2_rf lose
    // packets only after the trial; 12-3 loses them throughout and is not scored). The figures
    // are what the detector measured: gait-stance F1 and the median heel-strike and toe-off
    // errors in ms; the test allows kF1Margin and kTimingMargin_ms on them.
    QTest::addColumn<QString>("file");
    QTest::addColumn<double>("f1");
    QTest::addColumn<double>("heelStrike_ms");
    QTest::addColumn<double>("toeOff_ms");
    QTest::newRow("1-1 left") << "1-1_lf.txt" << 0.986 << 10.7 << 5.4;
    QTest::newRow("1-1 right") << "1-1_rf.txt" << 0.973 << 11.5 << 6.8;
    QTest::newRow("1-4 left") << "1-4_lf.txt" << 0.984 << 4.0 << 11.3;
    QTest::newRow("1-4 right") << "1-4_rf.txt" << 0.985 << 6.4 << 7.3;
    QTest::newRow("3-2 left") << "3-2_lf.txt" << 0.990 << 6.6 << 7.2;
    QTest::newRow("3-2 right") << "3-2_rf.txt" << 0.970 << 14.3 << 3.9;
    QTest::newRow("10-1 left") << "10-1_lf.txt" << 0.989 << 9.1 << 2.7;
    QTest::newRow("10-1 right") << "10-1_rf.txt" << 0.980 << 11.5 << 2.2;
    QTest::newRow("14-1 left") << "14-1_lf.txt" << 0.989 << 7.6 << 4.6;
    QTest::newRow("14-1 right") << "14-1_rf.txt" << 0.980 << 4.1 << 9.5;
}

void TestGaitEvents::ipolTrials()
{
    FOOTPATH_REQUIRE_DATASETS();
    QFETCH(QString, file);
    QFETCH(double, f1);
    QFETCH(double, heelStrike_ms);
    QFETCH(double, toeOff_ms);
    const double kF1Margin = 0.01, kTimingMargin_ms = 4.0;
    const ImportResult imported = importRecording(datasetPath(QStringLiteral("xsens-mtw-ipol/") + file).toStdString());
    QVERIFY(imported.ok());
    const Reference& reference = imported.recording.reference;
    QVERIFY(!reference.swings.empty() && reference.hasTrialBoundaries);
    const Result result = runPipeline(imported.recording, Parameters()).result;

    const StanceScore gaitStance = scoreStanceDetection(result.gaitStance, reference.swings, &reference.trialBoundaries);
    const StanceScore zuptStance = scoreStanceDetection(result.flags.stance, reference.swings, &reference.trialBoundaries);
    const GaitEventTiming timing = scoreGaitEventTiming(result, reference);
    const QString measured =
        QStringLiteral("F1 %1 (ZUPT %2), heel strike %3 ms (worst %4), toe off %5 ms (worst %6), missed %7")
            .arg(gaitStance.f1, 0, 'f', 3).arg(zuptStance.f1, 0, 'f', 3)
            .arg(1000.0 * timing.heelStrike.medianError_s, 0, 'f', 1)
            .arg(1000.0 * timing.heelStrike.maxError_s, 0, 'f', 0)
            .arg(1000.0 * timing.toeOff.medianError_s, 0, 'f', 1)
            .arg(1000.0 * timing.toeOff.maxError_s, 0, 'f', 0)
            .arg(timing.heelStrike.missed);
    qInfo("%s: %s", qPrintable(file), qPrintable(measured));
    QVERIFY2(gaitStance.f1 >= f1 - kF1Margin, qPrintable(measured));
    QVERIFY2(1000.0 * timing.heelStrike.medianError_s <= heelStrike_ms + kTimingMargin_ms, qPrintable(measured));
    QVERIFY2(1000.0 * timing.toeOff.medianError_s <= toeOff_ms + kTimingMargin_ms, qPrintable(measured));
    // The targets hold on every trial, far above the ZUPT's foot at rest.
    QVERIFY2(gaitStance.f1 >= 0.95 && gaitStance.f1 > zuptStance.f1 + 0.25, qPrintable(measured));
    QVERIFY2(timing.heelStrike.medianError_s < 0.02 && timing.toeOff.medianError_s < 0.02, qPrintable(measured));
    QCOMPARE(timing.heelStrike.referenceEvents, timing.toeOff.referenceEvents);
    // At most the U-turn's pivot (a swing under 0.25 s that hardly turns the foot) goes unseen.
    QVERIFY2(timing.heelStrike.missed <= 1 && timing.toeOff.missed == timing.heelStrike.missed, qPrintable(measured));
}

QTEST_GUILESS_MAIN(TestGaitEvents)
#include "tst_gaitevents.moc"
