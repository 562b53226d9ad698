// Both feet of one walk (core/gait/BilateralGait.h): double support and symmetry on strides of
// known timing, the pairing of left and right file names, the path alignment, and double support
// against the hand-labelled events of the gap-free IPOL MTw trials.

#include "TestData.h"
#include "gait/BilateralGait.h"
#include "io/FootPairing.h"
#include "io/Import.h"
#include "nav/Pipeline.h"

#include <Eigen/Geometry>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace footpath;

namespace {

/// A foot walking at a steady rhythm: heel strikes at firstHeelStrike + k * cycle, stance for
/// stanceShare of the cycle, `cycles` complete cycles; the events start with the toe off before
/// the first heel strike, as a detected walk's do.
struct Rhythm {
    double firstHeelStrike_s = 0.0;
    double cycle_s = 1.1;
    double stanceShare = 0.62;
    int cycles = 10;
};

GaitEvent event(GaitEventKind kind, double time_s)
{
    GaitEvent e;
    e.kind = kind;
    e.time_s = time_s;
    return e;
}

/// A result holding only the gait events and strides of the rhythm (what BilateralGait reads),
/// with the per-walk means of GaitSummary set from the rhythm.
Result resultOf(const Rhythm& rhythm, double strideLength_m)
{
    Result result;
    result.gaitEvents.push_back(event(GaitEventKind::ToeOff, rhythm.firstHeelStrike_s - (1.0 - rhythm.stanceShare) * rhythm.cycle_s));
    for (int k = 0; k <= rhythm.cycles; ++k) {
        const double heelStrike = rhythm.firstHeelStrike_s + k * rhythm.cycle_s;
        result.gaitEvents.push_back(event(GaitEventKind::HeelStrike, heelStrike));
        if (k < rhythm.cycles)
            result.gaitEvents.push_back(event(GaitEventKind::ToeOff, heelStrike + rhythm.stanceShare * rhythm.cycle_s));
    }
    for (int k = 0; k < rhythm.cycles; ++k) {
        GaitStride stride;
        stride.heelStrike = result.gaitEvents[std::size_t(2 * k + 1)];
        stride.toeOff = result.gaitEvents[std::size_t(2 * k + 2)];
        stride.nextHeelStrike = result.gaitEvents[std::size_t(2 * k + 3)];
        stride.strideTime_s = rhythm.cycle_s;
        stride.strideLength_m = strideLength_m;
        stride.stancePct = 100.0 * rhythm.stanceShare;
        stride.swingPct = 100.0 - stride.stancePct;
        result.gaitStrides.push_back(stride);
    }
    result.gait.strides = result.gait.straightStrides = result.gaitStrides.size();
    result.gait.strideTime_s = rhythm.cycle_s;
    result.gait.strideLength_m = strideLength_m;
    result.gait.stancePct = 100.0 * rhythm.stanceShare;
    result.gait.swingPct = 100.0 - result.gait.stancePct;
    const double end = rhythm.firstHeelStrike_s + (rhythm.cycles + 1) * rhythm.cycle_s;
    for (double t = rhythm.firstHeelStrike_s - 1.0; t < end; t += 0.01)
        result.time_s.push_back(t);
    return result;
}

/// One foot of a long walk with a jittered rhythm: some swings missed, some found twice (split
/// in two), some strides turning; `offset_s` shifts it against the other foot.
struct JitteredFoot {
    std::vector<GaitCycle> cycles;
    std::vector<FootSwing> swings;
};

JitteredFoot jitteredFoot(int strides, double offset_s, std::mt19937& random)
{
    std::uniform_real_distribution<double> jitter(-0.08, 0.08);
    std::uniform_int_distribution<int> oddity(0, 49);
    JitteredFoot foot;
    double heelStrike_s = offset_s;
    for (int k = 0; k < strides; ++k) {
        const double toeOff_s = heelStrike_s + 0.68 + jitter(random), next_s = heelStrike_s + 1.1 + jitter(random);
        const int odd = oddity(random);
        if (odd == 0) {  // found twice: two short swings
            const double middle_s = 0.5 * (toeOff_s + next_s);
            foot.swings.push_back({toeOff_s, middle_s - 0.02});
            foot.swings.push_back({middle_s + 0.02, next_s});
        } else if (odd != 1) {  // 1: missed
            foot.swings.push_back({toeOff_s, next_s});
        }
        foot.cycles.push_back({heelStrike_s, toeOff_s, next_s, odd != 2});
        heelStrike_s = next_s;
    }
    return foot;
}

/// summariseDoubleSupport against doubleSupportIn over every swing of the other foot, field by
/// field and to the last bit.
void compareWithScan(const std::vector<GaitCycle>& cycles, const std::vector<FootSwing>& otherSwings)
{
    std::vector<CycleDoubleSupport> scanned;
    std::size_t unpaired = 0;
    for (const GaitCycle& cycle : cycles) {
        if (!cycle.counted)
            continue;
        if (const std::optional<CycleDoubleSupport> support = doubleSupportIn(cycle, otherSwings))
            scanned.push_back(*support);
        else
            ++unpaired;
    }
    std::vector<CycleDoubleSupport> summarised;
    const DoubleSupportSummary summary = summariseDoubleSupport(cycles, otherSwings, &summarised);
    QCOMPARE(summary.unpairedCycles, unpaired);
    QCOMPARE(summarised.size(), scanned.size());
    for (std::size_t i = 0; i < scanned.size(); ++i) {
        QCOMPARE(summarised[i].heelStrike_s, scanned[i].heelStrike_s);
        QCOMPARE(summarised[i].initial_s, scanned[i].initial_s);
        QCOMPARE(summarised[i].terminal_s, scanned[i].terminal_s);
        QCOMPARE(summarised[i].pct, scanned[i].pct);
    }
}

}  // namespace

