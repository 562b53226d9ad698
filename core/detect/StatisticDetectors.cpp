#include "detect/StatisticDetectors.h"

#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

// Timestamps are rounded decimals: a window edge exactly on a sample must include it.
constexpr double kTimeTolerance_s = 1e-9;
// A statistic of exactly zero (a simulated, noise-free rest) has no logarithm; this stands for it.
constexpr double kSmallestStatistic = 1e-12;
// 1 / ln 10: log10 through the natural logarithm, which glibc computes in about half the time of
// log10. Within a few units in the last place of the double log10, so the float the detector keeps
// is the same but for a value within 1e-16 of a float's rounding boundary (none on the shared
// recordings, tst_stancedetector).
constexpr double kLog10OfE = 0.434294481903251827651128918916605082;
// Offline, the samples are handed to the stages this many at a time: the stages' buffers stay
// small (in cache) and the per-call overhead is shared. Any size gives the same flags.
constexpr std::size_t kOfflineBatch = 1024;

Eigen::Vector3d meanAcceleration(const ImuSample* window, std::size_t count)
{
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < count; ++k)
        sum += window[k].acc_mps2;
    return sum / static_cast<double>(count);
}

}  // namespace

StatisticConstants statisticConstants(const Parameters& params)
{
    StatisticConstants constants;
    constants.gravity_mps2 = params.gravity_mps2;
    constants.varAcc = params.zv_sigma_acc_mps2 * params.zv_sigma_acc_mps2;
    constants.varGyr = params.zv_sigma_gyr_radps * params.zv_sigma_gyr_radps;
    constants.invVarAcc = 1.0 / constants.varAcc;
    constants.invVarGyr = 1.0 / constants.varGyr;
    return constants;
}

ZeroVelocityStatistic::ZeroVelocityStatistic(const Parameters& params)
    : constants_(statisticConstants(params))
    , statistic_(chosenDetector(params).statistic ? chosenDetector(params).statistic : shoeStatistic)
{
}

double shoeStatistic(const StatisticConstants& c, const ImuSample* window, std::size_t count)
{
    const Eigen::Vector3d mean = meanAcceleration(window, count);
    const double meanNorm = mean.norm();
    const Eigen::Vector3d gravityAlongMean =
        meanNorm > 0.0 ? Eigen::Vector3d(c.gravity_mps2 * mean / meanNorm) : Eigen::Vector3d::Zero();
    double sum = 0.0;
    for (std::size_t k = 0; k < count; ++k)
        sum += (window[k].acc_mps2 - gravityAlongMean).squaredNorm() * c.invVarAcc
               + window[k].gyr_radps.squaredNorm() * c.invVarGyr;
    return sum / static_cast<double>(count);
}

double aredStatistic(const StatisticConstants& c, const ImuSample* window, std::size_t count)
{
    double sum = 0.0;
    for (std::size_t k = 0; k < count; ++k)
        sum += window[k].gyr_radps.squaredNorm();
    return sum / static_cast<double>(count) / c.varGyr;
}

double amvdStatistic(const StatisticConstants& c, const ImuSample* window, std::size_t count)
{
    const Eigen::Vector3d mean = meanAcceleration(window, count);
    double sum = 0.0;
    for (std::size_t k = 0; k < count; ++k)
        sum += (window[k].acc_mps2 - mean).squaredNorm();
    return sum / static_cast<double>(count) / c.varAcc;
}

double mbgtdStatistic(const StatisticConstants& c, const ImuSample* window, std::size_t count)
{
    double largest = 0.0;
    for (std::size_t split = 0; split + 1 < count; ++split) {
        double sum = 0.0;
        for (std::size_t i = 0; i <= split; ++i)
            for (std::size_t j = split + 1; j < count; ++j)
                sum += (window[i].acc_mps2 - window[j].acc_mps2).norm();
        const double pairs = static_cast<double>((split + 1) * (count - 1 - split));
        largest = std::max(largest, sum / pairs);
    }
    return largest * largest / c.varAcc;
}

StatisticStanceDetector::StatisticStanceDetector(const Parameters& params)
    : params_(params)
    , statistic_(params)
    , statisticHalf_s_(params.zv_window_s / 2.0)
    , thresholdHalf_s_(params.zv_adaptive ? params.zv_adapt_window_s / 2.0 : 0.0)
{
}

double StatisticStanceDetector::latency_s(const Parameters& params)
{
    return params.zv_window_s / 2.0 + (params.zv_adaptive ? params.zv_adapt_window_s / 2.0 : 0.0)
           + params.zv_min_stance_s;
}

void StatisticStanceDetector::push(const ImuSample& sample, std::deque<SampleStanceFlags>& decided)
{
    samples_.push_back(sample);
    const auto emit = [&decided](const SampleStanceFlags& flags) { decided.push_back(flags); };
    advance(samples_.data(), samples_.first(), samples_.end(), false, emit);
    samples_.dropBefore(windowFirst_);  // later windows start no earlier
}

void StatisticStanceDetector::finish(std::deque<SampleStanceFlags>& decided)
{
    const auto emit = [&decided](const SampleStanceFlags& flags) { decided.push_back(flags); };
    advance(samples_.data(), samples_.first(), samples_.end(), true, emit);
}

StanceFlags StatisticStanceDetector::detect(const std::vector<ImuSample>& samples, const Parameters& params)
{
    StanceFlags flags;
    detectInto(samples, params, flags, {});
    return flags;
}

