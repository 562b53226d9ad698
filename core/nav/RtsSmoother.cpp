#include "nav/RtsSmoother.h"

#include "nav/Attitude.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <future>
#include <type_traits>

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

/// The states the backward pass carries. mu and L are zero in the rows of a state no update observes
/// and no observed state's transition reads: with ZUPT (and ZARU) alone that is the position, which
/// Phi only adds to itself (Phi(pos, pos) = I is its column's only entry) and H never selects. So
/// unless an update measures position (height, IPER), mu and L live on the other states and the
/// smoothed variances need L times 6 (or 12) columns of P instead of 9 (or 15).
/// N: the states the filter runs (9 or 15); Position: the backward pass carries position too.
/// Offsets are in the carried states' order (the filter's, without position when it is dropped);
/// -1 where a block is not carried.
template <int N, bool Position>
struct Carried {
    static constexpr bool biases = N == 15;
    static constexpr int running = N;
    static constexpr int size = Position ? N : N - 3;  ///< M, the states mu and L have
    static constexpr int runningPos = biases ? 6 : 3;  ///< position's offset among the running states
    static constexpr int att = 0, gyroBias = biases ? 3 : -1;
    static constexpr int pos = Position ? runningPos : -1;
    static constexpr int vel = Position ? runningPos + 3 : runningPos;
    static constexpr int accBias = biases ? vel + 3 : -1;
    /// The running state of carried state i.
    static constexpr int runningIndex(int i) { return Position || i < runningPos ? i : i + 3; }
    /// The carried state of running state i, -1 for position when it is dropped.
    static constexpr int carriedIndex(int i)
    {
        if (Position || i < runningPos)
            return i;
        return i < runningPos + 3 ? -1 : i - 3;
    }
};

/// The upper triangle of the running states' block of P, column by column, from out; returns the
/// end. The running states' indices are known at compile time, so the loop unrolls.
template <int N>
double* storePackedCovariance(const ErrorStateEkf::Matrix15& p, double* out)
{
    constexpr auto filterIndex = &ErrorStateEkf::filterIndex<N>;
#pragma GCC unroll 15
    for (int j = 0; j < N; ++j)
#pragma GCC unroll 15
        for (int i = 0; i <= j; ++i)
            *out++ = p(filterIndex(i), filterIndex(j));
    return out;
}

/// Asks for the cache lines of values (count doubles) ahead of their use.
void prefetch(const double* values, std::size_t count)
{
    constexpr std::size_t kLine = 64 / sizeof(double);
    for (std::size_t i = 0; i < count; i += kLine)
        __builtin_prefetch(values + i);
}

constexpr int kMaxRows = update_record::kMaxRows;

}  // namespace

RtsSmoother::RtsSmoother(const Parameters& params, ErrorStateEkf& ekf)
    : active_(activeStates(params.filterStates()))
    , storesPropagationAttitude_(params.filterStates() == FilterStates::Fifteen)
{
    ekf.setRecordUpdates(true);
}

void RtsSmoother::reserve(std::size_t samples, std::size_t updates)
{
    records_.reserve(samples * recordStride());
    updateStart_.reserve(samples + 1);
    updateData_.reserve(updates * bytesPerUpdate(storesPropagationAttitude_ ? 6 : 3) / sizeof(double));
}

void RtsSmoother::capture(const ErrorStateEkf& ekf)
{
    records_.resize(records_.size() + recordStride());
    double* out = records_.data() + samples_++ * recordStride();
    out = active_.size() == 15 ? storePackedCovariance<15>(ekf.covariance(), out)
                               : storePackedCovariance<9>(ekf.covariance(), out);
    const auto store = [&out](const auto& values) {
        for (int i = 0; i < values.size(); ++i)
            *out++ = values(i);
    };
    store(Eigen::Quaterniond(ekf.state().bodyToNav).coeffs());
    const PropagationStep& step = ekf.lastPropagation();
    store(step.navSpecificForce);
    *out++ = step.dt_s;
    if (storesPropagationAttitude_)
        store(Eigen::Quaterniond(step.bodyToNav).coeffs());
    // The filter wrote its updates' records as the backward pass reads them (update_record).
    const update_record::Records& updates = ekf.recordedUpdates();
    updateData_.insert(updateData_.end(), updates.begin(), updates.end());
    positionObserved_ = positionObserved_ || ekf.recordedUpdatesObservePosition();
    updateStart_.push_back(updateData_.size());
}

