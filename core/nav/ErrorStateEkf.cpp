#include "nav/ErrorStateEkf.h"

#include "nav/Attitude.h"
#include "nav/Strapdown.h"

#include <Eigen/Cholesky>

namespace footpath {

namespace {

// The paper's Q values are per step at 100 Hz; scaling the variance by dt / 10 ms keeps the noise
// per second the same at any rate.
constexpr double kReferenceStep_s = 0.01;

Eigen::Matrix<double, 15, 1> blockDiagonal(double att, double gyroBias, double pos, double vel, double accBias)
{
    Eigen::Matrix<double, 15, 1> d;
    d << Eigen::Vector3d::Constant(att * att), Eigen::Vector3d::Constant(gyroBias * gyroBias),
        Eigen::Vector3d::Constant(pos * pos), Eigen::Vector3d::Constant(vel * vel),
        Eigen::Vector3d::Constant(accBias * accBias);
    return d;
}

}  // namespace

ErrorStateEkf::ErrorStateEkf(const Parameters& params, const Eigen::Matrix3d& initialAttitude)
    : params_(params)
{
    state_.bodyToNav = initialAttitude;
    covariance_ = blockDiagonal(params.p0_att_rad, params.p0_gyro_bias_radps, params.p0_pos_m, params.p0_vel_mps,
                                params.p0_acc_bias_mps2)
                      .asDiagonal();
    processVariancePerStep_ = blockDiagonal(params.q_att_rad, params.q_gyro_bias_radps, params.q_pos_m,
                                            params.q_vel_mps, params.q_acc_bias_mps2);
}

void ErrorStateEkf::propagate(const Eigen::Vector3d& acc_mps2, const Eigen::Vector3d& gyr_radps, double dt_s)
{
    if (!(dt_s > 0.0))
        return;  // a repeated timestamp carries no motion
    lastNavAcc_ = strapdownStep(state_, acc_mps2, gyr_radps, dt_s, params_.gravity_mps2);
    propagateCovariance(lastNavAcc_, dt_s);
}

ErrorStateEkf::Matrix15 ErrorStateEkf::transitionMatrix(const Eigen::Vector3d& navSpecificForce, double dt_s) const
{
    Matrix15 phi = Matrix15::Identity();
    const Eigen::Matrix3d& c = state_.bodyToNav;
    phi.block<3, 3>(kAtt, kGyroBias) = dt_s * c;
    phi.block<3, 3>(kPos, kVel) = dt_s * Eigen::Matrix3d::Identity();
    phi.block<3, 3>(kVel, kAtt) = -dt_s * skew(navSpecificForce);
    phi.block<3, 3>(kVel, kAccBias) = dt_s * c;
    return phi;
}

void ErrorStateEkf::propagateCovariance(const Eigen::Vector3d& navSpecificForce, double dt_s)
{
    // Phi = I + four 3x3 blocks, so Phi P Phi^T is P plus a few block products: first M = Phi P
    // (row blocks), then M Phi^T (column blocks). About 12x fewer operations than the dense product.
    const Eigen::Matrix3d attFromGyroBias = dt_s * state_.bodyToNav;
    const Eigen::Matrix3d velFromAtt = -dt_s * skew(navSpecificForce);
    const Eigen::Matrix3d& velFromAccBias = attFromGyroBias;  // dt C as well
    Matrix15& p = covariance_;

    Matrix15 m = p;
    m.middleRows<3>(kAtt).noalias() += attFromGyroBias * p.middleRows<3>(kGyroBias);
    m.middleRows<3>(kPos) += dt_s * p.middleRows<3>(kVel);
    m.middleRows<3>(kVel).noalias() += velFromAtt * p.middleRows<3>(kAtt);
    m.middleRows<3>(kVel).noalias() += velFromAccBias * p.middleRows<3>(kAccBias);

    p = m;
    p.middleCols<3>(kAtt).noalias() += m.middleCols<3>(kGyroBias) * attFromGyroBias.transpose();
    p.middleCols<3>(kPos) += dt_s * m.middleCols<3>(kVel);
    p.middleCols<3>(kVel).noalias() += m.middleCols<3>(kAtt) * velFromAtt.transpose();
    p.middleCols<3>(kVel).noalias() += m.middleCols<3>(kAccBias) * velFromAccBias.transpose();

    p.diagonal() += processVariancePerStep_ * (dt_s / kReferenceStep_s);
}

template <int Rows>
void ErrorStateEkf::update(const Eigen::Matrix<int, Rows / 3, 1>& blockOffsets,
                           const Eigen::Matrix<double, Rows, 1>& innovation,
                           const Eigen::Matrix<double, Rows, 1>& noiseVariance)
{
    using PHt = Eigen::Matrix<double, kStates, Rows>;
    using MatR = Eigen::Matrix<double, Rows, Rows>;
    const Matrix15& p = covariance_;
    // H only selects 3-blocks of the state with +I, so P H^T is a set of columns of P.
    PHt pht;
    for (int b = 0; b < Rows / 3; ++b)
        pht.template middleCols<3>(3 * b) = p.template middleCols<3>(blockOffsets(b));
    MatR s;
    for (int b = 0; b < Rows / 3; ++b)
        s.template middleRows<3>(3 * b) = pht.template middleRows<3>(blockOffsets(b));
    s.diagonal() += noiseVariance;
    // K = P H^T S^-1 (eq. 31) by a solve with the symmetric S: K^T = S^-1 (P H^T)^T.
    const PHt gain = s.ldlt().solve(pht.transpose()).transpose();
    const Vector15 dx = gain * innovation;

    // Joseph form (eq. 33): (I - KH) P (I - KH)^T + K R K^T, using H P = (P H^T)^T.
    Matrix15 a = p;
    a.noalias() -= gain * pht.transpose();
    PHt aht;
    for (int b = 0; b < Rows / 3; ++b)
        aht.template middleCols<3>(3 * b) = a.template middleCols<3>(blockOffsets(b));
    a.noalias() -= aht * gain.transpose();
    a.noalias() += gain * noiseVariance.asDiagonal() * gain.transpose();
    covariance_ = 0.5 * (a + a.transpose());
    applyCorrection(dx);
}

void ErrorStateEkf::updateZeroVelocity()
{
    // z = v_est - 0 = dv (estimate - truth).
    const Eigen::Matrix<int, 1, 1> blocks(kVel);
    update<3>(blocks, state_.velocity_mps, Eigen::Vector3d::Constant(params_.r_zupt_mps * params_.r_zupt_mps));
}

void ErrorStateEkf::updateZeroAngularRate(const Eigen::Vector3d& gyr_radps)
{
    // At rest the raw rate is the true bias: z = w - b_est = dw_b (truth - estimate).
    const Eigen::Matrix<int, 1, 1> blocks(kGyroBias);
    update<3>(blocks, gyr_radps - state_.gyroBias_radps,
              Eigen::Vector3d::Constant(params_.r_zaru_radps * params_.r_zaru_radps));
}

void ErrorStateEkf::updateZeroVelocityAndRate(const Eigen::Vector3d& gyr_radps)
{
    const Eigen::Matrix<int, 2, 1> blocks(kGyroBias, kVel);
    Eigen::Matrix<double, 6, 1> innovation, variance;
    innovation << gyr_radps - state_.gyroBias_radps, state_.velocity_mps;
    variance << Eigen::Vector3d::Constant(params_.r_zaru_radps * params_.r_zaru_radps),
        Eigen::Vector3d::Constant(params_.r_zupt_mps * params_.r_zupt_mps);
    update<6>(blocks, innovation, variance);
}

void ErrorStateEkf::applyCorrection(const Vector15& dx)
{
    // Eq. 12-15 with the sign that matches dphi = estimate - truth: C_true = (I - S(dphi)) C_est,
    // in Padé form (2I - S)(2I + S)^-1 C.
    state_.bodyToNav = padeRotation(-dx.segment<3>(kAtt)) * state_.bodyToNav;
    reorthonormalize(state_.bodyToNav);
    state_.gyroBias_radps += dx.segment<3>(kGyroBias);
    state_.position_m -= dx.segment<3>(kPos);
    state_.velocity_mps -= dx.segment<3>(kVel);
    state_.accBias_mps2 += dx.segment<3>(kAccBias);
    // The error states return to zero implicitly: dx is recomputed from zero at every update.
}

}  // namespace footpath
