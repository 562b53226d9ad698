#include "nav/ErrorStateEkf.h"

#include "nav/ChiSquare.h"

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

/// The Cholesky factor L of a small symmetric positive definite S = L L^T (lower triangle; the upper
/// is zero). Written out because Eigen's LLT does not unroll at these sizes and cost as much as the
/// rest of a ZUPT's gain.
template <int Rows>
Eigen::Matrix<double, Rows, Rows> choleskyFactor(const Eigen::Matrix<double, Rows, Rows>& s)
{
    Eigen::Matrix<double, Rows, Rows> l = Eigen::Matrix<double, Rows, Rows>::Zero();
    for (int j = 0; j < Rows; ++j) {
        double diagonal = s(j, j);
        for (int k = 0; k < j; ++k)
            diagonal -= l(j, k) * l(j, k);
        l(j, j) = std::sqrt(diagonal);
        const double inverse = 1.0 / l(j, j);
        for (int i = j + 1; i < Rows; ++i) {
            double below = s(i, j);
            for (int k = 0; k < j; ++k)
                below -= l(i, k) * l(j, k);
            l(i, j) = below * inverse;
        }
    }
    return l;
}

/// W = P H^T L^-T, for S = L L^T (the Cholesky factor L of S, symmetric positive definite because
/// R is): by forward substitution on whole columns of W, which are contiguous N-vectors (Eigen's
/// general triangular solver is slow at these sizes). W W^T = P H^T S^-1 H P, what the update takes
/// off P, and K = W L^-1 (gainFromWhitened).
template <int N, int Rows>
Eigen::Matrix<double, N, Rows> whitenedGain(const Eigen::Matrix<double, N, Rows>& pht,
                                            const Eigen::Matrix<double, Rows, Rows>& l)
{
    Eigen::Matrix<double, N, Rows> w = pht;
    for (int i = 0; i < Rows; ++i) {  // W L^T = P H^T: forward over the columns of W
        for (int j = 0; j < i; ++j)
            w.col(i) -= l(i, j) * w.col(j);
        w.col(i) /= l(i, i);
    }
    return w;
}

/// K = P H^T S^-1 (eq. 31) = W L^-1: K L = W, backward over the columns of K.
template <int N, int Rows>
Eigen::Matrix<double, N, Rows> gainFromWhitened(const Eigen::Matrix<double, N, Rows>& w,
                                                const Eigen::Matrix<double, Rows, Rows>& l)
{
    Eigen::Matrix<double, N, Rows> k = w;
    for (int i = Rows - 1; i >= 0; --i) {
        for (int j = i + 1; j < Rows; ++j)
            k.col(i) -= l(j, i) * k.col(j);
        k.col(i) /= l(i, i);
    }
    return k;
}

/// S^-1 = L^-T L^-1 from the Cholesky factor S = L L^T: L^-1 by forward substitution on its
/// columns (Eigen's general triangular solver is slow at these sizes, as in solveGain).
template <int Rows>
Eigen::Matrix<double, Rows, Rows> inverseFromCholesky(const Eigen::Matrix<double, Rows, Rows>& l)
{
    Eigen::Matrix<double, Rows, Rows> inverseL = Eigen::Matrix<double, Rows, Rows>::Zero();
    for (int c = 0; c < Rows; ++c) {
        inverseL(c, c) = 1.0 / l(c, c);
        for (int i = c + 1; i < Rows; ++i) {
            double sum = 0.0;
            for (int j = c; j < i; ++j)
                sum += l(i, j) * inverseL(j, c);
            inverseL(i, c) = -sum / l(i, i);
        }
    }
    return inverseL.transpose() * inverseL;
}

/// F B for an F with a zero diagonal, -dt S(a_n) in the propagation: each entry is the sum of the
/// two products off F's diagonal. Eigen's 3x3 product adds a third, F's diagonal entry (a signed
/// zero) times B's, which changes no sum (x + 0 = x, whichever way the three are grouped): the
/// same bits at two thirds of the multiplications.
template <class B>
Eigen::Matrix3d zeroDiagonalTimes(const Eigen::Matrix3d& f, const B& b)
{
    Eigen::Matrix3d r;
    for (int j = 0; j < 3; ++j) {
        r(0, j) = f(0, 1) * b(1, j) + f(0, 2) * b(2, j);
        r(1, j) = f(1, 0) * b(0, j) + f(1, 2) * b(2, j);
        r(2, j) = f(2, 0) * b(0, j) + f(2, 1) * b(1, j);
    }
    return r;
}