std::size_t RtsSmoother::bytesPerSample() const
{
    return recordStride() * sizeof(double) + sizeof(std::size_t);
}

std::size_t RtsSmoother::projectedBytes(std::size_t samples, std::size_t stanceSamples) const
{
    return samples * bytesPerSample() + stanceSamples * bytesPerUpdate(storesPropagationAttitude_ ? 6 : 3);
}

std::size_t RtsSmoother::bytesPerUpdate(int rows) const
{
    return update_record::length(static_cast<int>(active_.size()), rows, true) * sizeof(double);
}

Eigen::Matrix3d RtsSmoother::attitude(std::size_t k) const
{
    return Eigen::Map<const Eigen::Quaterniond>(record(k) + packedSize()).toRotationMatrix();
}

PropagationStep RtsSmoother::propagationInto(std::size_t k) const
{
    const double* values = record(k) + packedSize() + 4;
    PropagationStep step;
    step.navSpecificForce = Eigen::Map<const Eigen::Vector3d>(values);
    step.dt_s = values[3];
    if (storesPropagationAttitude_)
        step.bodyToNav = Eigen::Map<const Eigen::Quaterniond>(values + 4).toRotationMatrix();
    return step;
}

template <int N>
void RtsSmoother::writeSmoothedState(Result& result, std::size_t k, const Eigen::Matrix<double, N, 1>& correction) const
{
    using E = ErrorStateEkf;
    // The running states in the filter's order: attitude, (gyro bias,) position, velocity, (acc bias).
    constexpr int pos = N == E::kStates ? E::kPos : E::kPos - 3;
    constexpr int vel = pos + 3;
    // The filter's signs (ErrorStateEkf::applyCorrection): attitude, position and velocity errors
    // are estimate - truth, bias errors truth - estimate.
    // Not re-orthonormalised: both factors are rotations to rounding (a unit quaternion's matrix, a
    // Cayley transform), and this product is read for its angles once, never multiplied on.
    result.rollPitchYaw_rad[k] = rollPitchYaw(padeRotation(-correction.template segment<3>(0)) * attitude(k));
    result.position_m[k] -= correction.template segment<3>(pos);
    result.velocity_mps[k] -= correction.template segment<3>(vel);
    if constexpr (N == E::kStates) {
        result.gyroBias_radps[k] += correction.template segment<3>(E::kGyroBias);
        result.accBias_mps2[k] += correction.template segment<3>(E::kAccBias);
    }
}

bool RtsSmoother::smooth(Result& result, const std::function<bool(double fraction)>& keepGoing,
                         const std::function<void()>& afterStates, Threads threads, Variances variances) const
{
    const bool withVariances = variances == Variances::Compute;
    if (samples_ == 0 || result.position_m.size() != samples_ || (withVariances && result.errorStd.size() != samples_)) {
        if (afterStates)
            afterStates();
        return true;
    }
    if (!withVariances || threads == Threads::One) {
        const bool completed = withVariances ? backwardPass(Pass::Both, &result, &result.errorStd, keepGoing)
                                             : backwardPass(Pass::States, &result, nullptr, keepGoing);
        if (completed && afterStates)
            afterStates();
        return completed;
    }
    // The variances on a second thread: the passes share nothing but what capture() stored. The
    // fraction reported is the mean of the two passes'; keepGoing is asked on this thread only.
    std::atomic_bool stop{false};
    std::atomic<double> variancesDone{0.0};
    auto variancesPass = std::async(std::launch::async, [this, &result, &stop, &variancesDone] {
        return smoothVariances(result.errorStd, [&stop, &variancesDone](double fraction) {
            variancesDone.store(fraction, std::memory_order_relaxed);
            return !stop.load(std::memory_order_relaxed);
        });
    });
    const auto keepGoingAt = [&](double statesDone) {
        return !keepGoing || keepGoing(0.5 * (statesDone + variancesDone.load(std::memory_order_relaxed)));
    };
    bool completed = smoothStates(result, keepGoingAt);
    if (completed && afterStates)
        afterStates();
    using namespace std::chrono_literals;
    while (completed && variancesPass.wait_for(20ms) != std::future_status::ready)
        completed = keepGoingAt(1.0);
    stop = !completed;
    return variancesPass.get() && completed;
}

