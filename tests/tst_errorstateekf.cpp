#include "DenseReferenceFilter.h"
#include "nav/Attitude.h"
#include "nav/ChiSquare.h"
#include "nav/ErrorStateEkf.h"
#include "nav/Strapdown.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <QtTest>

using namespace footpath;
using Vector15 = ErrorStateEkf::Vector15;
using Matrix15 = ErrorStateEkf::Matrix15;

namespace {

constexpr int kAtt = ErrorStateEkf::kAtt, kGyroBias = ErrorStateEkf::kGyroBias, kPos = ErrorStateEkf::kPos,
              kVel = ErrorStateEkf::kVel, kAccBias = ErrorStateEkf::kAccBias;

Eigen::Matrix3d rotationOf(const Eigen::Vector3d& phi)
{
    return phi.norm() == 0.0 ? Eigen::Matrix3d::Identity()
                             : Eigen::AngleAxisd(phi.norm(), phi.normalized()).toRotationMatrix();
}

Eigen::Vector3d rotationVector(const Eigen::Matrix3d& rotation)
{
    const Eigen::AngleAxisd angleAxis(rotation);
    return angleAxis.angle() * angleAxis.axis();
}

/// Guo 2015's parameters with a filter of 9 or 15 states.
Parameters guo2015WithStates(int states)
{
    Parameters params = guo2015Parameters();
    params.filter_states = static_cast<int>(states == 9 ? FilterStates::Nine : FilterStates::Fifteen);
    return params;
}

NavState sampleTruth()
{
    NavState truth;
    truth.bodyToNav = rotationFromRollPitchYaw(0.3, -0.2, 1.0);
    truth.position_m = {1.0, 2.0, 3.0};
    truth.velocity_mps = {0.5, -0.3, 0.2};
    truth.gyroBias_radps = {0.01, 0.02, -0.01};
    truth.accBias_mps2 = {0.1, -0.05, 0.2};
    return truth;
}

/// The estimate that differs from truth by dx, with the filter's error definitions.
NavState perturb(const NavState& truth, const Vector15& dx)
{
    NavState estimate = truth;
    estimate.bodyToNav = rotationOf(dx.segment<3>(kAtt)) * truth.bodyToNav;
    estimate.gyroBias_radps -= dx.segment<3>(kGyroBias);
    estimate.position_m += dx.segment<3>(kPos);
    estimate.velocity_mps += dx.segment<3>(kVel);
    estimate.accBias_mps2 -= dx.segment<3>(kAccBias);
    return estimate;
}

Vector15 errorBetween(const NavState& estimate, const NavState& truth)
{
    Vector15 dx;
    dx << rotationVector(estimate.bodyToNav * truth.bodyToNav.transpose()),
        truth.gyroBias_radps - estimate.gyroBias_radps, estimate.position_m - truth.position_m,
        estimate.velocity_mps - truth.velocity_mps, truth.accBias_mps2 - estimate.accBias_mps2;
    return dx;
}

Parameters zeroInitialUncertainty()
{
    Parameters params = guo2015Parameters();
    params.p0_gyro_bias_radps = 0.0;
    params.p0_acc_bias_mps2 = 0.0;
    return params;
}

}  // namespace

class TestErrorStateEkf : public QObject {
    Q_OBJECT
private slots:
    void transitionMatrixMatchesFiniteDifferencesOfTheMechanization_data()
    {
        QTest::addColumn<int>("state");
        for (int i = 0; i < ErrorStateEkf::kStates; ++i)
            QTest::newRow(qPrintable(QString("error state %1").arg(i))) << i;
    }
    void transitionMatrixMatchesFiniteDifferencesOfTheMechanization()
    {
        QFETCH(int, state);
        const double dt = 1e-4, delta = 1e-7;
        const Eigen::Vector3d acc(1.0, 2.0, 9.5), gyr(0.5, -1.0, 2.0);
        Vector15 dx = Vector15::Zero();
        dx(state) = delta;

        NavState truth = sampleTruth();
        NavState estimate = perturb(truth, dx);
        strapdownStep(truth, acc, gyr, dt, 9.81);
        const Eigen::Vector3d navForce = strapdownStep(estimate, acc, gyr, dt, 9.81);
        const Vector15 propagated = errorBetween(estimate, truth);

        const ErrorStateEkf ekf(guo2015Parameters(), estimate.bodyToNav);
        const Matrix15 phi = ekf.transitionMatrix(navForce, dt);
        const Vector15 predicted = phi * dx;
        // The first-order part (Phi - I) dx must match to a few per mille; the rest is O(dt^2) and
        // O(delta^2). A sign error in any block makes the mismatch as large as the block itself.
        const double firstOrder = (predicted - dx).norm();
        const double mismatch = (propagated - predicted).norm();
        QVERIFY2(mismatch <= 2e-2 * firstOrder + 1e-15,
                 qPrintable(QString("mismatch %1 vs first-order %2").arg(mismatch).arg(firstOrder)));
    }

