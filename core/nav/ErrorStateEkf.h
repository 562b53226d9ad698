#pragma once

#include "nav/Parameters.h"
#include "nav/UpdateRecord.h"

#include <Eigen/Core>
#include <Eigen/Dense>

#include <vector>

namespace footpath {

/// Nominal navigation state carried by the strapdown mechanization.
struct NavState {
    Eigen::Matrix3d bodyToNav = Eigen::Matrix3d::Identity();
    Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
    Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();
    Eigen::Vector3d gyroBias_radps = Eigen::Vector3d::Zero();
    Eigen::Vector3d accBias_mps2 = Eigen::Vector3d::Zero();
};

/// What the covariance propagation of one step used: enough to redo it (the smoother's backward
/// pass recomputes P(k+1|k) from P(k|k) instead of storing both).
struct PropagationStep {
    Eigen::Vector3d navSpecificForce = Eigen::Vector3d::Zero();  ///< a_n of eq. 27
    Eigen::Matrix3d bodyToNav = Eigen::Matrix3d::Identity();     ///< attitude after the strapdown step
    double dt_s = 0.0;                                           ///< 0: no propagation (repeated timestamp)
};

/// Strapdown mechanization plus the 15-state error-state EKF of Guo 2015 (sections 2.2, 2.4-2.6).
///
/// Error state dx = [dphi, dw_b, dr, dv, da_b] with these definitions (docs/method.md, "The pipeline"):
///   dphi, dr, dv are estimate - truth, with C_est = (I + S(dphi)) C_true;
///   dw_b, da_b are truth - estimate.
/// They give exactly the transition blocks of eq. 26 with the signs as printed
/// (+dt C, +dt I, -dt S(a_n), +dt C), and the feedback r -= dr, v -= dv, biases += d(bias),
/// C = (2I - S(dphi)) (2I + S(dphi))^-1 C. A static IMU and a constant gyro bias test pin this down.
class ErrorStateEkf {
public:
    static constexpr int kAtt = 0;
    static constexpr int kGyroBias = 3;
    static constexpr int kPos = 6;
    static constexpr int kVel = 9;
    static constexpr int kAccBias = 12;
    static constexpr int kStates = 15;
    using Matrix15 = Eigen::Matrix<double, kStates, kStates>;
    using Vector15 = Eigen::Matrix<double, kStates, 1>;

    ErrorStateEkf(const Parameters& params, const Eigen::Matrix3d& initialAttitude);

    /// The filter's state index of running state i of an N-state filter (9 or 15): from position
    /// on, the 9-state filter's running states skip the gyro bias block, whose rows of P, and so of
    /// every gain, stay zero.
    template <int N>
    static constexpr int filterIndex(int i)
    {
        return N == kStates || i < kGyroBias ? i : i + 3;
    }
    static constexpr bool isPosition(int state) { return state >= kPos && state < kPos + 3; }
    /// The inverse of filterIndex: state's index among the running states of an N-state filter,
    /// -1 for a state it does not run.
    template <int N>
    static constexpr int runningIndex(int state)
    {
        if (N == kStates || state < kGyroBias)
            return state;
        return state < kPos || state >= kAccBias ? -1 : state - 3;
    }

    /// Eq. 6-11 and 32: removes the bias estimates, integrates attitude (Padé), velocity and
    /// position over dt, and propagates the covariance with the structured transition matrix.
    void propagate(const Eigen::Vector3d& acc_mps2, const Eigen::Vector3d& gyr_radps, double dt_s);

    /// Eq. 34 ZUPT: the foot is at rest, velocity should be zero.
    void updateZeroVelocity();
    /// Eq. 34 ZARU: the foot is at rest, the bias-compensated rate should be zero.
    void updateZeroAngularRate(const Eigen::Vector3d& gyr_radps);
    /// ZUPT and ZARU as one 6-row update (eq. 34-35).
    void updateZeroVelocityAndRate(const Eigen::Vector3d& gyr_radps);
    /// Any other measurement, z = H dx + noise: innovation is the predicted minus the measured value
    /// in the error convention above (so dx = estimate - truth gives z = H dx), H dense (rows x 15),
    /// noiseVariance one R entry per row. For the sources that see parts of blocks (a yaw row alone,
    /// one horizontal axis); dense, so meant for a few updates per stride, not every sample.
    /// With gate_probability set, a measurement whose normalised innovation y' S^-1 y exceeds that
    /// quantile of the chi-square distribution (rows degrees of freedom) is not applied: false.
    bool updateRows(const Eigen::MatrixXd& h, const Eigen::VectorXd& innovation, const Eigen::VectorXd& noiseVariance);