class TestBilateralGait : public QObject {
    Q_OBJECT
private slots:
    void symmetricWalk();
    void asymmetricWalkByHand();
    void runningHasNoDoubleSupport();
    void missedSwingLeavesTheCycleOut();
    void turningStridesAreNotCounted();
    void manyStridesAgreeWithAScanOfEverySwing();
    void clocksThatDifferAreReported();
    void symmetryIndex();
    void footSidesFromNames_data();
    void footSidesFromNames();
    void pairingTwoFiles();
    void pairInFolder();
    void otherPathIsTurnedOntoThisOne();
    void ipolTrials_data();
    void ipolTrials();
};

void TestBilateralGait::symmetricWalk()
{
    // Both feet 62 % stance, the right half a cycle after the left: 12 % double support after
    // each heel strike and 12 % before each toe off, 24 % of the cycle.
    const Result left = resultOf({0.0, 1.1, 0.62, 10}, 1.4);
    const Result right = resultOf({0.55, 1.1, 0.62, 10}, 1.4);
    const BilateralGait walk = analyseBilateralGait(left, right);
    QVERIFY(walk.warnings.empty());
    QCOMPARE(walk.leftCycles.cycles, std::size_t(10));
    QCOMPARE(walk.rightCycles.cycles, std::size_t(10));
    QCOMPARE(walk.doubleSupport.unpairedCycles, std::size_t(0));
    QVERIFY(std::abs(walk.doubleSupport.meanPct - 24.0) < 1e-9);
    QVERIFY(std::abs(walk.doubleSupport.initialPct - 12.0) < 1e-9);
    QVERIFY(std::abs(walk.doubleSupport.terminalPct - 12.0) < 1e-9);
    QCOMPARE(walk.perCycle.size(), std::size_t(20));
    QVERIFY(std::is_sorted(walk.perCycle.begin(), walk.perCycle.end(),
                           [](const CycleDoubleSupport& a, const CycleDoubleSupport& b) { return a.heelStrike_s < b.heelStrike_s; }));
    QCOMPARE(walk.symmetry.strideTimePct, 0.0);
    QCOMPARE(walk.symmetry.stancePct, 0.0);
}