    void structuredPropagationEqualsDenseProduct_data()
    {
        QTest::addColumn<int>("states");
        QTest::newRow("15 states") << 15;
        QTest::newRow("9 states") << 9;
    }

    void structuredPropagationEqualsDenseProduct()
    {
        QFETCH(int, states);
        Parameters params = guo2015WithStates(states);
        params.q_gyro_bias_radps = 1e-5;
        params.q_pos_m = 1e-5;
        params.q_acc_bias_mps2 = 1e-5;
        ErrorStateEkf ekf(params, rotationFromRollPitchYaw(0.1, 0.2, 0.3));
        const double dt = 0.005;
        // A few steps and updates make the covariance dense before the comparison.
        for (int k = 0; k < 20; ++k) {
            ekf.propagate(Eigen::Vector3d(1.0, -2.0, 9.0), Eigen::Vector3d(0.3, 0.1, -0.2), dt);
            if (k % 5 == 0)
                ekf.updateZeroVelocityAndRate(Eigen::Vector3d(0.01, 0.0, 0.0));
        }
        const Matrix15 before = ekf.covariance();
        ekf.propagate(Eigen::Vector3d(2.0, 1.0, 8.0), Eigen::Vector3d(-0.5, 0.4, 1.0), dt);
        const Matrix15 phi = ekf.transitionMatrix(ekf.lastNavAcceleration(), dt);
        const double bias = states == 9 ? 0.0 : 1e-10;  // the 9-state filter has no bias noise
        Vector15 q;
        q << Eigen::Vector3d::Constant(1e-8), Eigen::Vector3d::Constant(bias), Eigen::Vector3d::Constant(1e-10),
            Eigen::Vector3d::Constant(1e-8), Eigen::Vector3d::Constant(bias);
        const Matrix15 dense = phi * before * phi.transpose() + Matrix15(q.asDiagonal()) * (dt / 0.01);
        QVERIFY2((ekf.covariance() - dense).norm() < 1e-12 * dense.norm(),
                 qPrintable(QString::number((ekf.covariance() - dense).norm())));
    }

    void updateEqualsTheJosephFormOfEq33_data()
    {
        QTest::addColumn<int>("states");
        QTest::addColumn<bool>("withRate");
        QTest::newRow("9 states, ZUPT") << 9 << false;
        QTest::newRow("15 states, ZUPT") << 15 << false;
        QTest::newRow("15 states, ZUPT and ZARU") << 15 << true;
    }

    void updateEqualsTheJosephFormOfEq33()
    {
        // The filter takes P - W W^T (W = P H^T L^-T, S = L L^T) off the covariance: the Joseph form
        // (I - KH) P (I - KH)^T + K R K^T for the gain it uses, but for rounding. Checked after a
        // second-long swing, when the velocity variance is hundreds of times R and the update
        // cancels most of its digits.
        QFETCH(int, states);
        QFETCH(bool, withRate);
        Parameters params = guo2015WithStates(states);
        params.p0_att_rad = 0.01;
        params.q_vel_mps = 0.02;
        ErrorStateEkf ekf(params, rotationFromRollPitchYaw(0.1, 0.2, 0.3));
        for (int k = 0; k < 100; ++k)
            ekf.propagate(Eigen::Vector3d(1.0, -2.0, 9.0), Eigen::Vector3d(0.3, 0.1, -0.2), 0.01);
        const Matrix15 before = ekf.covariance();
        const double zupt = params.r_zupt_mps * params.r_zupt_mps, zaru = params.r_zaru_radps * params.r_zaru_radps;
        QVERIFY(before(kVel, kVel) > 100.0 * zupt);
        ekf.setRecordUpdates(true);
        if (withRate)
            ekf.updateZeroVelocityAndRate(Eigen::Vector3d(0.01, 0.0, 0.0));
        else
            ekf.updateZeroVelocity();
        const int rows = withRate ? 6 : 3;
        // One record, of an update that selects states (the filter's fast way of recording).
        QCOMPARE(ekf.recordedUpdates().size(), update_record::length(states, rows, true));
        const Eigen::MatrixXd gain = update_record::gainOf(ekf.recordedUpdates().data(), states);
        Eigen::MatrixXd h = Eigen::MatrixXd::Zero(rows, 15);
        Eigen::VectorXd r(rows);
        if (withRate) {
            h.block<3, 3>(0, kGyroBias).setIdentity();
            h.block<3, 3>(3, kVel).setIdentity();
            r << Eigen::Vector3d::Constant(zaru), Eigen::Vector3d::Constant(zupt);
        } else {
            h.block<3, 3>(0, kVel).setIdentity();
            r = Eigen::Vector3d::Constant(zupt);
        }
        const Matrix15 joseph = josephForm(before, gain, h, r);
        const Matrix15& p = ekf.covariance();
        QCOMPARE((p - p.transpose()).norm(), 0.0);
        QVERIFY2((p - joseph).norm() < 1e-12 * before.norm(),
                 qPrintable(QString("%1 of %2").arg((p - joseph).norm()).arg(before.norm())));
        // And the gain is eq. 31's.
        const Eigen::MatrixXd s = h * before * h.transpose() + Eigen::MatrixXd(r.asDiagonal());
        const Eigen::MatrixXd expectedGain = before * h.transpose() * s.inverse();
        QVERIFY((gain - expectedGain).norm() < 1e-12 * expectedGain.norm());
    }

