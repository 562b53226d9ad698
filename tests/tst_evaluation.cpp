// Hand-computed cases for the accuracy metrics of docs/accuracy.md (ARMSE, loop closure, distance error). Every expected value
// is worked out in the comment beside it, not produced by the code under test.

#include "metrics/Evaluation.h"

#include <QMetaType>
#include <QtTest>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using footpath::ArmseResult;
using footpath::Step;

using Trajectory = std::vector<Eigen::Vector3d>;
Q_DECLARE_METATYPE(Trajectory)

namespace {

constexpr double kTolerance = 1e-12;
constexpr double kPi = 3.14159265358979323846;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

double degrees(double deg) { return deg * kPi / 180.0; }

/// count samples from start, one `step` apart (computed per sample so no rounding accumulates).
Trajectory straightLine(const Eigen::Vector3d& start, const Eigen::Vector3d& step, int count)
{
    Trajectory line;
    for (int k = 0; k < count; ++k)
        line.push_back(start + static_cast<double>(k) * step);
    return line;
}

/// 6 samples along +x (0.25 m apart), then 6 along +y, climbing 0.02 m per sample so that a rotation
/// which disturbed z would show up in the 3D error.
Trajectory lShapedClimb()
{
    Trajectory path;
    for (int k = 0; k < 12; ++k) {
        const double along = 0.25 * std::min(k, 5);
        const double across = 0.25 * std::max(k - 5, 0);
        path.emplace_back(along, across, 0.02 * k);
    }
    return path;
}

Trajectory rotatedAboutZ(const Trajectory& path, double angle_rad)
{
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    Trajectory rotated;
    for (const Eigen::Vector3d& p : path)
        rotated.push_back(rotation * p);
    return rotated;
}

Trajectory translated(Trajectory path, const Eigen::Vector3d& offset)
{
    for (Eigen::Vector3d& p : path)
        p += offset;
    return path;
}

std::vector<Step> stepsAt(const Trajectory& positions)
{
    std::vector<Step> steps(positions.size());
    for (std::size_t k = 0; k < positions.size(); ++k)
        steps[k].position_m = positions[k];
    return steps;
}

/// Difference of two angles folded into [-pi, pi], so +pi and -pi count as the same rotation.
double angleBetween(double a_rad, double b_rad) { return std::abs(std::remainder(a_rad - b_rad, 2.0 * kPi)); }

}  // namespace

class TestEvaluation : public QObject {
    Q_OBJECT

private slots:
    void armse_data();
    void armse();
    void armseOfUnusableInputIsNan_data();
    void armseOfUnusableInputIsNan();
    void loopClosure_data();
    void loopClosure();
    void loopClosureWithoutPositionsIsNan();
    void loopClosureOfSinglePositionIsZero();
    void stancePathLength_data();
    void stancePathLength();
    void distanceError_data();
    void distanceError();
    void stanceScore_data();
    void stanceScore();
};