bool RtsSmoother::smoothStates(Result& result, const std::function<bool(double fraction)>& keepGoing) const
{
    if (samples_ == 0 || result.position_m.size() != samples_)
        return true;
    return backwardPass(Pass::States, &result, nullptr, keepGoing);
}

bool RtsSmoother::smoothVariances(std::vector<Eigen::Matrix<float, 15, 1>>& errorStd,
                                  const std::function<bool(double fraction)>& keepGoing) const
{
    if (samples_ == 0 || errorStd.size() != samples_)
        return true;
    return backwardPass(Pass::Variances, nullptr, &errorStd, keepGoing);
}

bool RtsSmoother::backwardPass(Pass pass, Result* result, std::vector<Eigen::Matrix<float, 15, 1>>* errorStd,
                               const std::function<bool(double fraction)>& keepGoing) const
{
    // Each pass on the carried states the filter's states and updates call for (Carried).
    const auto on = [&](auto carried) {
        using C = decltype(carried);
        switch (pass) {
        case Pass::States: return backwardPassAs<C, true, false>(result, errorStd, keepGoing);
        case Pass::Variances: return backwardPassAs<C, false, true>(result, errorStd, keepGoing);
        case Pass::Both: break;
        }
        return backwardPassAs<C, true, true>(result, errorStd, keepGoing);
    };
    if (active_.size() == 15)
        return positionObserved_ ? on(Carried<15, true>()) : on(Carried<15, false>());
    return positionObserved_ ? on(Carried<9, true>()) : on(Carried<9, false>());
}

template <class C, class Rows>
void RtsSmoother::carriedRowsOf(std::size_t k, Rows& carriedRows) const
{
    // P(k|k) is symmetric: its rows of the carried states are its columns of them.
    const double* packed = record(k);
#pragma GCC unroll 15
    for (int j = 0; j < C::running; ++j)
#pragma GCC unroll 15
        for (int i = 0; i <= j; ++i, ++packed) {
            if (C::carriedIndex(i) >= 0)
                carriedRows(C::carriedIndex(i), j) = *packed;
            if (C::carriedIndex(j) >= 0)
                carriedRows(C::carriedIndex(j), i) = *packed;
        }
}

