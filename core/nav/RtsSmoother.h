#pragma once

#include "Result.h"
#include "nav/ErrorStateEkf.h"
#include "nav/Parameters.h"

#include <Eigen/Geometry>

#include <functional>
#include <vector>

namespace footpath {

/// Rauch-Tung-Striebel fixed-interval smoother over the error-state filter: offline, every sample's
/// estimate then uses the whole recording, so the end of a swing corrects its start (a filter sees
/// the next stance's velocity error only after the fact; the smoother spreads it back over the swing).
///
/// Error-state form: the forward filter resets its error state after each measurement, so the
/// backward pass works on corrections, not states. With s(k+1) = the correction that takes the
/// predicted state at k+1 to the smoothed one (the filter's own correction at k+1 plus the
/// smoothed correction r(k+1) on top of the filtered state), the RTS gain G(k) gives
///   r(k) = G(k) s(k+1),   G(k) = P(k|k) Phi(k)^T P(k+1|k)^-1,
///   P(k|N) = P(k|k) + G(k) (P(k+1|N) - P(k+1|k)) G(k)^T,
/// and the smoothed state is the filtered state at k with r(k) applied as the filter applies its
/// corrections (ErrorStateEkf::applyCorrection's signs).
///
/// Storage per sample: the filtered covariance of the states the filter runs (upper triangle), the
/// sample's corrections, the attitude and the propagation's specific force and step; P(k+1|k) is
/// recomputed from P(k|k) instead of stored. 9 states: 62 doubles (496 bytes) a sample, an hour at
/// 200 Hz 357 MB; 15 states: 147 doubles (1176 bytes), 847 MB (bytesPerSample()). Doubles, because
/// the backward pass inverts P(k+1|k), whose condition float rounding would spoil.
class RtsSmoother {
public:
    RtsSmoother(const Parameters& params, const ErrorStateEkf& ekf);

    void reserve(std::size_t samples);
    /// After the filter's work on a sample (propagation into it, then its measurements).
    void capture(const ErrorStateEkf& ekf);
    /// The backward pass over the captured samples: replaces the per-sample states and errorStd of
    /// result (which must hold one entry per captured sample) by the smoothed ones. Returns false
    /// if keepGoing (asked now and then) said stop; result is then partly smoothed.
    bool smooth(Result& result, const std::function<bool(double fraction)>& keepGoing = {}) const;

    std::size_t bytesPerSample() const;

private:
    using Vector15 = ErrorStateEkf::Vector15;
    using Matrix15 = ErrorStateEkf::Matrix15;

    std::size_t packedSize() const { return active_.size() * (active_.size() + 1) / 2; }
    /// The backward pass on fixed-size N x N blocks of the running states (9 or 15), which Eigen
    /// unrolls and vectorises: the dynamic-size version took five times as long.
    template <int N>
    bool smoothBackward(Result& result, const std::function<bool(double fraction)>& keepGoing) const;
    template <int N>
    Eigen::Matrix<double, N, N> filteredCovariance(std::size_t k) const;
    PropagationStep propagationInto(std::size_t k) const;
    template <int N>
    void applyTransition(Eigen::Matrix<double, N, N>& m, const PropagationStep& step) const;
    template <int N>
    void writeSmoothed(Result& result, std::size_t k, const Eigen::Matrix<double, N, 1>& correction,
                       const Eigen::Matrix<double, N, N>& covariance) const;

    std::vector<int> active_;  ///< error-state indices the filter runs (all 15, or 9 without biases)
    bool storesPropagationAttitude_ = false;  ///< only the bias blocks of Phi need it
    Vector15 processVariancePerSecond_;
    std::vector<double> packedCovariance_;
    std::vector<double> corrections_;
    std::vector<Eigen::Quaterniond> attitude_;
    std::vector<Eigen::Vector3d> navSpecificForce_;
    std::vector<double> dt_s_;
    std::vector<Eigen::Quaterniond> propagationAttitude_;
};

}  // namespace footpath
