#include "DenseReferenceFilter.h"

#include "detect/StanceDetector.h"
#include "nav/Alignment.h"
#include "nav/Attitude.h"
#include "nav/ErrorStateEkf.h"
#include "nav/Strapdown.h"

#include <Eigen/Cholesky>

namespace footpath {

namespace {

/// The running states in the filter's order: [att, gyro bias, pos, vel, acc bias], or
/// [att, pos, vel] without biases.
template <int N>
struct Layout {
    static constexpr bool biases = N == 15;
    static constexpr int att = 0, gyroBias = 3, pos = biases ? 6 : 3, vel = biases ? 9 : 6, accBias = 12;
};

template <int N>
struct DenseFilter {
    using Matrix = Eigen::Matrix<double, N, N>;
    using Vector = Eigen::Matrix<double, N, 1>;
    using L = Layout<N>;

    /// What the smoother needs of each sample.
    struct Stored {
        Matrix filtered;    ///< P(k|k)
        Matrix predicted;   ///< P(k|k-1)
        Matrix transition;  ///< Phi from k-1 to k
        Vector correction;  ///< the filter's dx at k
    };

    const Parameters& params;
    NavState state;
    Matrix p = Matrix::Zero();
    Vector qPerStep = Vector::Zero();  ///< at the 10 ms reference step

    DenseFilter(const Parameters& parameters, const Eigen::Matrix3d& attitude) : params(parameters)
    {
        state.bodyToNav = attitude;
        setBlock(p, L::att, params.p0_att_rad);
        setBlock(p, L::pos, params.p0_pos_m);
        setBlock(p, L::vel, params.p0_vel_mps);
        setBlock(qPerStep, L::att, params.q_att_rad);
        setBlock(qPerStep, L::pos, params.q_pos_m);
        setBlock(qPerStep, L::vel, params.q_vel_mps);
        if constexpr (L::biases) {
            setBlock(p, L::gyroBias, params.p0_gyro_bias_radps);
            setBlock(p, L::accBias, params.p0_acc_bias_mps2);
            setBlock(qPerStep, L::gyroBias, params.q_gyro_bias_radps);
            setBlock(qPerStep, L::accBias, params.q_acc_bias_mps2);
        }
    }

    static void setBlock(Matrix& m, int at, double std) { m.template block<3, 3>(at, at) = std * std * Eigen::Matrix3d::Identity(); }
    static void setBlock(Vector& v, int at, double std) { v.template segment<3>(at).setConstant(std * std); }

    /// Strapdown step, then P = Phi P Phi^T + Q with the dense Phi of eq. 26.
    Matrix propagate(const ImuSample& sample, double dt_s)
    {
        const Eigen::Vector3d navForce = strapdownStep(state, sample.acc_mps2, sample.gyr_radps, dt_s, params.gravity_mps2);
        Matrix phi = Matrix::Identity();
        phi.template block<3, 3>(L::pos, L::vel) = dt_s * Eigen::Matrix3d::Identity();
        phi.template block<3, 3>(L::vel, L::att) = -dt_s * skew(navForce);
        if constexpr (L::biases) {
            phi.template block<3, 3>(L::att, L::gyroBias) = dt_s * state.bodyToNav;
            phi.template block<3, 3>(L::vel, L::accBias) = dt_s * state.bodyToNav;
        }
        p = phi * p * phi.transpose();
        p.diagonal() += qPerStep * (dt_s / 0.01);
        return phi;
    }

