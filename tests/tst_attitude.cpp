#include "nav/Alignment.h"
#include "nav/Attitude.h"

#include <Eigen/Geometry>
#include <QtTest>

using namespace footpath;

namespace {

Eigen::Matrix3d exactRotation(const Eigen::Vector3d& theta)
{
    const double angle = theta.norm();
    return angle == 0.0 ? Eigen::Matrix3d::Identity()
                        : Eigen::AngleAxisd(angle, theta / angle).toRotationMatrix();
}

std::vector<ImuSample> staticSamples(const Eigen::Matrix3d& bodyToNav, double seconds, double rate_hz,
                                     bool withMag)
{
    std::vector<ImuSample> samples;
    const Eigen::Vector3d earthField(0.2, 0.0, -0.45);  // horizontal part along +x: magnetic north
    for (int k = 0; k < static_cast<int>(seconds * rate_hz); ++k) {
        ImuSample s;
        s.time_s = k / rate_hz;
        s.acc_mps2 = bodyToNav.transpose() * Eigen::Vector3d(0, 0, 9.81);
        if (withMag)
            s.mag = bodyToNav.transpose() * earthField;
        samples.push_back(s);
    }
    return samples;
}

}  // namespace

class TestAttitude : public QObject {
    Q_OBJECT
private slots:
    void skewIsTheCrossProduct()
    {
        const Eigen::Vector3d a(0.3, -1.2, 2.0), b(-0.7, 0.4, 1.1);
        QVERIFY((skew(a) * b - a.cross(b)).norm() < 1e-15);
        QVERIFY((skew(a) + skew(a).transpose()).norm() == 0.0);
    }

    void padeMatchesExactRotationToThirdOrder_data()
    {
        QTest::addColumn<double>("angle");
        QTest::newRow("0.001 rad") << 0.001;
        QTest::newRow("0.01 rad (1 rad/s at 100 Hz)") << 0.01;
        QTest::newRow("0.1 rad (10 rad/s at 100 Hz)") << 0.1;
    }
    void padeMatchesExactRotationToThirdOrder()
    {
        QFETCH(double, angle);
        const Eigen::Vector3d theta = angle * Eigen::Vector3d(1, -2, 0.5).normalized();
        const Eigen::Matrix3d pade = padeRotation(theta);
        // Cayley's angle is 2 atan(|theta|/2) = |theta| - |theta|^3/12 + ...: the only error.
        const double bound = std::pow(angle, 3) / 12.0 * 1.01 + 1e-15;
        QVERIFY2((pade - exactRotation(theta)).norm() <= bound * std::sqrt(2.0),
                 qPrintable(QString::number((pade - exactRotation(theta)).norm())));
        QVERIFY((pade * pade.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-14);
        QVERIFY(std::abs(pade.determinant() - 1.0) < 1e-14);
    }

    void padeEqualsPrintedEquationEight()
    {
        // (2I + S)(2I - S)^-1 with the proper skew matrix, computed the slow way.
        const Eigen::Vector3d theta(0.2, -0.1, 0.3);
        const Eigen::Matrix3d two = 2.0 * Eigen::Matrix3d::Identity();
        const Eigen::Matrix3d printed = (two + skew(theta)) * (two - skew(theta)).inverse();
        QVERIFY((padeRotation(theta) - printed).norm() < 1e-14);
    }

    void rollPitchYawRoundTrip_data()
    {
        QTest::addColumn<double>("roll");
        QTest::addColumn<double>("pitch");
        QTest::addColumn<double>("yaw");
        QTest::newRow("level") << 0.0 << 0.0 << 0.0;
        QTest::newRow("mixed") << 0.3 << -0.4 << 2.0;
        QTest::newRow("upside down (pyshoe z down)") << 3.0 << 0.2 << -1.0;
    }
    void rollPitchYawRoundTrip()
    {
        QFETCH(double, roll);
        QFETCH(double, pitch);
        QFETCH(double, yaw);
        const Eigen::Vector3d rpy = rollPitchYaw(rotationFromRollPitchYaw(roll, pitch, yaw));
        QVERIFY(std::abs(rpy.x() - roll) < 1e-12);
        QVERIFY(std::abs(rpy.y() - pitch) < 1e-12);
        QVERIFY(std::abs(rpy.z() - yaw) < 1e-12);
    }

    void alignmentRecoversRollPitchAndMagneticHeading()
    {
        const Eigen::Matrix3d truth = rotationFromRollPitchYaw(0.2, -0.3, 1.1);
        const std::vector<ImuSample> samples = staticSamples(truth, 2.0, 100.0, true);
        Parameters params;
        const AlignmentResult aligned = alignInitialAttitude(samples, std::vector<std::uint8_t>(samples.size(), 1), params);
        QVERIFY(std::abs(aligned.roll_rad - 0.2) < 1e-12);
        QVERIFY(std::abs(aligned.pitch_rad + 0.3) < 1e-12);
        QVERIFY(std::abs(aligned.yaw_rad - 1.1) < 1e-12);
        QVERIFY(aligned.headingFromMagnetometer);
        QVERIFY((aligned.bodyToNav - truth).norm() < 1e-12);
    }

    void declinationIsSubtractedFromTheCompassHeading()
    {
        const Eigen::Matrix3d truth = rotationFromRollPitchYaw(0.0, 0.0, 0.5);
        const std::vector<ImuSample> samples = staticSamples(truth, 1.0, 100.0, true);
        Parameters params;
        params.declination_rad = 0.1;
        const AlignmentResult aligned = alignInitialAttitude(samples, {}, params);
        QVERIFY(std::abs(aligned.yaw_rad - 0.4) < 1e-12);
    }

    void headingIsZeroWithoutMagnetometer()
    {
        const std::vector<ImuSample> samples = staticSamples(rotationFromRollPitchYaw(0.1, 0.1, 0.8), 1.0, 100.0, false);
        const AlignmentResult aligned = alignInitialAttitude(samples, {}, Parameters());
        QCOMPARE(aligned.yaw_rad, 0.0);
        QVERIFY(!aligned.headingFromMagnetometer);
        QVERIFY(std::abs(aligned.roll_rad - 0.1) < 1e-12);
    }

    void alignmentUsesOnlyStanceSamplesOfThePeriod()
    {
        // The foot starts to move at 0.5 s, inside the 1 s alignment period: those samples must
        // not tilt the start.
        std::vector<ImuSample> samples = staticSamples(Eigen::Matrix3d::Identity(), 1.0, 100.0, false);
        std::vector<std::uint8_t> stance(samples.size(), 1);
        for (std::size_t k = 50; k < samples.size(); ++k) {
            samples[k].acc_mps2 = Eigen::Vector3d(5.0, 0.0, 9.81);
            stance[k] = 0;
        }
        const AlignmentResult aligned = alignInitialAttitude(samples, stance, Parameters());
        QCOMPARE(aligned.samplesUsed, std::size_t(50));
        QVERIFY(std::abs(aligned.pitch_rad) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestAttitude)
#include "tst_attitude.moc"