void TestBilateralGait::asymmetricWalkByHand()
{
    // Cycle T = 1 s. Left: heel strike 0, toe off 0.64. Right: heel strike 0.5, toe off 1.1
    // (stance 60 %), so its swing runs 0.1-0.5 in each left cycle. Left cycle: both down 0-0.1
    // (initial) and 0.5-0.64 (terminal) = 24 %. Right cycle 0.5-1.5: both down 0.5-0.64 and
    // 1.0-1.1 = 24 % too: double support is a share of the time, whichever foot's cycle counts.
    const Result left = resultOf({0.0, 1.0, 0.64, 8}, 1.5);
    const Result right = resultOf({-0.5, 1.0, 0.60, 9}, 1.3);
    const BilateralGait walk = analyseBilateralGait(left, right);
    QVERIFY(std::abs(walk.leftCycles.meanPct - 24.0) < 1e-9);
    QVERIFY(std::abs(walk.leftCycles.initialPct - 10.0) < 1e-9);
    QVERIFY(std::abs(walk.leftCycles.terminalPct - 14.0) < 1e-9);
    QVERIFY(std::abs(walk.rightCycles.initialPct - 14.0) < 1e-9);
    QVERIFY(std::abs(walk.rightCycles.terminalPct - 10.0) < 1e-9);
    QVERIFY(std::abs(walk.doubleSupport.meanPct - 24.0) < 1e-9);
    // Symmetry indices: 200 (L - R) / (L + R).
    QVERIFY(std::abs(walk.symmetry.strideLengthPct - 200.0 * 0.2 / 2.8) < 1e-9);
    QVERIFY(std::abs(walk.symmetry.stancePct - 200.0 * 4.0 / 124.0) < 1e-9);
    QVERIFY(std::abs(walk.symmetry.swingPct - 200.0 * -4.0 / 76.0) < 1e-9);
    QCOMPARE(walk.symmetry.strideTimePct, 0.0);
}

void TestBilateralGait::runningHasNoDoubleSupport()
{
    // 35 % stance: the feet are never down together (a flight phase instead).
    const BilateralGait walk = analyseBilateralGait(resultOf({0.0, 0.7, 0.35, 10}, 2.5), resultOf({0.35, 0.7, 0.35, 10}, 2.5));
    QCOMPARE(walk.doubleSupport.cycles, std::size_t(19));  // the right's last cycle holds no left toe off
    QCOMPARE(walk.doubleSupport.meanPct, 0.0);
}

void TestBilateralGait::missedSwingLeavesTheCycleOut()
{
    const Result left = resultOf({0.0, 1.1, 0.62, 10}, 1.4);
    Result right = resultOf({0.55, 1.1, 0.62, 10}, 1.4);
    // The right foot's swing after its third heel strike missed: that toe off and the next heel
    // strike vanish (events: toe off, then heel strike k at 2k + 1, toe off k at 2k + 2). The left
    // cycle the swing was in has no right heel strike; the right "stride" across it is two cycles
    // long and holds two left toe offs.
    right.gaitEvents.erase(right.gaitEvents.begin() + 6, right.gaitEvents.begin() + 8);
    GaitStride merged = right.gaitStrides[2];
    merged.toeOff = right.gaitStrides[3].toeOff;
    merged.nextHeelStrike = right.gaitStrides[3].nextHeelStrike;
    right.gaitStrides.erase(right.gaitStrides.begin() + 2, right.gaitStrides.begin() + 4);
    right.gaitStrides.insert(right.gaitStrides.begin() + 2, merged);
    const BilateralGait walk = analyseBilateralGait(left, right);
    QCOMPARE(walk.leftCycles.unpairedCycles, std::size_t(1));
    QCOMPARE(walk.leftCycles.cycles, std::size_t(9));
    QCOMPARE(walk.rightCycles.unpairedCycles, std::size_t(1));
    QCOMPARE(walk.rightCycles.cycles, std::size_t(8));
    QVERIFY(std::abs(walk.doubleSupport.meanPct - 24.0) < 1e-9);  // the rest unharmed
}

void TestBilateralGait::turningStridesAreNotCounted()
{
    Result left = resultOf({0.0, 1.1, 0.62, 10}, 1.4);
    const Result right = resultOf({0.55, 1.1, 0.62, 10}, 1.4);
    left.gaitStrides[4].turning = true;
    left.gaitStrides[5].paused = true;
    const BilateralGait walk = analyseBilateralGait(left, right);
    QCOMPARE(walk.leftCycles.cycles, std::size_t(8));
    QCOMPARE(walk.leftCycles.unpairedCycles, std::size_t(0));
}