    /// What the innovation gate of updateRows did since the filter started.
    struct GateCounts {
        std::size_t tested = 0;    ///< measurements put to the gate
        std::size_t rejected = 0;  ///< of them, not applied
    };
    const GateCounts& gateCounts() const { return gateCounts_; }

    const NavState& state() const { return state_; }
    const Matrix15& covariance() const { return covariance_; }
    /// The last propagation's inputs (dt 0 until the first, and after a skipped one).
    const PropagationStep& lastPropagation() const { return lastPropagation_; }
    /// Keep a record of each measurement update since the last propagate(), as the smoother's
    /// backward pass reads it (off by default: only the smoother needs them).
    void setRecordUpdates(bool record) { recordUpdates_ = record; }
    /// The records of the updates since the last propagate(), in the order they were made, one
    /// after the other (update_record's layout; empty unless recorded).
    const update_record::Records& recordedUpdates() const { return updateRecords_; }
    /// Whether one of those updates measures position.
    bool recordedUpdatesObservePosition() const { return recordsObservePosition_; }
    /// Process noise variance added over a step of dt_s (diagonal of Q).
    Vector15 processVariance(double dt_s) const;

    /// Navigation-frame specific force of the last propagation (a_n = C f, eq. 27).
    const Eigen::Vector3d& lastNavAcceleration() const { return lastPropagation_.navSpecificForce; }

    /// Transition matrix of eq. 26 for the current attitude and a navigation-frame specific force,
    /// as a dense matrix: for tests and documentation; propagate() uses the block structure.
    Matrix15 transitionMatrix(const Eigen::Vector3d& navSpecificForce, double dt_s) const;

private:
    /// Phi P Phi^T + Q for one step with the block structure of eq. 26 (Phi = I + four 3x3 blocks).
    void propagateCovariance(const PropagationStep& step, const Vector15& processVariance);
    /// Phi P Phi^T of the 15-state filter.
    void propagateAllBlocks(const PropagationStep& step);
    /// Phi P Phi^T of the 9-state filter: no bias terms, the bias blocks stay zero.
    void propagateNavigationBlocks(const PropagationStep& step);
    template <int Rows>
    void update(const Eigen::Matrix<int, Rows / 3, 1>& blockOffsets, const Eigen::Matrix<double, Rows, 1>& innovation,
                const Eigen::Matrix<double, Rows, 1>& noiseVariance);
    /// The update on the N states the filter runs (9 or 15), on fixed-size blocks Eigen unrolls.
    template <int N, int Rows>
    void updateRunning(const Eigen::Matrix<int, Rows / 3, 1>& blockOffsets, const Eigen::Matrix<double, Rows, 1>& innovation,
                       const Eigen::Matrix<double, Rows, 1>& noiseVariance);
    /// Appends the record of a block update (runningGain: K on the running states).
    template <int N, int Rows>
    void recordUpdate(const Eigen::Matrix<int, Rows / 3, 1>& blockOffsets, const Eigen::Matrix<double, N, Rows>& runningGain,
                      const Eigen::Matrix<double, Rows, 1>& innovation,
                      const Eigen::Matrix<double, Rows, Rows>& choleskyFactor);
    void appendRecord(const update_record::GeneralUpdate& update);
    /// The innovation gate: whether the measurement may be applied (counted in gateCounts_).
    bool passesGate(const Eigen::LDLT<Eigen::MatrixXd>& sFactor, const Eigen::VectorXd& innovation);
    int runningStates() const { return biasStates_ ? kStates : 9; }
    void applyCorrection(const Vector15& dx);

    Parameters params_;
    NavState state_;
    Matrix15 covariance_;
    Eigen::Matrix<double, kStates, 1> processVariancePerStep_;  ///< at the 10 ms reference step
    PropagationStep lastPropagation_;
    /// false: the 9-state filter, whose bias rows of P, and so of every gain, stay exactly zero
    /// (the propagation and the update skip them, which changes no number).
    bool biasStates_ = true;
    bool recordUpdates_ = false;
    update_record::Records updateRecords_;  ///< reused: grows to the most one sample had
    bool recordsObservePosition_ = false;
    /// The gate's threshold on y' S^-1 y for 1..kGatedRows rows (index rows - 1); empty: no gate.
    static constexpr int kGatedRows = 6;
    std::vector<double> gateThresholds_;
    GateCounts gateCounts_;
};

}  // namespace footpath