void TestEvaluation::armse_data()
{
    QTest::addColumn<Trajectory>("estimate");
    QTest::addColumn<Trajectory>("reference");
    QTest::addColumn<double>("expected2d");
    QTest::addColumn<double>("expected3d");
    QTest::addColumn<qsizetype>("expectedAlignmentIndex");
    QTest::addColumn<double>("expectedRotation");

    // 0.25 m per sample: sample 3 is 0.75 m out, sample 4 is 1.0 m, the first to reach 0.8 m.
    const Eigen::Vector3d alongX(0.25, 0.0, 0.0);
    const Trajectory line = straightLine(Eigen::Vector3d::Zero(), alongX, 10);

    QTest::newRow("identical, different start points")
        << translated(line, {5.0, -3.0, 1.0}) << translated(line, {-2.0, 4.0, 0.5}) << 0.0 << 0.0
        << qsizetype(4) << 0.0;

    // "Reaches" includes equality: 4 x 0.2 m is exactly 0.8 in binary floating point.
    const Trajectory fifthsAlongX = straightLine(Eigen::Vector3d::Zero(), {0.2, 0.0, 0.0}, 8);
    QTest::newRow("exactly 0.8 m at sample 4")
        << fifthsAlongX << fifthsAlongX << 0.0 << 0.0 << qsizetype(4) << 0.0;

    // The estimate is the reference turned by +angle, so undoing it takes -angle and leaves no error.
    for (const double angleDeg : {30.0, -100.0, 180.0}) {
        const Trajectory estimate =
            translated(rotatedAboutZ(lShapedClimb(), degrees(angleDeg)), {1.0, 2.0, 3.0});
        QTest::addRow("rotated by %g deg", angleDeg)
            << estimate << lShapedClimb() << 0.0 << 0.0 << qsizetype(4) << degrees(-angleDeg);
    }

    // Samples 5..9 are 0.1 m off sideways; samples 0..4 (alignment included) match, so no rotation.
    // Those 5 samples have e = sqrt(0.1^2 / 2) in 2D and sqrt(0.1^2 / 3) in 3D, the other 5 have 0.
    Trajectory lateralOffset = line;
    for (std::size_t k = 5; k < lateralOffset.size(); ++k)
        lateralOffset[k].y() += 0.1;
    QTest::newRow("0.1 m lateral offset after alignment")
        << lateralOffset << line << 5.0 * (0.1 / std::sqrt(2.0)) / 10.0
        << 5.0 * (0.1 / std::sqrt(3.0)) / 10.0 << qsizetype(4) << 0.0;

    // 1 mm per sample never reaches 0.8 m in 400 samples, so sample 300 aligns +x onto +y.
    const Eigen::Vector3d creepX(0.001, 0.0, 0.0);
    const Eigen::Vector3d creepY(0.0, 0.001, 0.0);
    QTest::newRow("never 0.8 m: sample 300")
        << straightLine(Eigen::Vector3d::Zero(), creepX, 400)
        << straightLine(Eigen::Vector3d::Zero(), creepY, 400) << 0.0 << 0.0 << qsizetype(300)
        << kPi / 2.0;
    QTest::newRow("never 0.8 m, shorter than 300: last sample")
        << straightLine(Eigen::Vector3d::Zero(), creepX, 50)
        << straightLine(Eigen::Vector3d::Zero(), creepY, 50) << 0.0 << 0.0 << qsizetype(49)
        << kPi / 2.0;

    // Only z differs: 2D error is 0 and each 3D e_k is |dz| / sqrt(3); the |dz| sum to 2.1 over 8.
    Trajectory heightErrors = straightLine(Eigen::Vector3d::Zero(), alongX, 8);
    const double dz[] = {0.0, 0.3, -0.6, 0.3, 0.0, 0.9, 0.0, 0.0};
    for (std::size_t k = 0; k < heightErrors.size(); ++k)
        heightErrors[k].z() += dz[k];
    QTest::newRow("only z differs")
        << heightErrors << straightLine(Eigen::Vector3d::Zero(), alongX, 8) << 0.0
        << 2.1 / 8.0 / std::sqrt(3.0) << qsizetype(4) << 0.0;

    QTest::newRow("single sample") << Trajectory{{1.0, 2.0, 3.0}} << Trajectory{{4.0, 5.0, 6.0}}
                                   << 0.0 << 0.0 << qsizetype(0) << 0.0;

    // Reference at rest: no direction at sample 4, so no rotation. |difference| is 0.25 k for
    // k = 0..4, mean 0.5, i.e. 0.5 / sqrt(2) in 2D and 0.5 / sqrt(3) in 3D.
    const Trajectory fiveAlongX = straightLine(Eigen::Vector3d::Zero(), alongX, 5);
    const Trajectory atRest(5, Eigen::Vector3d(7.0, 7.0, 7.0));
    QTest::newRow("reference at rest: no rotation")
        << fiveAlongX << atRest << 0.5 / std::sqrt(2.0) << 0.5 / std::sqrt(3.0) << qsizetype(4)
        << 0.0;
    // Estimate at rest: falls back to the last sample, which has no direction either.
    QTest::newRow("estimate at rest: no rotation")
        << atRest << fiveAlongX << 0.5 / std::sqrt(2.0) << 0.5 / std::sqrt(3.0) << qsizetype(4)
        << 0.0;
}

void TestEvaluation::armse()
{
    QFETCH(Trajectory, estimate);
    QFETCH(Trajectory, reference);
    QFETCH(double, expected2d);
    QFETCH(double, expected3d);
    QFETCH(qsizetype, expectedAlignmentIndex);
    QFETCH(double, expectedRotation);

    const ArmseResult result = footpath::computeArmse(estimate, reference);

    QCOMPARE(static_cast<qsizetype>(result.alignmentIndex), expectedAlignmentIndex);
    QCOMPARE_LE(angleBetween(result.rotation_rad, expectedRotation), kTolerance);
    QCOMPARE_LE(std::abs(result.armse2d_m - expected2d), kTolerance);
    QCOMPARE_LE(std::abs(result.armse3d_m - expected3d), kTolerance);
}

