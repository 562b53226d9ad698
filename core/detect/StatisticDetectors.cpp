#include "detect/StatisticDetectors.h"

#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

// Timestamps are rounded decimals: a window edge exactly on a sample must include it.
constexpr double kTimeTolerance_s = 1e-9;
// A statistic of exactly zero (a simulated, noise-free rest) has no logarithm; this stands for it.
constexpr double kSmallestStatistic = 1e-12;

Eigen::Vector3d meanAcceleration(const std::deque<ImuSample>& samples, std::size_t first, std::size_t last)
{
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t k = first; k <= last; ++k)
        sum += samples[k].acc_mps2;
    return sum / static_cast<double>(last - first + 1);
}

double shoe(const std::deque<ImuSample>& samples, std::size_t first, std::size_t last, const Parameters& params)
{
    const Eigen::Vector3d mean = meanAcceleration(samples, first, last);
    const Eigen::Vector3d gravityAlongMean =
        mean.norm() > 0.0 ? Eigen::Vector3d(params.gravity_mps2 * mean / mean.norm()) : Eigen::Vector3d::Zero();
    const double invVarAcc = 1.0 / (params.zv_sigma_acc_mps2 * params.zv_sigma_acc_mps2);
    const double invVarGyr = 1.0 / (params.zv_sigma_gyr_radps * params.zv_sigma_gyr_radps);
    double sum = 0.0;
    for (std::size_t k = first; k <= last; ++k)
        sum += (samples[k].acc_mps2 - gravityAlongMean).squaredNorm() * invVarAcc
               + samples[k].gyr_radps.squaredNorm() * invVarGyr;
    return sum / static_cast<double>(last - first + 1);
}

double ared(const std::deque<ImuSample>& samples, std::size_t first, std::size_t last, const Parameters& params)
{
    double sum = 0.0;
    for (std::size_t k = first; k <= last; ++k)
        sum += samples[k].gyr_radps.squaredNorm();
    return sum / static_cast<double>(last - first + 1) / (params.zv_sigma_gyr_radps * params.zv_sigma_gyr_radps);
}

double amvd(const std::deque<ImuSample>& samples, std::size_t first, std::size_t last, const Parameters& params)
{
    const Eigen::Vector3d mean = meanAcceleration(samples, first, last);
    double sum = 0.0;
    for (std::size_t k = first; k <= last; ++k)
        sum += (samples[k].acc_mps2 - mean).squaredNorm();
    return sum / static_cast<double>(last - first + 1) / (params.zv_sigma_acc_mps2 * params.zv_sigma_acc_mps2);
}

double mbgtd(const std::deque<ImuSample>& samples, std::size_t first, std::size_t last, const Parameters& params)
{
    double largest = 0.0;
    for (std::size_t split = first; split < last; ++split) {
        double sum = 0.0;
        for (std::size_t i = first; i <= split; ++i)
            for (std::size_t j = split + 1; j <= last; ++j)
                sum += (samples[i].acc_mps2 - samples[j].acc_mps2).norm();
        const double pairs = static_cast<double>((split - first + 1) * (last - split));
        largest = std::max(largest, sum / pairs);
    }
    return largest * largest / (params.zv_sigma_acc_mps2 * params.zv_sigma_acc_mps2);
}

}  // namespace

double zeroVelocityStatistic(DetectorKind kind, const std::deque<ImuSample>& samples, std::size_t first,
                             std::size_t last, const Parameters& params)
{
    switch (kind) {
    case DetectorKind::Ared:
        return ared(samples, first, last, params);
    case DetectorKind::Amvd:
        return amvd(samples, first, last, params);
    case DetectorKind::Mbgtd:
        return mbgtd(samples, first, last, params);
    case DetectorKind::Shoe:
    case DetectorKind::PaperC1C2C3:
        break;
    }
    return shoe(samples, first, last, params);
}

StatisticStanceDetector::StatisticStanceDetector(const Parameters& params)
    : params_(params)
    , kind_(params.detectorKind())
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
    scoreReadySamples(false);
    thresholdReadySamples(false, decided);
}

void StatisticStanceDetector::finish(std::deque<SampleStanceFlags>& decided)
{
    scoreReadySamples(true);
    thresholdReadySamples(true, decided);
    releaseHeldRun(false, decided);  // a run still held at the end is shorter than zv_min_stance_s
}

/// Stage 1: the statistic of every sample whose window has closed (a later sample arrived).
void StatisticStanceDetector::scoreReadySamples(bool endOfData)
{
    while (statisticCentre_ < samples_.size()) {
        const double centre = samples_[statisticCentre_].time_s;
        if (!endOfData && samples_.back().time_s <= centre + statisticHalf_s_ + kTimeTolerance_s)
            return;
        std::size_t first = 0;
        while (samples_[first].time_s < centre - statisticHalf_s_ - kTimeTolerance_s)
            ++first;
        std::size_t last = statisticCentre_;
        while (last + 1 < samples_.size() && samples_[last + 1].time_s <= centre + statisticHalf_s_ + kTimeTolerance_s)
            ++last;
        const double statistic = zeroVelocityStatistic(kind_, samples_, first, last, params_);
        scored_.push_back({centre, static_cast<float>(std::log10(std::max(statistic, kSmallestStatistic)))});
        ++statisticCentre_;
        // Later centres' windows start after this one's: what lies before it is not read again.
        while (statisticCentre_ > 0 && samples_.front().time_s < centre - statisticHalf_s_ - kTimeTolerance_s) {
            samples_.pop_front();
            --statisticCentre_;
        }
    }
}

