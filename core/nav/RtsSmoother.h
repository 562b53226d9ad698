#pragma once

#include "Result.h"
#include "nav/BulkAllocator.h"
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
/// backward pass works on corrections, not states: r(k), the correction that takes the filtered
/// state at k to the smoothed one, applied as the filter applies its corrections
/// (ErrorStateEkf::applyCorrection's signs).
///
/// The RTS equations in Bierman's modified Bryson-Frazier form, which needs no inverse of P(k+1|k):
/// with the adjoint mu and its information matrix L, zero after the last sample,
///   r(k) = P(k|k) mu(k),  P(k|N) = P(k|k) - P(k|k) L(k) P(k|k),
///   mu(k) = Phi(k)^T mu~(k+1),  L(k) = Phi(k)^T L~(k+1) Phi(k),
/// and through each update of sample k (z = H dx + noise, gain K, S = H P H^T + R), last one first,
///   mu~ = mu + H^T (S^-1 z - K^T mu),  L~ = A^T L A + H^T S^-1 H,  A = I - K H.
/// The same numbers as G(k) = P(k|k) Phi^T P(k+1|k)^-1 (tests/DenseReferenceFilter), but Phi is
/// I plus a few 3x3 blocks and H selects states, so a sample costs N quadratic forms of size M (the
/// smoothed variances) and a few block products, where the gain form needs a Cholesky solve and
/// two products.
/// M: mu and L are zero in the states no update reaches (position under ZUPT/ZARU), so the pass
/// carries the other 6 of 9 (12 of 15) unless an update measures position (RtsSmoother.cpp, Carried).
///
/// Storage per sample: the filtered covariance of the states the filter runs (upper triangle), the
/// attitude, the propagation's specific force and step, where its updates start; per update its
/// rows of H (state indices when they select states), K, S^-1 z and S^-1. 9 states: 54 doubles a
/// sample plus 45 a ZUPT, about 77 (612 bytes) with stance half the time, an hour at 200 Hz 440 MB;
/// 15 states: 133 doubles plus 141 a ZUPT+ZARU. Doubles: P(k|k) - P L P cancels most digits in the
/// states the future observes.
class RtsSmoother {
public:
    /// The most a run may store (4 GiB): a recording that would need more is estimated by the
    /// filter alone, with a note (runPipeline). A fixed figure, not a share of this machine's
    /// memory, so a file gives the same result everywhere: 10 hours at 100 Hz with 9 states fit
    /// (about 2.2 GB), 10 hours at 200 Hz (4.4 GB) do not.
    static constexpr std::size_t kMemoryBudget_bytes = std::size_t(4) << 30;

    /// Switches the filter's update recording on: the backward pass runs its updates backwards.
    RtsSmoother(const Parameters& params, ErrorStateEkf& ekf);

    /// Room for this many samples and measurement updates (of the usual 3 or 6 rows).
    void reserve(std::size_t samples, std::size_t updates);
    /// After the filter's work on a sample (propagation into it, then its measurements).
    void capture(const ErrorStateEkf& ekf);
    /// The backward pass over the captured samples: replaces the per-sample states and errorStd of
    /// result (which must hold one entry per captured sample; attitude and errorStd are written
    /// for every sample) by the smoothed ones. The variances are computed on a second thread
    /// (smoothStates and smoothVariances share nothing but what capture() stored); afterStates,
    /// if given, runs on this thread as soon as the states are smoothed, while the variances may
    /// still be, so it must not touch errorStd. Returns false if keepGoing (asked now and then, on
    /// this thread) said stop; result is then partly smoothed and afterStates may not have run.
    /// Threads::One: one pass for both, then afterStates, for a caller that keeps every core busy
    /// already (AutoTune); the same numbers.
    /// Variances::Skip: the states alone, errorStd untouched (it may be empty), for a caller that
    /// reads no standard deviations; the states are the same to the last bit.
    enum class Threads { One, Two };
    enum class Variances { Compute, Skip };
    bool smooth(Result& result, const std::function<bool(double fraction)>& keepGoing = {},
                const std::function<void()>& afterStates = {}, Threads threads = Threads::Two,
                Variances variances = Variances::Compute) const;
    /// The smoothed states alone: position, velocity, biases and attitude (written for every sample).
    bool smoothStates(Result& result, const std::function<bool(double fraction)>& keepGoing = {}) const;
    /// The smoothed standard deviations alone, into errorStd (one entry per captured sample).
    bool smoothVariances(std::vector<Eigen::Matrix<float, 15, 1>>& errorStd,
                         const std::function<bool(double fraction)>& keepGoing = {}) const;