void TestBilateralGait::manyStridesAgreeWithAScanOfEverySwing()
{
    // 4000 strides a foot (over an hour of walking): each cycle looks at the few swings of the
    // other foot that meet it, and must find what a scan of all of them finds, with missed,
    // doubled and turning strides among them; swings out of time order take the scan itself.
    std::mt19937 random(7);
    const JitteredFoot left = jitteredFoot(4000, 0.0, random), right = jitteredFoot(4000, 0.55, random);
    compareWithScan(left.cycles, right.swings);
    compareWithScan(right.cycles, left.swings);
    const BilateralGait walk = doubleSupportOfWalk(left.cycles, left.swings, right.cycles, right.swings);
    QVERIFY2(walk.doubleSupport.cycles > 6000 && walk.doubleSupport.unpairedCycles > 100,
             qPrintable(QStringLiteral("%1 paired, %2 unpaired").arg(walk.doubleSupport.cycles).arg(walk.doubleSupport.unpairedCycles)));
    std::vector<FootSwing> shuffled(right.swings.begin(), right.swings.begin() + 300);
    std::shuffle(shuffled.begin(), shuffled.end(), random);
    const std::vector<GaitCycle> someCycles(left.cycles.begin(), left.cycles.begin() + 300);
    compareWithScan(someCycles, shuffled);
}

void TestBilateralGait::clocksThatDifferAreReported()
{
    // The right file's clock starts 300 s later: no stride pairs.
    const BilateralGait walk =
        analyseBilateralGait(resultOf({0.0, 1.1, 0.62, 10}, 1.4), resultOf({300.55, 1.1, 0.62, 10}, 1.4));
    QCOMPARE(walk.doubleSupport.cycles, std::size_t(0));
    QVERIFY(std::isnan(walk.doubleSupport.meanPct));
    QCOMPARE(walk.warnings.size(), std::size_t(2));
    QVERIFY(QString::fromStdString(walk.warnings[0]).contains("share less than half their time"));
    QVERIFY(QString::fromStdString(walk.warnings[1]).contains("one clock"));
}

void TestBilateralGait::symmetryIndex()
{
    QCOMPARE(symmetryIndexPct(1.0, 1.0), 0.0);
    QVERIFY(std::abs(symmetryIndexPct(1.1, 1.0) - 200.0 * 0.1 / 2.1) < 1e-12);
    QVERIFY(std::abs(symmetryIndexPct(1.0, 1.1) + 200.0 * 0.1 / 2.1) < 1e-12);
    QVERIFY(std::isnan(symmetryIndexPct(0.0, 0.0)));
    QVERIFY(std::isnan(symmetryIndexPct(std::nan(""), 1.0)));
    // A foot without straight strides gives no symmetry rather than 200 %.
    Result left = resultOf({0.0, 1.1, 0.62, 3}, 1.4);
    left.gait.straightStrides = 0;
    QVERIFY(std::isnan(analyseBilateralGait(left, resultOf({0.55, 1.1, 0.62, 3}, 1.4)).symmetry.strideLengthPct));
}

void TestBilateralGait::footSidesFromNames_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<int>("side");
    QTest::addColumn<QString>("trial");
    QTest::newRow("ipol left") << "/data/1-4_lf.txt" << int(FootSide::Left) << "1-4";
    QTest::newRow("ipol right") << "1-4_rf.txt" << int(FootSide::Right) << "1-4";
    QTest::newRow("words") << "walk-Left.csv" << int(FootSide::Left) << "walk";
    QTest::newRow("letter") << "park walk_R.csv" << int(FootSide::Right) << "park walk";
    QTest::newRow("no side") << "rectangle_72m.TXT" << int(FootSide::Unknown) << "rectangle_72m";
    QTest::newRow("word ending in r") << "floor.csv" << int(FootSide::Unknown) << "floor";
    QTest::newRow("ending without separator") << "shelf.txt" << int(FootSide::Unknown) << "shelf";
}