/// A F for an F with a zero diagonal, as zeroDiagonalTimes. Written out rather than as
/// zeroDiagonalTimes(F^T, A^T)^T, which gives the same bits but copied the transposes: 9 % more
/// instructions in the 9-state propagation (callgrind).
template <class A>
Eigen::Matrix3d timesZeroDiagonal(const A& a, const Eigen::Matrix3d& f)
{
    Eigen::Matrix3d r;
    for (int i = 0; i < 3; ++i) {
        r(i, 0) = a(i, 1) * f(1, 0) + a(i, 2) * f(2, 0);
        r(i, 1) = a(i, 0) * f(0, 1) + a(i, 2) * f(2, 1);
        r(i, 2) = a(i, 0) * f(0, 2) + a(i, 1) * f(1, 2);
    }
    return r;
}

}  // namespace

ErrorStateEkf::ErrorStateEkf(const Parameters& params, const Eigen::Matrix3d& initialAttitude)
    : params_(params)
{
    state_.bodyToNav = initialAttitude;
    // The 9-state filter is the 15-state one with the bias states held at zero: no initial
    // uncertainty and no process noise, so no gain ever reaches them and no error flows through them.
    const bool biasStates = params.filterStates() == FilterStates::Fifteen;
    const double biasGate = biasStates ? 1.0 : 0.0;
    covariance_ = blockDiagonal(params.p0_att_rad, biasGate * params.p0_gyro_bias_radps, params.p0_pos_m,
                                params.p0_vel_mps, biasGate * params.p0_acc_bias_mps2)
                      .asDiagonal();
    processVariancePerStep_ = blockDiagonal(params.q_att_rad, biasGate * params.q_gyro_bias_radps, params.q_pos_m,
                                            params.q_vel_mps, biasGate * params.q_acc_bias_mps2);
    biasStates_ = biasStates;
    if (params.gate_probability > 0.0)
        for (int rows = 1; rows <= kGatedRows; ++rows)
            gateThresholds_.push_back(chiSquareQuantile(params.gate_probability, rows));
}

void ErrorStateEkf::propagate(const Eigen::Vector3d& acc_mps2, const Eigen::Vector3d& gyr_radps, double dt_s)
{
    updateRecords_.clear();
    recordsObservePosition_ = false;
    if (!(dt_s > 0.0)) {
        lastPropagation_.dt_s = 0.0;  // a repeated timestamp carries no motion
        return;
    }
    const Eigen::Vector3d navSpecificForce = strapdownStep(state_, acc_mps2, gyr_radps, dt_s, params_.gravity_mps2);
    lastPropagation_ = PropagationStep{navSpecificForce, state_.bodyToNav, dt_s};
    propagateCovariance(lastPropagation_, processVariance(dt_s));
}