void TestEvaluation::armseOfUnusableInputIsNan_data()
{
    QTest::addColumn<Trajectory>("estimate");
    QTest::addColumn<Trajectory>("reference");

    const Trajectory two{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
    QTest::newRow("both empty") << Trajectory{} << Trajectory{};
    QTest::newRow("estimate longer") << two << Trajectory{{0.0, 0.0, 0.0}};
    QTest::newRow("reference empty") << two << Trajectory{};
}

void TestEvaluation::armseOfUnusableInputIsNan()
{
    QFETCH(Trajectory, estimate);
    QFETCH(Trajectory, reference);

    const ArmseResult result = footpath::computeArmse(estimate, reference);

    QVERIFY(std::isnan(result.armse2d_m));
    QVERIFY(std::isnan(result.armse3d_m));
    QVERIFY(std::isnan(result.rotation_rad));
}

void TestEvaluation::loopClosure_data()
{
    QTest::addColumn<double>("pathLength");
    QTest::addColumn<double>("referenceLength");
    QTest::addColumn<double>("expectedLengthUsed");
    QTest::addColumn<double>("expectedPct");

    // The square below misses its start by a 3-4-5 triangle: DBSE 0.5 m.
    QTest::newRow("estimated length") << 16.0 << 0.0 << 16.0 << 0.5 / 16.0 * 100.0;
    QTest::newRow("reference length wins") << 16.0 << 20.0 << 20.0 << 2.5;
    QTest::newRow("negative reference ignored") << 16.0 << -1.0 << 16.0 << 0.5 / 16.0 * 100.0;
    QTest::newRow("no length: 0 %") << 0.0 << 0.0 << 0.0 << 0.0;
}

void TestEvaluation::loopClosure()
{
    QFETCH(double, pathLength);
    QFETCH(double, referenceLength);
    QFETCH(double, expectedLengthUsed);
    QFETCH(double, expectedPct);

    // A 4 m square walked back to (0.3, -0.4): 0.5 m horizontally. The 0.5 m of z would make the
    // 3D distance sqrt(0.5) = 0.707 m, so a non-horizontal DBSE fails.
    const Trajectory square{{0.0, 0.0, 0.0}, {4.0, 0.0, 0.2}, {4.0, 4.0, 0.4}, {0.0, 4.0, 0.2},
                            {0.3, -0.4, 0.5}};

    const footpath::LoopClosure closure =
        footpath::computeLoopClosure(square, pathLength, referenceLength);

    QCOMPARE_LE(std::abs(closure.dbse_m - 0.5), kTolerance);
    QCOMPARE(closure.lengthUsed_m, expectedLengthUsed);
    QCOMPARE_LE(std::abs(closure.dbsePct - expectedPct), kTolerance);
}

void TestEvaluation::loopClosureWithoutPositionsIsNan()
{
    const footpath::LoopClosure closure = footpath::computeLoopClosure({}, 10.0);

    QVERIFY(std::isnan(closure.dbse_m));
    QVERIFY(std::isnan(closure.dbsePct));
}

void TestEvaluation::loopClosureOfSinglePositionIsZero()
{
    const footpath::LoopClosure closure = footpath::computeLoopClosure({{1.0, 2.0, 3.0}}, 10.0);

    QCOMPARE(closure.dbse_m, 0.0);
    QCOMPARE(closure.dbsePct, 0.0);
}

void TestEvaluation::stancePathLength_data()
{
    QTest::addColumn<Trajectory>("stancePositions");
    QTest::addColumn<double>("expectedLength");

    QTest::newRow("no steps") << Trajectory{} << 0.0;
    QTest::newRow("one stance") << Trajectory{{1.0, 2.0, 3.0}} << 0.0;
    // One 3-4-5 stride up a 0.2 m stair: 0.5 m horizontally (3D would be 0.539 m).
    QTest::newRow("stair stride") << Trajectory{{0.0, 0.0, 0.0}, {0.3, 0.4, 0.2}} << 0.5;
    // A 4 m x 3 m rectangle with height changes: 4 + 3 + 4 + 3.
    QTest::newRow("rectangle")
        << Trajectory{{0.0, 0.0, 0.0}, {4.0, 0.0, 0.3}, {4.0, 3.0, 0.6}, {0.0, 3.0, 0.3},
                      {0.0, 0.0, 0.0}}
        << 14.0;
}

void TestEvaluation::stancePathLength()
{
    QFETCH(Trajectory, stancePositions);
    QFETCH(double, expectedLength);

    const double length = footpath::stancePathLength(stepsAt(stancePositions));

    QCOMPARE_LE(std::abs(length - expectedLength), kTolerance);
}

void TestEvaluation::distanceError_data()
{
    QTest::addColumn<double>("estimated");
    QTest::addColumn<double>("reference");
    QTest::addColumn<double>("expectedError");
    QTest::addColumn<double>("expectedPct");  // NaN: the percentage must be NaN

    QTest::newRow("too long") << 102.0 << 100.0 << 2.0 << 2.0;
    QTest::newRow("too short") << 95.0 << 100.0 << 5.0 << 5.0;
    QTest::newRow("exact") << 40.0 << 40.0 << 0.0 << 0.0;
    QTest::newRow("no reference") << 3.0 << 0.0 << 3.0 << kNaN;
    QTest::newRow("negative reference") << 3.0 << -1.0 << 4.0 << kNaN;
}

void TestEvaluation::distanceError()
{
    QFETCH(double, estimated);
    QFETCH(double, reference);
    QFETCH(double, expectedError);
    QFETCH(double, expectedPct);

    const footpath::DistanceError error = footpath::computeDistanceError(estimated, reference);

    QCOMPARE(error.estimated_m, estimated);
    QCOMPARE(error.reference_m, reference);
    QCOMPARE_LE(std::abs(error.error_m - expectedError), kTolerance);
    if (std::isnan(expectedPct))
        QVERIFY(std::isnan(error.errorPct));
    else
        QCOMPARE_LE(std::abs(error.errorPct - expectedPct), kTolerance);
}

namespace {

std::vector<std::uint8_t> flagsOf(const QString& pattern)
{
    std::vector<std::uint8_t> flags;
    for (QChar ch : pattern)
        flags.push_back(ch == '1');
    return flags;
}

}  // namespace

void TestEvaluation::stanceScore_data()
{
    QTest::addColumn<QString>("detected");
    QTest::addColumn<double>("precision");
    QTest::addColumn<double>("recall");
    QTest::addColumn<long>("phaseError");
    // Swings at samples 2-4 and 9-11: the window is 2..11, reference stance 5..8 (4 samples, one phase).
    //                       index: 0123456789012
    QTest::newRow("perfect") << "1100011110001" << 1.0 << 1.0 << 0L;
    QTest::newRow("one stance sample missed") << "1100001110001" << 1.0 << 0.75 << 0L;
    QTest::newRow("stance leaks into a swing") << "1100111110001" << 0.8 << 1.0 << 0L;
    QTest::newRow("split stance counts two phases") << "1100010110001" << 1.0 << 0.75 << 1L;
    QTest::newRow("nothing detected") << "0000000000000" << 0.0 << 0.0 << -1L;
}

void TestEvaluation::stanceScore()
{
    QFETCH(QString, detected);
    QFETCH(double, precision);
    QFETCH(double, recall);
    QFETCH(long, phaseError);
    const std::vector<footpath::SampleRange> swings{{2, 4}, {9, 11}};
    const footpath::StanceScore score = footpath::scoreStanceDetection(flagsOf(detected), swings);
    QCOMPARE(score.samplesCompared, std::size_t(10));
    QCOMPARE(score.referencePhases, std::size_t(1));
    QCOMPARE_LE(std::abs(score.precision - precision), 1e-12);
    QCOMPARE_LE(std::abs(score.recall - recall), 1e-12);
    const double f1 = precision + recall > 0 ? 2 * precision * recall / (precision + recall) : 0.0;
    QCOMPARE_LE(std::abs(score.f1 - f1), 1e-12);
    QCOMPARE(score.stepCountError, phaseError);

    // Trial boundaries clip the window: only 5..8 remains, all reference stance.
    const footpath::SampleRange trial{5, 8};
    const footpath::StanceScore clipped = footpath::scoreStanceDetection(flagsOf(detected), swings, &trial);
    QCOMPARE(clipped.samplesCompared, std::size_t(4));
}

QTEST_APPLESS_MAIN(TestEvaluation)
#include "tst_evaluation.moc"
