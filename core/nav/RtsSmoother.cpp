#include "nav/RtsSmoother.h"

#include "nav/Attitude.h"

#include <Eigen/Cholesky>

namespace footpath {

namespace {

constexpr std::size_t kProgressInterval = 8192;

std::vector<int> activeStates(FilterStates states)
{
    using E = ErrorStateEkf;
    if (states == FilterStates::Fifteen)
        return {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14};
    std::vector<int> active;
    for (const int block : {E::kAtt, E::kPos, E::kVel})
        for (int i = 0; i < 3; ++i)
            active.push_back(block + i);
    return active;
}

}  // namespace

RtsSmoother::RtsSmoother(const Parameters& params, const ErrorStateEkf& ekf)
    : active_(activeStates(params.filterStates()))
    , storesPropagationAttitude_(params.filterStates() == FilterStates::Fifteen)
    , processVariancePerSecond_(ekf.processVariance(1.0))
{
}

void RtsSmoother::reserve(std::size_t samples)
{
    packedCovariance_.reserve(samples * packedSize());
    corrections_.reserve(samples * active_.size());
    attitude_.reserve(samples);
    navSpecificForce_.reserve(samples);
    dt_s_.reserve(samples);
    if (storesPropagationAttitude_)
        propagationAttitude_.reserve(samples);
}

void RtsSmoother::capture(const ErrorStateEkf& ekf)
{
    const Matrix15& p = ekf.covariance();
    for (std::size_t j = 0; j < active_.size(); ++j)
        for (std::size_t i = 0; i <= j; ++i)
            packedCovariance_.push_back(p(active_[i], active_[j]));
    for (const int state : active_)
        corrections_.push_back(ekf.correctionsSincePropagation()(state));
    attitude_.emplace_back(ekf.state().bodyToNav);
    const PropagationStep& step = ekf.lastPropagation();
    navSpecificForce_.push_back(step.navSpecificForce);
    dt_s_.push_back(step.dt_s);
    if (storesPropagationAttitude_)
        propagationAttitude_.emplace_back(step.bodyToNav);
}

std::size_t RtsSmoother::bytesPerSample() const
{
    const std::size_t doubles = packedSize() + active_.size() + 4 + 3 + 1 + (storesPropagationAttitude_ ? 4 : 0);
    return doubles * sizeof(double);
}

PropagationStep RtsSmoother::propagationInto(std::size_t k) const
{
    PropagationStep step;
    step.navSpecificForce = navSpecificForce_[k];
    step.dt_s = dt_s_[k];
    if (storesPropagationAttitude_)
        step.bodyToNav = propagationAttitude_[k].toRotationMatrix();
    return step;
}

namespace {

/// X = A^-1 B for a symmetric positive semi-definite A by Cholesky and substitution over whole rows,
/// written out because Eigen's triangular solver takes its general matrix path at these sizes
/// (a third of the backward pass). A gets a tiny diagonal load: at the start of a recording some
/// states have no variance yet (P0 of zero), and their rows of B are zero too, so they get zero.
template <int N>
Eigen::Matrix<double, N, N> solveSymmetric(Eigen::Matrix<double, N, N> a, Eigen::Matrix<double, N, N> b)
{
    a.diagonal().array() += 1e-18 + 1e-12 * a.diagonal().maxCoeff();
    const Eigen::Matrix<double, N, N> l = a.llt().matrixL();
    for (int i = 0; i < N; ++i) {  // L Y = B
        for (int j = 0; j < i; ++j)
            b.row(i) -= l(i, j) * b.row(j);
        b.row(i) /= l(i, i);
    }
    for (int i = N - 1; i >= 0; --i) {  // L^T X = Y
        for (int j = i + 1; j < N; ++j)
            b.row(i) -= l(j, i) * b.row(j);
        b.row(i) /= l(i, i);
    }
    return b;
}

}  // namespace

template <int N>
void RtsSmoother::writeSmoothed(Result& result, std::size_t k, const Eigen::Matrix<double, N, 1>& correction,
                                const Eigen::Matrix<double, N, N>& covariance) const
{
    using E = ErrorStateEkf;
    Vector15 dx = Vector15::Zero();
    for (int i = 0; i < N; ++i)
        dx(active_[static_cast<std::size_t>(i)]) = correction(i);
    // The filter's signs (ErrorStateEkf::applyCorrection): attitude, position and velocity errors
    // are estimate - truth, bias errors truth - estimate.
    Eigen::Matrix3d bodyToNav = padeRotation(-dx.segment<3>(E::kAtt)) * attitude_[k].toRotationMatrix();
    reorthonormalize(bodyToNav);
    result.rollPitchYaw_rad[k] = rollPitchYaw(bodyToNav);
    result.position_m[k] -= dx.segment<3>(E::kPos);
    result.velocity_mps[k] -= dx.segment<3>(E::kVel);
    result.gyroBias_radps[k] += dx.segment<3>(E::kGyroBias);
    result.accBias_mps2[k] += dx.segment<3>(E::kAccBias);
    if (k < result.errorStd.size()) {
        Eigen::Matrix<float, 15, 1>& sigma = result.errorStd[k];
        sigma.setZero();
        for (int i = 0; i < N; ++i)
            sigma(active_[static_cast<std::size_t>(i)]) = static_cast<float>(std::sqrt(std::max(0.0, covariance(i, i))));
    }
}

bool RtsSmoother::smooth(Result& result, const std::function<bool(double fraction)>& keepGoing) const
{
    if (attitude_.empty() || result.position_m.size() != attitude_.size())
        return true;
    return active_.size() == 15 ? smoothBackward<15>(result, keepGoing) : smoothBackward<9>(result, keepGoing);
}

template <int N>
Eigen::Matrix<double, N, N> RtsSmoother::filteredCovariance(std::size_t k) const
{
    Eigen::Matrix<double, N, N> p;
    const double* packed = packedCovariance_.data() + k * packedSize();
    for (int j = 0; j < N; ++j)
        for (int i = 0; i <= j; ++i, ++packed)
            p(i, j) = p(j, i) = *packed;
    return p;
}

template <int N>
void RtsSmoother::applyTransition(Eigen::Matrix<double, N, N>& m, const PropagationStep& step) const
{
    // m = Phi m with Phi = I + the blocks of eq. 26, on the running states in their stored order
    // (attitude, position, velocity for 9 states; the filter's order for 15). Position first: it
    // takes the velocity rows before they change.
    if (!(step.dt_s > 0.0))
        return;
    constexpr bool biases = N == 15;
    constexpr int att = 0, gyroBias = 3, pos = biases ? 6 : 3, vel = biases ? 9 : 6, accBias = 12;
    m.template middleRows<3>(pos) += step.dt_s * m.template middleRows<3>(vel);
    m.template middleRows<3>(vel) -= (step.dt_s * skew(step.navSpecificForce)).lazyProduct(m.template middleRows<3>(att));
    if constexpr (biases) {
        const Eigen::Matrix3d biasGain = step.dt_s * step.bodyToNav;
        m.template middleRows<3>(att) += biasGain.lazyProduct(m.template middleRows<3>(gyroBias));
        m.template middleRows<3>(vel) += biasGain.lazyProduct(m.template middleRows<3>(accBias));
    }
}

template <int N>
bool RtsSmoother::smoothBackward(Result& result, const std::function<bool(double fraction)>& keepGoing) const
{
    using MatrixN = Eigen::Matrix<double, N, N>;
    using VectorN = Eigen::Matrix<double, N, 1>;
    const std::size_t n = attitude_.size();
    VectorN processVariancePerSecond;
    for (int i = 0; i < N; ++i)
        processVariancePerSecond(i) = processVariancePerSecond_(active_[static_cast<std::size_t>(i)]);
    // The last sample's smoothed estimate is its filtered one.
    VectorN correctionNext = VectorN::Zero();
    MatrixN smoothedCovarianceNext = filteredCovariance<N>(n - 1);
    for (std::size_t k = n - 1; k-- > 0;) {
        const MatrixN filtered = filteredCovariance<N>(k);
        const PropagationStep step = propagationInto(k + 1);
        // P(k+1|k) = Phi P Phi^T + Q, with Phi P kept: it is also the right-hand side of the gain.
        MatrixN phiP = filtered;
        applyTransition<N>(phiP, step);
        MatrixN predicted = phiP.transpose();
        applyTransition<N>(predicted, step);
        predicted.diagonal() += processVariancePerSecond * step.dt_s;

        // G^T = P(k+1|k)^-1 Phi P(k|k). Lazy products: fixed-size and unrolled, not Eigen's
        // general kernel.
        const MatrixN gainT = solveSymmetric<N>(predicted, phiP);
        const Eigen::Map<const VectorN> ownCorrection(corrections_.data() + (k + 1) * static_cast<std::size_t>(N));
        const VectorN correction = gainT.transpose() * (ownCorrection + correctionNext);
        const MatrixN change = (smoothedCovarianceNext - predicted).lazyProduct(gainT);
        const MatrixN smoothedCovariance = filtered + gainT.transpose().lazyProduct(change);

        writeSmoothed<N>(result, k, correction, smoothedCovariance);
        correctionNext = correction;
        smoothedCovarianceNext = smoothedCovariance;
        if (keepGoing && k % kProgressInterval == 0 && !keepGoing(static_cast<double>(n - k) / static_cast<double>(n)))
            return false;
    }
    return true;
}

}  // namespace footpath
