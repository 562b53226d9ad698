#pragma once

#include "Recording.h"
#include "detect/StanceDetector.h"
#include "methods/MethodRegistry.h"
#include "nav/Parameters.h"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <deque>
#include <vector>

namespace footpath {

/// Zero-velocity test statistics of the field, over a window of samples, each normalised by the
/// sensor noise (zv_sigma_acc_mps2, zv_sigma_gyr_radps) so that their logarithms share one scale and
/// one set of threshold bounds serves them all. A foot at rest gives values near 1-100; a swinging
/// foot 1e5 and more. pyshoe's definitions (ins_tools/EKF.py), written out:
///   SHOE  (Skog et al. 2010): (1/W) sum |a_k - g a_mean/|a_mean||^2 / sa^2 + |w_k|^2 / sw^2
///   ARED: (1/W) sum |w_k|^2 / sw^2
///   AMVD: (1/W) sum |a_k - a_mean|^2 / sa^2
///   MBGTD: max over the split points of the window of the mean distance between the accelerometer
///          samples before and after the split, squared and divided by sa^2 (so it is a variance like
///          the others; pyshoe compares the distance itself).
/// pyshoe evaluates them over non-overlapping blocks; here every sample gets its own centred window.
/// The chosen statistic with its constants worked out once: the detector evaluates it every sample.
class ZeroVelocityStatistic {
public:
    explicit ZeroVelocityStatistic(const Parameters& params);
    /// The statistic over the count samples from window on (count >= 1).
    double operator()(const ImuSample* window, std::size_t count) const { return statistic_(constants_, window, count); }

private:
    StatisticConstants constants_;
    ZeroVelocityStatisticFunction statistic_;  ///< the chosen detector's (SHOE for C1/C2/C3's thresholds)
};

/// The noise normalisation of params, worked out once.
StatisticConstants statisticConstants(const Parameters& params);
/// The statistics of the field (definitions above); the detector registry names them.
double shoeStatistic(const StatisticConstants& constants, const ImuSample* window, std::size_t count);
double aredStatistic(const StatisticConstants& constants, const ImuSample* window, std::size_t count);
double amvdStatistic(const StatisticConstants& constants, const ImuSample* window, std::size_t count);
double mbgtdStatistic(const StatisticConstants& constants, const ImuSample* window, std::size_t count);

/// The values of a stream from some index on, in one vector: appended at the back, taken from the
/// front by moving a head, the taken ones erased in batches of at least half the vector, so each
/// value moves O(1) times and the rest stays contiguous. Indices are those of the whole stream.
template <typename T>
class SlidingBuffer {
public:
    static constexpr std::size_t kMinimumDrop = 64;

    bool empty() const { return head_ == values_.size(); }
    std::size_t first() const { return base_ + head_; }  ///< index of front()
    std::size_t end() const { return base_ + values_.size(); }
    const T& operator[](std::size_t index) const { return values_[index - base_]; }
    const T& front() const { return values_[head_]; }
    const T& back() const { return values_.back(); }
    const T* data() const { return values_.data() + head_; }  ///< front() onwards, contiguous
    std::size_t stored() const { return values_.size(); }     ///< with those not yet erased

    void push_back(const T& value) { values_.push_back(value); }
    void pop_front() { dropBefore(first() + 1); }
    /// Forgets the values before index (at most end()).
    void dropBefore(std::size_t index)
    {
        head_ = index - base_;
        if (head_ < kMinimumDrop || 2 * head_ < values_.size())
            return;
        values_.erase(values_.begin(), values_.begin() + static_cast<std::ptrdiff_t>(head_));
        base_ += head_;
        head_ = 0;
    }

private:
    std::vector<T> values_;
    std::size_t base_ = 0;  ///< index of values_.front() in the stream
    std::size_t head_ = 0;  ///< position of front() in values_
};

/// The smallest (Order = std::less) or largest (std::greater) value in a window sliding forward
/// in time, as a monotonic queue: the values that may still become the extreme, oldest first, each
/// more extreme than the ones after it. O(1) per value; one vector, its used part moved to the
/// front when it reaches the end.
template <typename Order>
class SlidingExtremum {
public:
    void enter(double time_s, float value)
    {
        while (end_ > head_ && !Order()(entries_[end_ - 1].value, value))
            --end_;  // never the extreme again: the new value is as extreme and stays longer
        if (end_ == entries_.size())
            makeRoom();
        entries_[end_++] = {time_s, value};
    }
    /// Forgets the values before start_s; the newest value entered always stays.
    void leaveBefore(double start_s)
    {
        while (head_ + 1 < end_ && entries_[head_].time_s < start_s)
            ++head_;
    }
    float extreme() const { return entries_[head_].value; }

private:
    struct Entry {
        double time_s;
        float value;
    };
    void makeRoom()
    {
        std::move(entries_.begin() + static_cast<std::ptrdiff_t>(head_),
                  entries_.begin() + static_cast<std::ptrdiff_t>(end_), entries_.begin());
        end_ -= head_;
        head_ = 0;
        if (2 * end_ >= entries_.size())
            entries_.resize(std::max<std::size_t>(64, 2 * entries_.size()));
    }