    /// ZUPT (and ZARU with bias states): z = H dx + noise, H picking the velocity (and gyro bias).
    Vector update(const ImuSample& sample)
    {
        const bool zaru = L::biases && params.use_zaru;
        const bool zupt = params.use_zupt;
        const int rows = 3 * (int(zaru) + int(zupt));
        Eigen::MatrixXd h = Eigen::MatrixXd::Zero(rows, N);
        Eigen::VectorXd z(rows), r(rows);
        int row = 0;
        if (zaru) {
            h.block(row, L::gyroBias, 3, 3).setIdentity();
            z.segment(row, 3) = sample.gyr_radps - state.gyroBias_radps;
            r.segment(row, 3).setConstant(params.r_zaru_radps * params.r_zaru_radps);
            row += 3;
        }
        if (zupt) {
            h.block(row, L::vel, 3, 3).setIdentity();
            z.segment(row, 3) = state.velocity_mps;
            r.segment(row, 3).setConstant(params.r_zupt_mps * params.r_zupt_mps);
        }
        const Eigen::MatrixXd s = h * p * h.transpose() + Eigen::MatrixXd(r.asDiagonal());
        const Eigen::MatrixXd gain = s.llt().solve(h * p).transpose();  // K = P H^T S^-1
        const Vector dx = gain * z;
        p = josephForm(p, gain, h, r);
        p = 0.5 * (p + p.transpose());
        applyCorrection(dx);
        return dx;
    }

    /// The filter's signs: attitude, position and velocity errors are estimate - truth.
    void applyCorrection(const Vector& dx)
    {
        state.bodyToNav = padeRotation(-dx.template segment<3>(L::att)) * state.bodyToNav;
        reorthonormalize(state.bodyToNav);
        state.position_m -= dx.template segment<3>(L::pos);
        state.velocity_mps -= dx.template segment<3>(L::vel);
        if constexpr (L::biases) {
            state.gyroBias_radps += dx.template segment<3>(L::gyroBias);
            state.accBias_mps2 += dx.template segment<3>(L::accBias);
        }
    }
};

template <int N>
DenseReferenceOutput run(const Recording& recording, const Parameters& params)
{
    using Filter = DenseFilter<N>;
    using Vector = typename Filter::Vector;
    const std::vector<ImuSample>& samples = recording.samples;
    const StanceFlags flags = detectStance(samples, params);
    const std::size_t start = alignmentStart(flags.stance);
    Filter filter(params, alignInitialAttitude(samples, flags.stance, params).bodyToNav);

    DenseReferenceOutput output;
    std::vector<typename Filter::Stored> stored(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
        typename Filter::Stored& now = stored[k];
        now.transition.setIdentity();
        const double dt_s = k > start ? samples[k].time_s - samples[k - 1].time_s : 0.0;
        if (dt_s > 0.0)
            now.transition = filter.propagate(samples[k], dt_s);
        now.predicted = filter.p;
        now.correction.setZero();
        if (k >= start && flags.stance[k] && (params.use_zupt || params.use_zaru))
            now.correction = filter.update(samples[k]);
        now.filtered = filter.p;
        output.position_m.push_back(filter.state.position_m);
        output.velocity_mps.push_back(filter.state.velocity_mps);
    }
    if (params.estimatorKind() != EstimatorKind::Smoother || samples.empty())
        return output;

    // RTS backward: r(k) = G(k) (dx(k+1) + r(k+1)), G(k) = P(k|k) Phi^T P(k+1|k)^-1. LDLT: at the
    // start P(k+1|k) may be singular (no initial uncertainty), and then so is P(k|k).
    Vector next = Vector::Zero();
    for (std::size_t k = samples.size() - 1; k-- > 0;) {
        const typename Filter::Stored& after = stored[k + 1];
        const typename Filter::Matrix gainT =
            after.predicted.ldlt().solve(after.transition * stored[k].filtered);
        const Vector correction = gainT.transpose() * (after.correction + next);
        output.position_m[k] -= correction.template segment<3>(Layout<N>::pos);
        output.velocity_mps[k] -= correction.template segment<3>(Layout<N>::vel);
        next = correction;
    }
    return output;
}

}  // namespace

DenseReferenceOutput runDenseReference(const Recording& recording, const Parameters& params)
{
    DenseReferenceOutput output;
    if (params.use_hdr || params.use_iper || params.use_zuna || params.use_baro || params.use_mag_heading)
        output.error = "the dense reference implements the ZUPT/ZARU source only";
    else if (params.estimatorKind() == EstimatorKind::Feliz)
        output.error = "the dense reference implements the Kalman filter and smoother only";
    if (!output.error.empty())
        return output;
    return params.filterStates() == FilterStates::Fifteen ? run<15>(recording, params) : run<9>(recording, params);
}

}  // namespace footpath