    void aRowOnStatesTheFilterDoesNotRunIsLeftOutOfTheRecord()
    {
        // The 9-state filter has no gyro bias: ZUPT+ZARU's rate rows see none of its states, so
        // its record is the velocity rows alone, which then are the ZUPT's (S is block diagonal).
        const Parameters params = guo2015WithStates(9);
        ErrorStateEkf both(params, rotationFromRollPitchYaw(0.1, 0.2, 0.3));
        for (int k = 0; k < 100; ++k)
            both.propagate(Eigen::Vector3d(1.0, -2.0, 9.0), Eigen::Vector3d(0.3, 0.1, -0.2), 0.01);
        ErrorStateEkf zupt = both;
        both.setRecordUpdates(true);
        zupt.setRecordUpdates(true);
        both.updateZeroVelocityAndRate(Eigen::Vector3d(0.01, 0.0, 0.0));
        zupt.updateZeroVelocity();
        QCOMPARE(both.recordedUpdates().size(), update_record::length(9, 3, true));
        QVERIFY(!both.recordedUpdatesObservePosition());
        const Eigen::MatrixXd gain = update_record::gainOf(both.recordedUpdates().data(), 9);
        const Eigen::MatrixXd zuptGain = update_record::gainOf(zupt.recordedUpdates().data(), 9);
        QVERIFY2((gain - zuptGain).norm() <= 1e-14 * zuptGain.norm(), qPrintable(QString::number((gain - zuptGain).norm())));
        QVERIFY(zuptGain.norm() > 0.0);
    }

    void staticImuWithGyroBiasEstimatesTheBiasAndStaysPut()
    {
        const Eigen::Vector3d trueBias(0.01, -0.02, 0.005);
        const Eigen::Matrix3d attitude = rotationFromRollPitchYaw(0.05, -0.1, 0.0);
        const Eigen::Vector3d acc = attitude.transpose() * Eigen::Vector3d(0, 0, 9.81);
        ErrorStateEkf ekf(guo2015Parameters(), attitude);
        for (int k = 0; k < 6000; ++k) {  // one minute at 100 Hz
            ekf.propagate(acc, trueBias, 0.01);
            ekf.updateZeroVelocityAndRate(trueBias);
        }
        const NavState& state = ekf.state();
        QVERIFY2((state.gyroBias_radps - trueBias).norm() < 1e-4,
                 qPrintable(QString::number((state.gyroBias_radps - trueBias).norm())));
        QVERIFY2(state.position_m.norm() < 1e-3, qPrintable(QString::number(state.position_m.norm())));
        // At rest a tilt error and a horizontal accelerometer bias look alike; the filter may keep
        // a little of either, but their sum must not move the IMU (checked above) nor reach 0.03 deg.
        QVERIFY(rotationVector(state.bodyToNav * attitude.transpose()).head<2>().norm() < 5e-4);
    }

    void zuptAloneKeepsAStaticImuInPlace()
    {
        const Eigen::Vector3d acc(0.0, 0.0, 9.81);
        ErrorStateEkf ekf(guo2015Parameters(), Eigen::Matrix3d::Identity());
        for (int k = 0; k < 6000; ++k) {
            ekf.propagate(acc + Eigen::Vector3d(0.0, 0.0, 0.01 * ((k % 7) - 3)), Eigen::Vector3d::Zero(), 0.01);
            ekf.updateZeroVelocity();
        }
        QVERIFY(ekf.state().position_m.norm() < 1e-3);
        QVERIFY(ekf.state().velocity_mps.norm() < 1e-3);
    }