/// Stage 2 and 3: the threshold of every scored sample whose minimum window has closed, and the
/// decision against it, handed to stage 4.
void StatisticStanceDetector::thresholdReadySamples(bool endOfData, std::deque<SampleStanceFlags>& decided)
{
    while (thresholdCentre_ < scoredBase_ + scored_.size()) {
        const Scored& centre = scored_[thresholdCentre_ - scoredBase_];
        if (!endOfData && scored_.back().time_s <= centre.time_s + thresholdHalf_s_ + kTimeTolerance_s)
            return;
        SampleStanceFlags flags;
        flags.logStatistic = centre.logStatistic;
        flags.logThreshold = nextThreshold(thresholdCentre_);
        const std::uint8_t atRest = flags.logStatistic < flags.logThreshold ? 1 : 0;
        flags.c1 = flags.c2 = flags.c3 = flags.c = atRest;
        const double windowStart = centre.time_s - thresholdHalf_s_ - kTimeTolerance_s;
        dropShortRuns(flags, centre.time_s, decided);
        ++thresholdCentre_;
        // Later windows start after this one's: what lies before it is not read again.
        while (scoredBase_ < thresholdCentre_ && scored_.front().time_s < windowStart) {
            scored_.pop_front();
            ++scoredBase_;
        }
        for (std::deque<std::size_t>* candidates : {&minimumCandidates_, &maximumCandidates_})
            while (!candidates->empty() && candidates->front() < scoredBase_)
                candidates->pop_front();
    }
}

/// The threshold of the next centre (centres come in order: the queues only move forward). Running
/// minimum and maximum of the log statistic over the centred window (monotonic queues: O(1) per
/// sample); the threshold lies zv_adapt_offset_dec above the minimum plus
/// zv_adapt_fraction of the way to the maximum, clamped to the absolute bounds.
float StatisticStanceDetector::nextThreshold(std::size_t centre)
{
    if (!params_.zv_adaptive)
        return static_cast<float>(params_.zv_log_threshold);
    const double centreTime = scored_[centre - scoredBase_].time_s;
    const auto valueAt = [this](std::size_t index) { return scored_[index - scoredBase_].logStatistic; };
    const std::size_t end = scoredBase_ + scored_.size();
    while (nextToEnter_ < end && scored_[nextToEnter_ - scoredBase_].time_s <= centreTime + thresholdHalf_s_ + kTimeTolerance_s) {
        const float value = valueAt(nextToEnter_);
        while (!minimumCandidates_.empty() && valueAt(minimumCandidates_.back()) >= value)
            minimumCandidates_.pop_back();
        minimumCandidates_.push_back(nextToEnter_);
        while (!maximumCandidates_.empty() && valueAt(maximumCandidates_.back()) <= value)
            maximumCandidates_.pop_back();
        maximumCandidates_.push_back(nextToEnter_);
        ++nextToEnter_;
    }
    const double windowStart = centreTime - thresholdHalf_s_ - kTimeTolerance_s;
    for (std::deque<std::size_t>* candidates : {&minimumCandidates_, &maximumCandidates_})
        while (scored_[candidates->front() - scoredBase_].time_s < windowStart)
            candidates->pop_front();
    const double minimum = valueAt(minimumCandidates_.front());
    const double maximum = valueAt(maximumCandidates_.front());
    const double threshold = minimum + params_.zv_adapt_offset_dec + params_.zv_adapt_fraction * (maximum - minimum);
    return static_cast<float>(std::clamp(threshold, params_.zv_log_always, params_.zv_log_never));
}

/// Stage 4: a stance run is held until it has lasted zv_min_stance_s (then it is stance, and so is
/// the rest of it as it arrives) or ends sooner (then it is not).
void StatisticStanceDetector::dropShortRuns(const SampleStanceFlags& flags, double time_s,
                                            std::deque<SampleStanceFlags>& decided)
{
    SampleStanceFlags out = flags;
    out.stance = flags.c;
    if (!out.stance) {
        runConfirmed_ = false;
        releaseHeldRun(false, decided);
        decided.push_back(out);
        return;
    }
    if (runConfirmed_) {
        decided.push_back(out);
        return;
    }
    if (heldRun_.empty())
        heldRunStart_s_ = time_s;
    heldRun_.push_back(out);
    if (time_s - heldRunStart_s_ >= params_.zv_min_stance_s - kTimeTolerance_s) {
        releaseHeldRun(true, decided);
        runConfirmed_ = true;
    }
}

void StatisticStanceDetector::releaseHeldRun(bool keepAsStance, std::deque<SampleStanceFlags>& decided)
{
    for (SampleStanceFlags& flags : heldRun_) {
        flags.stance = keepAsStance ? 1 : 0;
        decided.push_back(flags);
    }
    heldRun_.clear();
}

}  // namespace footpath