    std::vector<Entry> entries_;
    std::size_t head_ = 0;
    std::size_t end_ = 0;
};

/// A stance detector built on one of the statistics above, run causally. Offline, detect() runs
/// the same stages over the whole recording in place, so live and offline flags are the same by
/// construction. Four stages, each releasing a sample once the samples its window needs have arrived:
///  1. the statistic over the centred window of zv_window_s;
///  2. the threshold: with zv_adaptive, over the centred zv_adapt_window_s (about a gait cycle) the
///     running minimum of log10 T (the quietest moment of the current motion) plus
///     zv_adapt_offset_dec decades plus zv_adapt_fraction of the way to the running maximum (the
///     busiest), clamped to [zv_log_always, zv_log_never]: the threshold rises with the motion, so
///     running gets a threshold of its own, while a standing foot is always at rest and a clearly
///     moving one never is; without it, zv_log_threshold;
///  3. the decision log10 T < threshold (c1 = c2 = c3 = c: one statistic, one condition);
///  4. stance runs shorter than zv_min_stance_s are dropped (the thr_time of the five-method EKF paper).
/// The decision trails the newest sample by latency_s(params).
class StatisticStanceDetector : public CausalStanceDecider {
public:
    explicit StatisticStanceDetector(const Parameters& params);

    void push(const ImuSample& sample, std::deque<SampleStanceFlags>& decided) override;
    void finish(std::deque<SampleStanceFlags>& decided) override;

    /// The flags of a whole recording: the stages of push() and finish(), reading the samples in
    /// place instead of copying them.
    static StanceFlags detect(const std::vector<ImuSample>& samples, const Parameters& params);
    /// detect() into flags, telling decided after each batch (detectStanceInto).
    static bool detectInto(const std::vector<ImuSample>& samples, const Parameters& params, StanceFlags& flags,
                           const DecidedCallback& decided);

    static double latency_s(const Parameters& params);

    /// Samples and scores held: those the open windows need, plus at most as many (or
    /// SlidingBuffer::kMinimumDrop) waiting to be erased in one go.
    std::size_t bufferedSamples() const { return samples_.stored() + scored_.stored(); }

private:
    struct Scored {
        double time_s;
        float logStatistic;
    };
    template <typename Emit>
    void advance(const ImuSample* samples, std::size_t base, std::size_t end, bool endOfData, Emit& emit);
    void scoreReadySamples(const ImuSample* samples, std::size_t base, std::size_t end, bool endOfData);
    template <typename Emit>
    void thresholdReadySamples(bool endOfData, Emit& emit);
    float nextThreshold(double centre_s);
    template <typename Emit>
    void dropShortRuns(const SampleStanceFlags& flags, double time_s, Emit& emit);
    template <typename Emit>
    void releaseHeldRun(bool keepAsStance, Emit& emit);

    Parameters params_;
    ZeroVelocityStatistic statistic_;
    double statisticHalf_s_;
    double thresholdHalf_s_;

    // Stage 1: the next centre and its window [windowFirst_, windowEnd_), indices in the stream.
    // Live, samples_ keeps the samples from the window's start on.
    SlidingBuffer<ImuSample> samples_;
    std::size_t statisticCentre_ = 0;
    std::size_t windowFirst_ = 0;
    std::size_t windowEnd_ = 0;

    // Stage 2: scored samples from the next one to threshold on, and the running minimum and
    // maximum of their log statistic.
    SlidingBuffer<Scored> scored_;
    std::size_t nextToEnter_ = 0;  ///< index of the next scored sample to enter the queues
    SlidingExtremum<std::less<float>> minimum_;
    SlidingExtremum<std::greater<float>> maximum_;

    // Stage 4: a stance run not yet known to be long enough, held back.
    std::vector<SampleStanceFlags> heldRun_;
    double heldRunStart_s_ = 0.0;
    bool runConfirmed_ = false;  ///< the current stance run has lasted zv_min_stance_s
};

}  // namespace footpath