ErrorStateEkf::Vector15 ErrorStateEkf::processVariance(double dt_s) const
{
    return processVariancePerStep_ * (dt_s / kReferenceStep_s);
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

void ErrorStateEkf::propagateCovariance(const PropagationStep& step, const Vector15& processVariance)
{
    if (!(step.dt_s > 0.0))
        return;
    if (biasStates_)
        propagateAllBlocks(step);
    else
        propagateNavigationBlocks(step);
    covariance_.diagonal() += processVariance;
}

void ErrorStateEkf::propagateNavigationBlocks(const PropagationStep& step)
{
    // Without bias states Phi = I + two blocks, (pos, vel) = dt I and (vel, att) = -dt S(a_n), and
    // the bias rows and columns of P stay zero: 4 products of 3x3 blocks. The attitude rows of
    // M = Phi P are those of P; P' = M Phi^T, upper triangle, then mirrored.
    const double dt_s = step.dt_s;
    const Eigen::Matrix3d velFromAtt = -dt_s * skew(step.navSpecificForce);
    const Eigen::Matrix3d velFromAttT = velFromAtt.transpose();
    Matrix15& p = covariance_;
    const auto b = [&p](int row, int col) { return p.block<3, 3>(row, col); };
    const Eigen::Matrix3d mPosAtt = b(kPos, kAtt) + dt_s * b(kVel, kAtt);
    const Eigen::Matrix3d mPosPos = b(kPos, kPos) + dt_s * b(kVel, kPos);
    const Eigen::Matrix3d mPosVel = b(kPos, kVel) + dt_s * b(kVel, kVel);
    const Eigen::Matrix3d mVelAtt = b(kVel, kAtt) + zeroDiagonalTimes(velFromAtt, b(kAtt, kAtt));
    const Eigen::Matrix3d mVelVel = b(kVel, kVel) + zeroDiagonalTimes(velFromAtt, b(kAtt, kVel));
    b(kVel, kVel) = mVelVel + timesZeroDiagonal(mVelAtt, velFromAttT);
    b(kPos, kVel) = mPosVel + timesZeroDiagonal(mPosAtt, velFromAttT);
    b(kPos, kPos) = mPosPos + dt_s * mPosVel;
    b(kAtt, kPos) = b(kAtt, kPos) + dt_s * b(kAtt, kVel);  // before (att, vel) changes
    // P'(att, vel) = P(att, vel) + P(att, att) velFromAtt^T is M(vel, att)^T, P being symmetric:
    // the same products summed in the same order, one product fewer.
    b(kAtt, kVel) = mVelAtt.transpose();
    for (const auto& [row, col] : {std::pair{kAtt, kPos}, std::pair{kAtt, kVel}, std::pair{kPos, kVel}})
        b(col, row) = b(row, col).transpose();
}

void ErrorStateEkf::propagateAllBlocks(const PropagationStep& step)
{
    const double dt_s = step.dt_s;
    // Phi = I + four 3x3 blocks, so Phi P Phi^T needs 20 products of 3x3 blocks instead of the
    // dense 15x15 triple product (BM_EkfPropagate against BM_DenseCovariancePropagation). Phi leaves
    // the bias rows alone, so only the attitude, position and velocity rows of M = Phi P change;
    // P' = M Phi^T is symmetric, so of the blocks among those three states only the upper
    // triangle is computed, and the bias blocks of P' are blocks of M.
    const Eigen::Matrix3d attFromGyroBias = dt_s * step.bodyToNav;  // also velocity from acc bias
    const Eigen::Matrix3d velFromAtt = -dt_s * skew(step.navSpecificForce);
    Matrix15& p = covariance_;
    const auto b = [&p](int row, int col) { return p.block<3, 3>(row, col); };

    // Rows of M = Phi P for the three states that change (stored as 9 x 15).
    Eigen::Matrix<double, 9, kStates> m;
    constexpr int mAtt = 0, mPos = 3, mVel = 6;
    for (int col = 0; col < kStates; col += 3) {
        m.block<3, 3>(mAtt, col) = b(kAtt, col) + attFromGyroBias * b(kGyroBias, col);
        m.block<3, 3>(mPos, col) = b(kPos, col) + dt_s * b(kVel, col);
        if (col != kPos)  // P'(vel, pos) is taken from P'(pos, vel) below
            m.block<3, 3>(mVel, col) =
                b(kVel, col) + zeroDiagonalTimes(velFromAtt, b(kAtt, col)) + attFromGyroBias * b(kAccBias, col);
    }
    const auto mb = [&m](int row, int col) { return m.block<3, 3>(row, col); };

    // P' = M Phi^T, upper triangle of the changing blocks, then mirror.
    const Eigen::Matrix3d velFromAttT = velFromAtt.transpose();
    const Eigen::Matrix3d cT = attFromGyroBias.transpose();
    b(kAtt, kAtt) = mb(mAtt, kAtt) + mb(mAtt, kGyroBias) * cT;
    b(kAtt, kPos) = mb(mAtt, kPos) + dt_s * mb(mAtt, kVel);
    b(kPos, kPos) = mb(mPos, kPos) + dt_s * mb(mPos, kVel);
    for (const auto& [row, mRow] : {std::pair{kAtt, mAtt}, std::pair{kPos, mPos}, std::pair{kVel, mVel}}) {
        b(row, kVel) = mb(mRow, kVel) + timesZeroDiagonal(mb(mRow, kAtt), velFromAttT) + mb(mRow, kAccBias) * cT;
        b(row, kGyroBias) = mb(mRow, kGyroBias);
        b(row, kAccBias) = mb(mRow, kAccBias);
    }
    for (const auto& [row, col] : {std::pair{kAtt, kPos}, std::pair{kAtt, kVel}, std::pair{kPos, kVel}})
        b(col, row) = b(row, col).transpose();
    for (const int row : {kAtt, kPos, kVel})
        for (const int bias : {kGyroBias, kAccBias})
            b(bias, row) = b(row, bias).transpose();
}

template <int Rows>
void ErrorStateEkf::update(const Eigen::Matrix<int, Rows / 3, 1>& blockOffsets,
                           const Eigen::Matrix<double, Rows, 1>& innovation,
                           const Eigen::Matrix<double, Rows, 1>& noiseVariance)
{
    if (biasStates_)
        updateRunning<kStates, Rows>(blockOffsets, innovation, noiseVariance);
    else
        updateRunning<9, Rows>(blockOffsets, innovation, noiseVariance);
}

template <int N, int Rows>
void ErrorStateEkf::updateRunning(const Eigen::Matrix<int, Rows / 3, 1>& blockOffsets,
                                  const Eigen::Matrix<double, Rows, 1>& innovation,
                                  const Eigen::Matrix<double, Rows, 1>& noiseVariance)
{
    using PHt = Eigen::Matrix<double, N, Rows>;
    using MatR = Eigen::Matrix<double, Rows, Rows>;
    // No work is done on the states the filter does not run (filterIndex).
    constexpr auto filterIndex = &ErrorStateEkf::filterIndex<N>;
    Matrix15& p = covariance_;
    // H only selects 3-blocks of the state with +I, so P H^T is a set of columns of P and H P H^T
    // a set of its rows; S = H P H^T + R.
    const auto selected = [&blockOffsets](int row) { return blockOffsets(row / 3) + row % 3; };
    PHt pht;
    for (int c = 0; c < Rows; ++c)
#pragma GCC unroll 15
        for (int i = 0; i < N; ++i)
            pht(i, c) = p(filterIndex(i), selected(c));
    MatR s;
    for (int c = 0; c < Rows; ++c)
        for (int r = 0; r < Rows; ++r)
            s(r, c) = p(selected(r), selected(c));
    s.diagonal() += noiseVariance;
    const MatR cholesky = choleskyFactor(s);  // S is symmetric positive definite because R is
    const PHt whitened = whitenedGain(pht, cholesky);
    const PHt gain = gainFromWhitened(whitened, cholesky);

    // Eq. 33's Joseph form for the gain made here, K = W L^-1: (I - KH) P (I - KH)^T + K R K^T
    // = P - W W^T but for a term of the gain's rounding, at half the work of the form's two
    // products (tst_errorstateekf updateEqualsTheJosephFormOfEq33). Only the lower triangle of
    // W W^T is computed, as dot products of W's rows, and mirrored: P stays exactly symmetric.
    const Eigen::Matrix<double, Rows, N> whitenedT = whitened.transpose();  // columns are contiguous
    const auto updateLowerAndMirror = [&](int i, int j) {
        double& lower = p(filterIndex(i), filterIndex(j));
        lower -= whitenedT.col(i).dot(whitenedT.col(j));
        p(filterIndex(j), filterIndex(i)) = lower;
    };
    if constexpr (N == 9) {
        // Unrolled: GCC leaves the triangle a loop. The 15 states' 120 entries stay a loop:
        // unrolled, with the Joseph form's longer dot products of the time, they took 8 % longer
        // (bench_pipeline, paper configuration).
#pragma GCC unroll 9
        for (int j = 0; j < N; ++j)
#pragma GCC unroll 9
            for (int i = j; i < N; ++i)
                updateLowerAndMirror(i, j);
    } else {
        for (int j = 0; j < N; ++j)
            for (int i = j; i < N; ++i)
                updateLowerAndMirror(i, j);
    }
    if (recordUpdates_)
        recordUpdate<N, Rows>(blockOffsets, gain, innovation, cholesky);
    if constexpr (N == kStates) {
        applyCorrection(gain * innovation);
    } else {
        // dx = K z on the running states, each sum from its first term on (the order Eigen's
        // product of all 15 rows took); the others stay zero.
        Vector15 dx = Vector15::Zero();
        for (int i = 0; i < N; ++i) {
            double sum = gain(i, 0) * innovation(0);
            for (int r = 1; r < Rows; ++r)
                sum += gain(i, r) * innovation(r);
            dx(filterIndex(i)) = sum;
        }
        applyCorrection(dx);
    }
}

template <int N, int Rows>
void ErrorStateEkf::recordUpdate(const Eigen::Matrix<int, Rows / 3, 1>& blockOffsets,
                                 const Eigen::Matrix<double, N, Rows>& runningGain,
                                 const Eigen::Matrix<double, Rows, 1>& innovation,
                                 const Eigen::Matrix<double, Rows, Rows>& choleskyFactor)
{
    const Eigen::Matrix<double, Rows, Rows> inverseS = inverseFromCholesky<Rows>(choleskyFactor);
    const Eigen::Matrix<double, Rows, 1> weightedInnovation = inverseS * innovation;
    Eigen::Matrix<int, Rows, 1> states, runningStates;  // H selects these
    bool runningButPosition = true;
    for (int row = 0; row < Rows; ++row) {
        states(row) = blockOffsets(row / 3) + row % 3;
        runningStates(row) = runningIndex<N>(states(row));
        runningButPosition = runningButPosition && runningStates(row) >= 0 && !isPosition(states(row));
    }
    if (runningButPosition) {  // ZUPT, ZARU with 15 states, both
        update_record::appendSelecting<N, Rows>(updateRecords_, runningStates, runningGain, weightedInnovation, inverseS);
        return;
    }
    update_record::GeneralUpdate update;
    update.selectedStates = states;
    update.gain = Eigen::MatrixXd::Zero(kStates, Rows);
    for (int i = 0; i < N; ++i)
        update.gain.row(filterIndex<N>(i)) = runningGain.row(i);
    update.weightedInnovation = weightedInnovation;
    update.inverseS = inverseS;
    appendRecord(update);
}

void ErrorStateEkf::appendRecord(const update_record::GeneralUpdate& update)
{
    if (update_record::append(updateRecords_, runningStates(), update))
        recordsObservePosition_ = true;
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

bool ErrorStateEkf::updateRows(const Eigen::MatrixXd& h, const Eigen::VectorXd& innovation,
                               const Eigen::VectorXd& noiseVariance)
{
    const Eigen::MatrixXd pht = covariance_ * h.transpose();
    Eigen::MatrixXd s = h * pht;
    s.diagonal() += noiseVariance;
    const Eigen::LDLT<Eigen::MatrixXd> sFactor = s.ldlt();
    if (!passesGate(sFactor, innovation))
        return false;
    const Eigen::MatrixXd gain = sFactor.solve(pht.transpose()).transpose();
    const Vector15 dx = gain * innovation;
    // Joseph form, as in the block update.
    const Matrix15 iMinusKh = Matrix15::Identity() - gain * h;
    Matrix15 p = iMinusKh * covariance_ * iMinusKh.transpose() + gain * noiseVariance.asDiagonal() * gain.transpose();
    covariance_ = 0.5 * (p + p.transpose());
    if (recordUpdates_) {
        update_record::GeneralUpdate update;
        update.h = h;
        update.gain = gain;
        const Eigen::LLT<Eigen::MatrixXd> cholesky(s);
        update.weightedInnovation = cholesky.solve(innovation);
        update.inverseS = cholesky.solve(Eigen::MatrixXd::Identity(s.rows(), s.cols()));
        appendRecord(update);
    }
    applyCorrection(dx);
    return true;
}

bool ErrorStateEkf::passesGate(const Eigen::LDLT<Eigen::MatrixXd>& sFactor, const Eigen::VectorXd& innovation)
{
    const auto rows = static_cast<std::size_t>(innovation.size());
    if (gateThresholds_.empty() || rows == 0 || rows > gateThresholds_.size())
        return true;
    ++gateCounts_.tested;
    const double normalised = innovation.dot(sFactor.solve(innovation));
    if (normalised <= gateThresholds_[rows - 1])
        return true;
    ++gateCounts_.rejected;
    return false;
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