bool StatisticStanceDetector::detectInto(const std::vector<ImuSample>& samples, const Parameters& params,
                                         StanceFlags& flags, const DecidedCallback& decided)
{
    resizeFlags(flags, samples.size());
    std::size_t next = 0;  // every sample is decided once, in order
    const auto emit = [&flags, &next](const SampleStanceFlags& sample) { setFlags(flags, next++, sample); };
    StatisticStanceDetector detector(params);
    for (std::size_t end = 0; end < samples.size();) {
        end = std::min(samples.size(), end + kOfflineBatch);
        detector.advance(samples.data(), 0, end, false, emit);
        if (decided && !decided(next))
            return false;
    }
    detector.advance(samples.data(), 0, samples.size(), true, emit);
    return !decided || decided(next);
}

/// Every stage, over the samples [base, end) of the stream (those before base are no longer read),
/// samples pointing at the one at base. At the end of data the windows are cut where the data ends.
template <typename Emit>
void StatisticStanceDetector::advance(const ImuSample* samples, std::size_t base, std::size_t end, bool endOfData,
                                      Emit& emit)
{
    scoreReadySamples(samples, base, end, endOfData);
    thresholdReadySamples(endOfData, emit);
    if (endOfData)
        releaseHeldRun(false, emit);  // a run still held at the end is shorter than zv_min_stance_s
}

/// Stage 1: the statistic of every sample whose window has closed (a later sample arrived). The
/// windows only move forward: their ends are found from the previous ones.
void StatisticStanceDetector::scoreReadySamples(const ImuSample* samples, std::size_t base, std::size_t end,
                                                bool endOfData)
{
    const auto timeAt = [samples, base](std::size_t index) { return samples[index - base].time_s; };
    while (statisticCentre_ < end) {
        const double centre = timeAt(statisticCentre_);
        const double windowEnd_s = centre + statisticHalf_s_ + kTimeTolerance_s;
        if (!endOfData && timeAt(end - 1) <= windowEnd_s)
            return;
        while (timeAt(windowFirst_) < centre - statisticHalf_s_ - kTimeTolerance_s)
            ++windowFirst_;
        while (windowEnd_ < end && timeAt(windowEnd_) <= windowEnd_s)
            ++windowEnd_;
        const double statistic = statistic_(samples + (windowFirst_ - base), windowEnd_ - windowFirst_);
        scored_.push_back({centre, static_cast<float>(std::log(std::max(statistic, kSmallestStatistic)) * kLog10OfE)});
        ++statisticCentre_;
    }
}

/// Stage 2 and 3: the threshold of every scored sample whose minimum window has closed, and the
/// decision against it, handed to stage 4.
template <typename Emit>
void StatisticStanceDetector::thresholdReadySamples(bool endOfData, Emit& emit)
{
    while (!scored_.empty()) {
        const Scored centre = scored_.front();
        if (!endOfData && scored_.back().time_s <= centre.time_s + thresholdHalf_s_ + kTimeTolerance_s)
            return;
        SampleStanceFlags flags;
        flags.logStatistic = centre.logStatistic;
        flags.logThreshold = nextThreshold(centre.time_s);
        const std::uint8_t atRest = flags.logStatistic < flags.logThreshold ? 1 : 0;
        flags.c1 = flags.c2 = flags.c3 = flags.c = atRest;
        dropShortRuns(flags, centre.time_s, emit);
        scored_.pop_front();  // the running minimum and maximum keep what later windows need of it
    }
}

/// The threshold of the next centre, scored_.front() (centres come in order: the windows only move
/// forward). Running minimum and maximum of the log statistic over the centred window; the
/// threshold lies zv_adapt_offset_dec above the minimum plus zv_adapt_fraction of the way to the
/// maximum, clamped to the absolute bounds.
float StatisticStanceDetector::nextThreshold(double centre_s)
{
    if (!params_.zv_adaptive)
        return static_cast<float>(params_.zv_log_threshold);
    const double windowEnd_s = centre_s + thresholdHalf_s_ + kTimeTolerance_s;
    for (; nextToEnter_ < scored_.end() && scored_[nextToEnter_].time_s <= windowEnd_s; ++nextToEnter_) {
        const Scored& entering = scored_[nextToEnter_];
        minimum_.enter(entering.time_s, entering.logStatistic);
        maximum_.enter(entering.time_s, entering.logStatistic);
    }
    const double windowStart_s = centre_s - thresholdHalf_s_ - kTimeTolerance_s;
    minimum_.leaveBefore(windowStart_s);
    maximum_.leaveBefore(windowStart_s);
    const double minimum = minimum_.extreme();
    const double maximum = maximum_.extreme();
    const double threshold = minimum + params_.zv_adapt_offset_dec + params_.zv_adapt_fraction * (maximum - minimum);
    return static_cast<float>(std::clamp(threshold, params_.zv_log_always, params_.zv_log_never));
}

/// Stage 4: a stance run is held until it has lasted zv_min_stance_s (then it is stance, and so is
/// the rest of it as it arrives) or ends sooner (then it is not).
template <typename Emit>
void StatisticStanceDetector::dropShortRuns(const SampleStanceFlags& flags, double time_s, Emit& emit)
{
    SampleStanceFlags out = flags;
    out.stance = flags.c;
    if (!out.stance) {
        runConfirmed_ = false;
        releaseHeldRun(false, emit);
        emit(out);
        return;
    }
    if (runConfirmed_) {
        emit(out);
        return;
    }
    if (heldRun_.empty())
        heldRunStart_s_ = time_s;
    heldRun_.push_back(out);
    if (time_s - heldRunStart_s_ >= params_.zv_min_stance_s - kTimeTolerance_s) {
        releaseHeldRun(true, emit);
        runConfirmed_ = true;
    }
}

template <typename Emit>
void StatisticStanceDetector::releaseHeldRun(bool keepAsStance, Emit& emit)
{
    for (SampleStanceFlags& flags : heldRun_) {
        flags.stance = keepAsStance ? 1 : 0;
        emit(flags);
    }
    heldRun_.clear();
}

}  // namespace footpath