    void updateKeepsCovarianceSymmetricPositiveDefinite()
    {
        Parameters params = guo2015Parameters();
        params.p0_pos_m = 1.0;
        params.p0_vel_mps = 1.0;
        params.p0_att_rad = 0.1;
        ErrorStateEkf ekf(params, Eigen::Matrix3d::Identity());
        ekf.propagate(Eigen::Vector3d(3.0, 0.0, 9.81), Eigen::Vector3d(0.0, 0.0, 1.0), 0.01);
        const double velocityVarianceBefore = ekf.covariance()(kVel, kVel);
        ekf.updateZeroVelocityAndRate(Eigen::Vector3d::Zero());
        const Matrix15& p = ekf.covariance();
        QCOMPARE((p - p.transpose()).norm(), 0.0);
        // Positive definite: its Cholesky factorization exists (an eigensolver of 15 x 15 took this
        // file a third of its compile time).
        QCOMPARE(Eigen::LLT<Matrix15>(p).info(), Eigen::Success);
        QVERIFY(p(kVel, kVel) < 0.01 * velocityVarianceBefore);
        QVERIFY(p(kVel, kVel) < 1e-4 + 1e-12);  // cannot beat R_zupt = 0.01^2
    }

    void zuptPullsVelocityToZeroAndCorrectsPosition()
    {
        Parameters params = zeroInitialUncertainty();
        params.q_vel_mps = 0.1;
        ErrorStateEkf ekf(params, Eigen::Matrix3d::Identity());
        for (int k = 0; k < 10; ++k)
            ekf.propagate(Eigen::Vector3d(1.0, 0.0, 9.81), Eigen::Vector3d::Zero(), 0.01);
        const double speedBefore = ekf.state().velocity_mps.x();
        const double positionBefore = ekf.state().position_m.x();
        QVERIFY(speedBefore > 0.09);
        ekf.updateZeroVelocity();
        QVERIFY(std::abs(ekf.state().velocity_mps.x()) < 0.05 * speedBefore);
        // Position and velocity errors are correlated through Phi(r, v): the update moves x back.
        QVERIFY(ekf.state().position_m.x() < positionBefore);
    }

    void zeroTimeStepIsIgnored()
    {
        ErrorStateEkf ekf(guo2015Parameters(), Eigen::Matrix3d::Identity());
        const Matrix15 before = ekf.covariance();
        ekf.propagate(Eigen::Vector3d(5.0, 0.0, 9.81), Eigen::Vector3d(1.0, 0.0, 0.0), 0.0);
        QCOMPARE(ekf.state().velocity_mps.norm(), 0.0);
        QCOMPARE((ekf.covariance() - before).norm(), 0.0);
    }

    void chiSquareQuantilesMatchTheTables()
    {
        // Values of the standard tables (and of scipy.stats.chi2.ppf).
        QVERIFY(std::abs(chiSquareQuantile(0.95, 1) - 3.841458820694124) < 1e-8);
        QVERIFY(std::abs(chiSquareQuantile(0.99, 2) - 9.210340371976184) < 1e-8);
        QVERIFY(std::abs(chiSquareQuantile(0.999, 3) - 16.26623619623813) < 1e-7);
        QVERIFY(std::abs(chiSquareQuantile(0.5, 6) - 5.348120627447122) < 1e-8);
        QVERIFY(std::abs(chiSquareProbability(chiSquareQuantile(0.9999, 4), 4) - 0.9999) < 1e-12);
    }

    void innovationGateRejectsWhatTheCovarianceRulesOut()
    {
        Parameters params;
        params.p0_att_rad = 0.01;  // a yaw std of 0.01 rad
        params.gate_probability = 0.99;
        ErrorStateEkf ekf(params, Eigen::Matrix3d::Identity());
        Eigen::MatrixXd h = Eigen::MatrixXd::Zero(1, ErrorStateEkf::kStates);
        h(0, ErrorStateEkf::kAtt + 2) = 1.0;
        const Eigen::VectorXd noise = Eigen::VectorXd::Constant(1, 0.01 * 0.01);
        // S = 2e-4: a 0.05 rad innovation is 3.5 sigma (12.5 > 6.63), a 0.01 rad one 0.7 sigma.
        const Matrix15 before = ekf.covariance();
        QVERIFY(!ekf.updateRows(h, Eigen::VectorXd::Constant(1, 0.05), noise));
        QCOMPARE((ekf.covariance() - before).norm(), 0.0);  // a rejected measurement changes nothing
        QVERIFY(ekf.updateRows(h, Eigen::VectorXd::Constant(1, 0.01), noise));
        QCOMPARE(ekf.gateCounts().tested, std::size_t(2));
        QCOMPARE(ekf.gateCounts().rejected, std::size_t(1));

        params.gate_probability = 0.0;  // no gate: everything is applied, nothing counted
        ErrorStateEkf ungated(params, Eigen::Matrix3d::Identity());
        QVERIFY(ungated.updateRows(h, Eigen::VectorXd::Constant(1, 0.05), noise));
        QCOMPARE(ungated.gateCounts().tested, std::size_t(0));
    }
};

QTEST_APPLESS_MAIN(TestErrorStateEkf)
#include "tst_errorstateekf.moc"