namespace {

/// Phi = I + the blocks of eq. 26: (att, gyro bias) and (vel, acc bias) dt C, (pos, vel) dt I,
/// (vel, att) -dt S(a_n); the backward pass needs only the blocks between carried states (C::pos
/// is -1 when position is not carried).
template <class C>
struct TransitionBlocks {
    // Also transposed, as matrices: a product with a transpose expression sums in another order.
    Eigen::Matrix3d velFromAtt, velFromAttT, biasGain, biasGainT;  // biasGain: with bias states only
    double dt_s;
    explicit TransitionBlocks(const PropagationStep& step)
        : velFromAtt(-step.dt_s * skew(step.navSpecificForce)), velFromAttT(velFromAtt.transpose()), dt_s(step.dt_s)
    {
        if constexpr (C::biases) {
            biasGain = step.dt_s * step.bodyToNav;
            biasGainT = biasGain.transpose();
        }
    }
};

/// mu = Phi^T mu. Each block reads a block the later ones change, so the order matters: biases,
/// then attitude, then velocity.
template <class C>
void transitionAdjointBackward(Eigen::Matrix<double, C::size, 1>& adjoint, const TransitionBlocks<C>& phi)
{
    if constexpr (C::biases) {
        adjoint.template segment<3>(C::gyroBias) += phi.biasGainT * adjoint.template segment<3>(C::att);
        adjoint.template segment<3>(C::accBias) += phi.biasGainT * adjoint.template segment<3>(C::vel);
    }
    adjoint.template segment<3>(C::att) += phi.velFromAttT * adjoint.template segment<3>(C::vel);
    if constexpr (C::pos >= 0)
        adjoint.template segment<3>(C::vel) += phi.dt_s * adjoint.template segment<3>(C::pos);
}

/// L = Phi^T L Phi: first L Phi (columns), then Phi^T times it (rows), in transitionAdjointBackward's order.
template <class C>
void transitionInformationBackward(Eigen::Matrix<double, C::size, C::size>& l, const TransitionBlocks<C>& phi)
{
    if constexpr (C::biases) {
        l.template middleCols<3>(C::gyroBias) += l.template middleCols<3>(C::att).lazyProduct(phi.biasGain);
        l.template middleCols<3>(C::accBias) += l.template middleCols<3>(C::vel).lazyProduct(phi.biasGain);
        l.template middleCols<3>(C::att) += l.template middleCols<3>(C::vel).lazyProduct(phi.velFromAtt);
        if constexpr (C::pos >= 0)
            l.template middleCols<3>(C::vel) += phi.dt_s * l.template middleCols<3>(C::pos);
        l.template middleRows<3>(C::gyroBias) += phi.biasGainT.lazyProduct(l.template middleRows<3>(C::att));
        l.template middleRows<3>(C::accBias) += phi.biasGainT.lazyProduct(l.template middleRows<3>(C::vel));
    } else {
        l.template middleCols<3>(C::att) += l.template middleCols<3>(C::vel).lazyProduct(phi.velFromAtt);
        if constexpr (C::pos >= 0)
            l.template middleCols<3>(C::vel) += phi.dt_s * l.template middleCols<3>(C::pos);
    }
    l.template middleRows<3>(C::att) += phi.velFromAttT.lazyProduct(l.template middleRows<3>(C::vel));
    if constexpr (C::pos >= 0)
        l.template middleRows<3>(C::vel) += phi.dt_s * l.template middleRows<3>(C::pos);
}

/// One stored update (the class comment's mu~ and L~) on the carried states of C, with Rows rows:
/// fixed for the usual ZUPT (3) and ZUPT+ZARU (6) updates that select states, so Eigen unrolls
/// them; Eigen::Dynamic for any other.
template <class C, int Rows>
struct StoredUpdate {
    static constexpr int N = C::running, M = C::size;
    static constexpr int MaxRows = Rows == Eigen::Dynamic ? kMaxRows : Rows;
    using CarriedGain = Eigen::Matrix<double, M, Rows, 0, M, MaxRows>;
    using RowsMatrix = Eigen::Matrix<double, Rows, Rows, 0, MaxRows, MaxRows>;
    using RowsVector = Eigen::Matrix<double, Rows, 1, 0, MaxRows, 1>;
    using CarriedH = Eigen::Matrix<double, Rows, M, Eigen::RowMajor, MaxRows, M>;

    int rows;
    bool selects;
    const double* h;
    const double* gainData;
    CarriedGain gain;  // K's rows of the carried states: mu and L are zero in the others