void TestBilateralGait::footSidesFromNames()
{
    QFETCH(QString, path);
    QFETCH(int, side);
    QFETCH(QString, trial);
    std::string trialName;
    QCOMPARE(int(footSideOfName(path.toStdString(), &trialName)), side);
    QCOMPARE(QString::fromStdString(trialName), trial);
}

void TestBilateralGait::pairingTwoFiles()
{
    std::string problem;
    const std::optional<FootPair> swapped = pairFeet("a/1-4_rf.txt", "a/1-4_lf.txt", problem);
    QVERIFY(swapped);
    QCOMPARE(swapped->left, std::string("a/1-4_lf.txt"));
    QCOMPARE(swapped->right, std::string("a/1-4_rf.txt"));
    QVERIFY(swapped->notes.empty());

    const std::optional<FootPair> unnamed = pairFeet("one.csv", "two.csv", problem);
    QVERIFY(unnamed);
    QCOMPARE(unnamed->left, std::string("one.csv"));
    QCOMPARE(unnamed->notes.size(), std::size_t(1));

    QVERIFY(!pairFeet("1-4_lf.txt", "10-1_lf.txt", problem));
    QVERIFY2(QString::fromStdString(problem).contains("both named as the left foot"), problem.c_str());
    QVERIFY(!pairFeet("1-4_lf.txt", "10-1_rf.txt", problem));
    QVERIFY2(QString::fromStdString(problem).contains("different walks"), problem.c_str());
}

void TestBilateralGait::pairInFolder()
{
    std::string problem;
    const std::optional<FootPair> pair = footPairInFolder({"d/1-4.json", "d/1-4_rf.txt", "d/1-4_lf.txt", "d/x.md"}, problem);
    QVERIFY(pair);
    QCOMPARE(pair->left, std::string("d/1-4_lf.txt"));
    QCOMPARE(pair->right, std::string("d/1-4_rf.txt"));
    QVERIFY(!footPairInFolder({"1-4_lf.txt", "1-4_rf.txt", "2-1_lf.txt", "2-1_rf.txt"}, problem));
    QVERIFY(QString::fromStdString(problem).contains("2 left/right pairs"));
    QVERIFY(!footPairInFolder({"1-4_lf.txt", "2-1_rf.txt"}, problem));
    QVERIFY(QString::fromStdString(problem).contains("no left/right pair"));
}