    /// Storage for each sample, and for each update of rows state-selecting rows on top.
    std::size_t bytesPerSample() const;
    /// What a run over this many samples, with a ZUPT (and ZARU for 15 states) in stanceSamples of
    /// them, stores.
    std::size_t projectedBytes(std::size_t samples, std::size_t stanceSamples) const;
    std::size_t bytesPerUpdate(int rows) const;

private:
    std::size_t packedSize() const { return active_.size() * (active_.size() + 1) / 2; }
    std::size_t recordStride() const { return packedSize() + 8 + (storesPropagationAttitude_ ? 4 : 0); }
    const double* record(std::size_t k) const { return records_.data() + k * recordStride(); }
    Eigen::Matrix3d attitude(std::size_t k) const;
    /// What a backward pass computes: the states (mu), the variances (L) or both.
    enum class Pass { States, Variances, Both };
    bool backwardPass(Pass pass, Result* result, std::vector<Eigen::Matrix<float, 15, 1>>* errorStd,
                      const std::function<bool(double fraction)>& keepGoing) const;
    /// The backward pass on fixed-size blocks of the carried states C (RtsSmoother.cpp: the running
    /// states, without position unless an update measures it), which Eigen unrolls; it writes
    /// result's states if States, errorStd if Variances.
    template <class C, bool States, bool Variances>
    bool backwardPassAs(Result* result, std::vector<Eigen::Matrix<float, 15, 1>>* errorStd,
                        const std::function<bool(double fraction)>& keepGoing) const;
    /// P(k|k)'s rows of the carried states, into an M x N matrix of either storage order: the
    /// states' correction reads its columns, the variances its rows (RtsSmoother.cpp, backwardPassAs).
    template <class C, class Rows>
    void carriedRowsOf(std::size_t k, Rows& carriedRows) const;
    PropagationStep propagationInto(std::size_t k) const;
    /// Calls visit with each stored update of sample k, last one first (RtsSmoother.cpp, StoredUpdate).
    template <class C, class Visit>
    void updatesBackward(std::size_t k, Visit&& visit) const;
    template <int N>
    void writeSmoothedState(Result& result, std::size_t k, const Eigen::Matrix<double, N, 1>& correction) const;


    std::vector<int> active_;  ///< error-state indices the filter runs (all 15, or 9 without biases)
    bool storesPropagationAttitude_ = false;  ///< only the bias blocks of Phi need it
    bool positionObserved_ = false;           ///< an update measured position (height, IPER)
    /// One record of recordStride() doubles a sample, so the backward pass reads one block per
    /// sample: the packed covariance, the attitude (quaternion), the propagation's specific force,
    /// step and (15 states) attitude.
    std::vector<double, BulkAllocator<double>> records_;
    std::size_t samples_ = 0;
    /// Sample k's updates are updateData_[updateStart_[k], updateStart_[k + 1]), each record
    /// [rows, 1 if H selects states, H (indices or rows x N), K (N x rows), S^-1 z, S^-1, length]
    /// (update_record), as the filter wrote it.
    std::vector<std::size_t> updateStart_{0};
    std::vector<double, BulkAllocator<double>> updateData_;
};

}  // namespace footpath