    explicit StoredUpdate(const double* record)
        : rows(static_cast<int>(record[0])), selects(record[1] != 0.0), h(record + 2),
          gainData(h + (selects ? rows : rows * N)), gain(M, rows)
    {
        for (int j = 0; j < rows; ++j)
            for (int a = 0; a < M; ++a)
                gain(a, j) = gainData[N * j + C::runningIndex(a)];
    }
    Eigen::Map<const RowsVector> weightedInnovation() const { return {gainData + N * rows, rows}; }
    Eigen::Map<const RowsMatrix> inverseS() const { return {gainData + N * rows + rows, rows, rows}; }
    /// The carried state row j selects (selects only).
    int selected(int j) const { return C::carriedIndex(static_cast<int>(h[j])); }
    CarriedH carriedH() const
    {
        CarriedH hm(rows, M);
        for (int r = 0; r < rows; ++r)
            for (int a = 0; a < M; ++a)
                hm(r, a) = h[r * N + C::runningIndex(a)];
        return hm;
    }

    /// mu += H^T t with t = S^-1 z - K^T mu.
    void adjointBackward(Eigen::Matrix<double, M, 1>& adjoint) const
    {
        const RowsVector t = weightedInnovation() - gain.transpose().lazyProduct(adjoint);
        if (selects) {
            for (int j = 0; j < rows; ++j)
                adjoint(selected(j)) += t(j);
        } else {
            adjoint += carriedH().transpose().lazyProduct(t);
        }
    }

    /// L = L - B H - (B H)^T + H^T C H with B = L K and C = K^T B + S^-1.
    void informationBackward(Eigen::Matrix<double, M, M>& l) const
    {
        const CarriedGain b = l.lazyProduct(gain);
        const RowsMatrix c = gain.transpose().lazyProduct(b) + inverseS();
        if (selects) {
            for (int j = 0; j < rows; ++j) {
                l.col(selected(j)) -= b.col(j);
                l.row(selected(j)) -= b.col(j).transpose();
            }
            for (int j = 0; j < rows; ++j)
                for (int i = 0; i < rows; ++i)
                    l(selected(i), selected(j)) += c(i, j);
        } else {
            const CarriedH hm = carriedH();
            const Eigen::Matrix<double, M, M> bh = b.lazyProduct(hm);
            l -= bh + bh.transpose();
            l += hm.transpose().lazyProduct(c.lazyProduct(hm));
        }
        // The steps above keep L symmetric only in exact arithmetic, and its antisymmetric part,
        // which they do not damp, grows from rounding to overflow over a few thousand strides
        // (a 30-minute walk's smoothed variances were infinite before its 20th minute). The
        // correction does not depend on L; the variances do.
        l = 0.5 * (l + l.transpose()).eval();
    }
};

/// A sample's smoothed standard deviations into sigma, from L and P(k|k): packed is its record
/// (RtsSmoother::capture: the upper triangle column by column first, whose diagonal is read here
/// straight from the record), carriedRows P's carried rows, stored row by row.
template <class C>
void writeSmoothedStd(const double* packed, const Eigen::Matrix<double, C::size, C::size>& information,
                      const Eigen::Matrix<double, C::size, C::running, Eigen::RowMajor>& carriedRows,
                      Eigen::Matrix<float, 15, 1>& sigma)
{
    constexpr int N = C::running, M = C::size;
    constexpr auto filterIndex = &ErrorStateEkf::filterIndex<N>;
    // diag(P L P): for each state i, the quadratic form c^T L c of column i of P's carried rows;
    // all N at once, on whole rows r_a (contiguous): the sum over a of r_a (L_aa r_a + the sum over
    // b > a of 2 L_ab r_b). L is symmetric, so its upper triangle is all this reads: 21 row steps
    // for 6 carried states where the product L P took 36 (18 % fewer instructions in the pass's
    // largest part, callgrind).
    Eigen::Matrix<double, N, 1> quadratic = Eigen::Matrix<double, N, 1>::Zero();
#pragma GCC unroll 15
    for (int a = 0; a < M; ++a) {
        Eigen::Matrix<double, N, 1> weighted = information(a, a) * carriedRows.row(a).transpose();
#pragma GCC unroll 15
        for (int b = a + 1; b < M; ++b)
            weighted += (2.0 * information(a, b)) * carriedRows.row(b).transpose();
        quadratic += carriedRows.row(a).transpose().cwiseProduct(weighted);
    }
    if constexpr (N != ErrorStateEkf::kStates)
        sigma.setZero();
    for (int i = 0; i < N; ++i) {
        packed += i;  // column i's entries above the diagonal
        const double variance = *packed++ - quadratic(i);
        sigma(filterIndex(i)) = static_cast<float>(std::sqrt(std::max(0.0, variance)));
    }
}

/// Runs visit(update) on sample k's stored updates, last one first, each as the StoredUpdate
/// its rows call for.
template <class C, class Visit>
void forEachUpdateBackward(const double* first, const double* end, Visit&& visit)
{
    // Each record ends with its length.
    while (end > first) {
        const double* record = end - static_cast<std::size_t>(end[-1]);
        end = record;
        const bool selects = record[1] != 0.0;
        if (selects && record[0] == 3.0)
            visit(StoredUpdate<C, 3>(record));
        else if (selects && record[0] == 6.0)
            visit(StoredUpdate<C, 6>(record));
        else
            visit(StoredUpdate<C, Eigen::Dynamic>(record));
    }
}

}  // namespace

