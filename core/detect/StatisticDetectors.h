#pragma once

#include "Recording.h"
#include "detect/StanceDetector.h"
#include "nav/Parameters.h"

#include <cstddef>
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
double zeroVelocityStatistic(DetectorKind kind, const std::deque<ImuSample>& samples, std::size_t first,
                             std::size_t last, const Parameters& params);

/// A stance detector built on one of the statistics above, run causally (offline, detectStance
/// pushes the whole recording through it, so live and offline flags are the same by construction).
/// Four stages, each releasing a sample once the samples its window needs have arrived:
///  1. the statistic over the centred window of zv_window_s;
///  2. the threshold: with zv_adaptive, over the centred zv_adapt_window_s (about a gait cycle) the
///     running minimum of log10 T (the quietest moment of the current motion) plus
///     zv_adapt_offset_dec decades plus zv_adapt_fraction of the way to the running maximum (the
///     busiest), clamped to [zv_log_always, zv_log_never]: the threshold rises with the motion, so
///     running gets a threshold of its own, while a standing foot is always at rest and a clearly
///     moving one never is; without it, zv_log_threshold;
///  3. the decision log10 T < threshold (c1 = c2 = c3 = c: one statistic, one condition);
///  4. stance runs shorter than zv_min_stance_s are dropped (seed 002's thr_time).
/// The decision trails the newest sample by latency_s(params).
class StatisticStanceDetector : public CausalStanceDecider {
public:
    explicit StatisticStanceDetector(const Parameters& params);

    void push(const ImuSample& sample, std::deque<SampleStanceFlags>& decided) override;
    void finish(std::deque<SampleStanceFlags>& decided) override;

    static double latency_s(const Parameters& params);

private:
    struct Scored {
        double time_s;
        float logStatistic;
    };
    void scoreReadySamples(bool endOfData);
    void thresholdReadySamples(bool endOfData, std::deque<SampleStanceFlags>& decided);
    float nextThreshold(std::size_t centre);
    void dropShortRuns(const SampleStanceFlags& flags, double time_s, std::deque<SampleStanceFlags>& decided);
    void releaseHeldRun(bool keepAsStance, std::deque<SampleStanceFlags>& decided);

    Parameters params_;
    DetectorKind kind_;
    double statisticHalf_s_;
    double thresholdHalf_s_;

    // Stage 1: samples around the next centre (index statisticCentre_ in samples_).
    std::deque<ImuSample> samples_;
    std::size_t statisticCentre_ = 0;

    // Stage 2: scored samples waiting for their threshold window, and monotonic queues of the
    // candidates for the running minimum and maximum (absolute indices: scored_ starts at scoredBase_).
    std::deque<Scored> scored_;
    std::size_t scoredBase_ = 0;
    std::size_t thresholdCentre_ = 0;  ///< absolute index of the next sample to threshold
    std::size_t nextToEnter_ = 0;      ///< absolute index of the next value to enter the queues
    std::deque<std::size_t> minimumCandidates_;
    std::deque<std::size_t> maximumCandidates_;

    // Stage 4: a stance run not yet known to be long enough, held back.
    std::deque<SampleStanceFlags> heldRun_;
    double heldRunStart_s_ = 0.0;
    bool runConfirmed_ = false;  ///< the current stance run has lasted zv_min_stance_s
};

}  // namespace footpath