void TestBilateralGait::otherPathIsTurnedOntoThisOne()
{
    // The right foot's sensor: its heading 70 degrees off, its start 2 m away, 0.15 m to the side.
    Result left, right;
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(1.2217, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (int k = 0; k <= 1000; ++k) {
        const double t = 0.01 * k;
        const Eigen::Vector3d onLeft(1.3 * t, 0.5 * std::sin(0.3 * t), 0.0);
        left.time_s.push_back(t);
        left.position_m.push_back(onLeft);
        right.time_s.push_back(t + 0.005);  // sampled in between
        right.position_m.push_back(turn * (onLeft + Eigen::Vector3d(0.0, -0.15, 0.0)) + Eigen::Vector3d(2.0, -1.0, 0.3));
    }
    // A constant offset is a shift like any other: the fit takes it away with the sensor's, and the
    // right path lands on the left one (5 ms later along it: 6.5 mm).
    const std::vector<Eigen::Vector3d> aligned = otherFootPathAligned(left, right);
    QCOMPARE(aligned.size(), right.position_m.size());
    for (std::size_t k = 0; k < aligned.size(); k += 50) {
        const Eigen::Vector3d offset = aligned[k] - left.position_m[k];
        QVERIFY2(std::abs(offset.x() - 0.0065) < 0.002 && std::abs(offset.y()) < 0.002 && std::abs(offset.z()) < 1e-9,
                 qPrintable(QStringLiteral("%1: %2 %3").arg(k).arg(offset.x()).arg(offset.y())));
    }
    QVERIFY(otherFootPathAligned(left, Result()).empty());
}

void TestBilateralGait::ipolTrials_data()
{
    // The gap-free trials (the labels' sample indices are rows only there). labelled: the double
    // support of the hand-labelled events over every stride of the trial; difference: the
    // detector's minus the labels' over the strides both have (what the event timing does), as
    // measured when this test was written; the test allows kMargin_pct on it.
    QTest::addColumn<QString>("trial");
    QTest::addColumn<double>("labelled_pct");
    QTest::addColumn<double>("difference_pct");
    QTest::newRow("1-4") << "1-4" << 20.73 << 1.90;
    QTest::newRow("10-1") << "10-1" << 26.52 << -2.13;
    QTest::newRow("14-1") << "14-1" << 26.84 << 0.58;
}

void TestBilateralGait::ipolTrials()
{
    FOOTPATH_REQUIRE_DATASETS();
    QFETCH(QString, trial);
    QFETCH(double, labelled_pct);
    QFETCH(double, difference_pct);
    const ImportResult left = importRecording(datasetPath("xsens-mtw-ipol/" + trial + "_lf.txt").toStdString());
    const ImportResult right = importRecording(datasetPath("xsens-mtw-ipol/" + trial + "_rf.txt").toStdString());
    QVERIFY(left.ok() && right.ok());
    const Result leftResult = runPipeline(left.recording, Parameters()).result;
    const Result rightResult = runPipeline(right.recording, Parameters()).result;
    const std::optional<DoubleSupportCheck> check =
        checkDoubleSupportAgainstLabels(left.recording, leftResult, right.recording, rightResult);
    QVERIFY(check);
    const BilateralGait walk = analyseBilateralGait(leftResult, rightResult);
    const QString measured = QStringLiteral("double support %1 % (labels %2 %) over %3 strides (labels %4), %5 unpaired; "
                                            "on the %6 strides both have %7 % (labels %8 %); "
                                            "walk %9 %; symmetry stride time %10 %, length %11 %, stance %12 %")
                                 .arg(check->detected.meanPct, 0, 'f', 2)
                                 .arg(check->labelled.meanPct, 0, 'f', 2)
                                 .arg(check->detected.cycles)
                                 .arg(check->labelled.cycles)
                                 .arg(check->detected.unpairedCycles)
                                 .arg(check->matchedStrides)
                                 .arg(check->matchedDetectedPct, 0, 'f', 2)
                                 .arg(check->matchedLabelledPct, 0, 'f', 2)
                                 .arg(walk.doubleSupport.meanPct, 0, 'f', 2)
                                 .arg(walk.symmetry.strideTimePct, 0, 'f', 2)
                                 .arg(walk.symmetry.strideLengthPct, 0, 'f', 2)
                                 .arg(walk.symmetry.stancePct, 0, 'f', 2);
    qInfo("%s: %s", qPrintable(trial), qPrintable(measured));
    QVERIFY2(walk.warnings.empty(), walk.warnings.empty() ? "" : walk.warnings.front().c_str());
    QVERIFY2(std::abs(check->labelled.meanPct - labelled_pct) < 0.01, qPrintable(measured));  // the labels' own figure
    const double difference = check->matchedDetectedPct - check->matchedLabelledPct;
    const double kMargin_pct = 1.0;
    QVERIFY2(std::abs(difference - difference_pct) < kMargin_pct, qPrintable(measured));
    // Whatever the recorded figures: within 2.5 points of the labels on the same strides (event
    // errors of 5-10 ms move it by about 1-2 points), and the strides nearly all found and paired.
    QVERIFY2(std::abs(difference) < 2.5, qPrintable(measured));
    QVERIFY2(check->matchedStrides + 4 >= check->labelled.cycles, qPrintable(measured));
    // Over all strides: the labelled strides the detector did not pair (in the U-turn) have long
    // double support, which moves the labels' mean more.
    QVERIFY2(std::abs(check->detected.meanPct - check->labelled.meanPct) < 4.0, qPrintable(measured));
    // Healthy walkers: both feet alike within a few percent.
    QVERIFY2(std::abs(walk.symmetry.strideTimePct) < 5.0 && std::abs(walk.symmetry.stancePct) < 5.0, qPrintable(measured));
}

QTEST_GUILESS_MAIN(TestBilateralGait)
#include "tst_bilateralgait.moc"