template <class C, class Visit>
void RtsSmoother::updatesBackward(std::size_t k, Visit&& visit) const
{
    forEachUpdateBackward<C>(updateData_.data() + updateStart_[k], updateData_.data() + updateStart_[k + 1],
                             std::forward<Visit>(visit));
}

template <class C, bool States, bool Variances>
bool RtsSmoother::backwardPassAs(Result* result, std::vector<Eigen::Matrix<float, 15, 1>>* errorStd,
                                 const std::function<bool(double fraction)>& keepGoing) const
{
    constexpr int N = C::running, M = C::size;
    const std::size_t n = samples_;
    // After the last sample nothing is measured: mu and L start at zero. A pass carries only the
    // one it needs; each sample's steps on mu and on L read nothing of the other.
    Eigen::Matrix<double, M, 1> adjoint = Eigen::Matrix<double, M, 1>::Zero();
    Eigen::Matrix<double, M, M> information = Eigen::Matrix<double, M, M>::Zero();
    // P(k|k) in the carried states' rows: column by column for the states' correction (each
    // column's dot product with mu sums as it always has, so the states keep their last bits),
    // row by row for the variances' quadratic forms; a pass that computes both copies them over.
    using ColumnWise = Eigen::Matrix<double, M, N>;
    using RowWise = Eigen::Matrix<double, M, N, Eigen::RowMajor>;
    std::conditional_t<States, ColumnWise, RowWise> carriedRows;
    for (std::size_t k = n; k-- > 0;) {
        if (k >= 2)  // the pass walks memory backwards, which the hardware prefetcher follows poorly
            prefetch(record(k - 2), recordStride());
        if (k + 1 < n)
            if (const PropagationStep step = propagationInto(k + 1); step.dt_s > 0.0) {
                const TransitionBlocks<C> phi(step);
                if constexpr (States)
                    transitionAdjointBackward<C>(adjoint, phi);
                if constexpr (Variances)
                    transitionInformationBackward<C>(information, phi);
            }
        carriedRowsOf<C>(k, carriedRows);
        if constexpr (States)
            writeSmoothedState<N>(*result, k, carriedRows.transpose().lazyProduct(adjoint));
        if constexpr (Variances && States)
            writeSmoothedStd<C>(record(k), information, RowWise(carriedRows), (*errorStd)[k]);
        else if constexpr (Variances)
            writeSmoothedStd<C>(record(k), information, carriedRows, (*errorStd)[k]);
        updatesBackward<C>(k, [&](const auto& update) {
            if constexpr (States)
                update.adjointBackward(adjoint);
            if constexpr (Variances)
                update.informationBackward(information);
        });
        if (keepGoing && k % kProgressInterval == 0 && !keepGoing(static_cast<double>(n - k) / static_cast<double>(n)))
            return false;
    }
    return true;
}

}  // namespace footpath
