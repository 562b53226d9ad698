#include "detect/StanceDetector.h"

#include "detect/StatisticDetectors.h"

#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

// Timestamps are rounded decimals: 0.15 s from t = 0.01 may be 0.15000000000000002 away.
constexpr double kTimeTolerance_s = 1e-9;

// The window tests, the statistics and the per-sample conditions below are shared by detectStance
// and CausalStanceDetector, so both compute the same flags to the last bit.

bool beforeWindow(double time_s, double centre_s, double half_s)
{
    return time_s < centre_s - half_s - kTimeTolerance_s;
}

bool withinWindowEnd(double time_s, double centre_s, double half_s)
{
    return time_s <= centre_s + half_s + kTimeTolerance_s;
}

/// Half-open index ranges [first, last) of the samples within +-half of each sample's time.
template <typename Visit>
void forEachCentredWindow(const std::vector<double>& times, double half, Visit visit)
{
    std::size_t first = 0;
    std::size_t last = 0;
    for (std::size_t k = 0; k < times.size(); ++k) {
        while (beforeWindow(times[first], times[k], half))
            ++first;
        while (last < times.size() && withinWindowEnd(times[last], times[k], half))
            ++last;
        visit(k, first, last);
    }
}

/// Standard deviation of count values from their sum and sum of squares.
double stdDevFromSums(double sum, double sumSq, std::size_t count)
{
    const double n = static_cast<double>(count);
    const double mean = sum / n;
    const double variance = sumSq / n - mean * mean;
    return std::sqrt(std::max(variance, 0.0));
}

/// Binary median of a window with `set` ones among `count` flags; a tie keeps the sample's own flag.
std::uint8_t medianVote(std::size_t set, std::size_t count, std::uint8_t own)
{
    if (2 * set == count)
        return own;
    return 2 * set > count ? 1 : 0;
}

/// C1: a_min < |a| < a_max.
bool accelerationNormAtRest(double accNorm, const Parameters& params)
{
    return accNorm > params.acc_min_mps2 && accNorm < params.acc_max_mps2;
}

/// The log10 of C2's input and threshold, as the detector view draws every detector's statistic.
float logOf(double value)
{
    return static_cast<float>(std::log10(std::max(value, 1e-12)));
}

/// C3: |w| < w_max.
bool angularRateAtRest(const Eigen::Vector3d& gyr_radps, const Parameters& params)
{
    return gyr_radps.norm() < params.gyr_max_radps;
}

}  // namespace

std::vector<double> centredStdDev(const std::vector<double>& times, const std::vector<double>& values,
                                  double halfWindow_s)
{
    std::vector<double> result(values.size(), 0.0);
    if (values.empty())
        return result;
    // Prefix sums of values shifted by the first value: keeps E[x^2] - E[x]^2 free of cancellation
    // when |a| sits near g.
    const double shift = values.front();
    std::vector<double> sum(values.size() + 1, 0.0), sumSq(values.size() + 1, 0.0);
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double x = values[i] - shift;
        sum[i + 1] = sum[i] + x;
        sumSq[i + 1] = sumSq[i] + x * x;
    }
    forEachCentredWindow(times, halfWindow_s, [&](std::size_t k, std::size_t first, std::size_t last) {
        result[k] = stdDevFromSums(sum[last] - sum[first], sumSq[last] - sumSq[first], last - first);
    });
    return result;
}

std::vector<std::uint8_t> medianFilter(const std::vector<double>& times, const std::vector<std::uint8_t>& flags,
                                       double window_s)
{
    std::vector<std::size_t> ones(flags.size() + 1, 0);
    for (std::size_t i = 0; i < flags.size(); ++i)
        ones[i + 1] = ones[i] + (flags[i] ? 1 : 0);
    std::vector<std::uint8_t> result(flags.size(), 0);
    forEachCentredWindow(times, window_s / 2.0, [&](std::size_t k, std::size_t first, std::size_t last) {
        result[k] = medianVote(ones[last] - ones[first], last - first, flags[k]);
    });
    return result;
}

void appendFlags(StanceFlags& flags, const SampleStanceFlags& sample)
{
    flags.c1.push_back(sample.c1);
    flags.c2.push_back(sample.c2);
    flags.c3.push_back(sample.c3);
    flags.c.push_back(sample.c);
    flags.stance.push_back(sample.stance);
    flags.logStatistic.push_back(sample.logStatistic);
    flags.logThreshold.push_back(sample.logThreshold);
}

void resizeFlags(StanceFlags& flags, std::size_t count)
{
    for (std::vector<std::uint8_t>* decisions : {&flags.c1, &flags.c2, &flags.c3, &flags.c, &flags.stance})
        decisions->resize(count);
    flags.logStatistic.resize(count);
    flags.logThreshold.resize(count);
}

std::unique_ptr<CausalStanceDecider> makeCausalStanceDetector(const Parameters& params)
{
    if (params.detectorKind() == DetectorKind::PaperC1C2C3)
        return std::make_unique<CausalStanceDetector>(params);
    return std::make_unique<StatisticStanceDetector>(params);
}

double stanceDetectorLatency_s(const Parameters& params)
{
    if (params.detectorKind() == DetectorKind::PaperC1C2C3)
        return params.window_half_s + params.median_window_s / 2.0;
    return StatisticStanceDetector::latency_s(params);
}

StanceFlags detectStance(const std::vector<ImuSample>& samples, const Parameters& params)
{
    StanceFlags flags;
    detectStanceInto(samples, params, flags, {});
    return flags;
}

bool detectStanceInto(const std::vector<ImuSample>& samples, const Parameters& params, StanceFlags& flags,
                      const DecidedCallback& decided)
{
    if (params.detectorKind() != DetectorKind::PaperC1C2C3)
        return StatisticStanceDetector::detectInto(samples, params, flags, decided);
    // Its centred windows and median filter run over whole vectors: the flags are final at once.
    flags = detectPaperStance(samples, params);
    return !decided || decided(samples.size());
}

StanceFlags detectPaperStance(const std::vector<ImuSample>& samples, const Parameters& params)
{
    const std::size_t n = samples.size();
    std::vector<double> times(n), accNorm(n);
    StanceFlags flags;
    flags.c1.resize(n);
    flags.c3.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        times[k] = samples[k].time_s;
        accNorm[k] = samples[k].acc_mps2.norm();
        flags.c1[k] = accelerationNormAtRest(accNorm[k], params);
        flags.c3[k] = angularRateAtRest(samples[k].gyr_radps, params);
    }
    const std::vector<double> accStd = centredStdDev(times, accNorm, params.window_half_s);
    flags.c2.resize(n);
    flags.c.resize(n);
    flags.logStatistic.resize(n);
    flags.logThreshold.assign(n, logOf(params.acc_std_max_mps2));
    for (std::size_t k = 0; k < n; ++k) {
        flags.logStatistic[k] = logOf(accStd[k]);
        flags.c2[k] = accStd[k] < params.acc_std_max_mps2;
        flags.c[k] = flags.c1[k] && flags.c2[k] && flags.c3[k];
    }
    flags.stance = medianFilter(times, flags.c, params.median_window_s);
    return flags;
}

CausalStanceDetector::CausalStanceDetector(const Parameters& params)
    : params_(params)
{
}

void CausalStanceDetector::push(const ImuSample& sample, std::deque<SampleStanceFlags>& decided)
{
    const double accNorm = sample.acc_mps2.norm();
    if (received() == 0)
        shift_ = accNorm;
    Entry entry;
    entry.time_s = sample.time_s;
    entry.sumBefore = sum_;
    entry.sumSqBefore = sumSq_;
    entry.flags.c1 = accelerationNormAtRest(accNorm, params_);
    entry.flags.c3 = angularRateAtRest(sample.gyr_radps, params_);
    entries_.push_back(entry);
    const double x = accNorm - shift_;
    sum_ += x;
    sumSq_ += x * x;
    decide(false, decided);
}

void CausalStanceDetector::finish(std::deque<SampleStanceFlags>& decided)
{
    decide(true, decided);
}

// The prefix sums at k: those before sample k, or the running totals one past the newest sample.
double CausalStanceDetector::sumBefore(std::size_t k) const
{
    return k == received() ? sum_ : at(k).sumBefore;
}

double CausalStanceDetector::sumSqBefore(std::size_t k) const
{
    return k == received() ? sumSq_ : at(k).sumSqBefore;
}

std::size_t CausalStanceDetector::onesBefore(std::size_t k) const
{
    return k == c2Next_ ? ones_ : at(k).onesBefore;
}

void CausalStanceDetector::decide(bool endOfData, std::deque<SampleStanceFlags>& decided)
{
    while (decideNextC2(endOfData)) {
    }
    while (decideNextStance(endOfData, decided)) {
    }
    dropSamplesNoWindowNeeds();
}

/// C2 of the next sample, once a sample beyond its window has arrived (or at the end of data).
bool CausalStanceDetector::decideNextC2(bool endOfData)
{
    if (c2Next_ == received())
        return false;
    const double centre = at(c2Next_).time_s;
    const double half = params_.window_half_s;
    while (beforeWindow(at(c2First_).time_s, centre, half))
        ++c2First_;
    while (c2Last_ < received() && withinWindowEnd(at(c2Last_).time_s, centre, half))
        ++c2Last_;
    if (c2Last_ == received() && !endOfData)
        return false;  // a later sample may still fall inside the window
    const double accStd = stdDevFromSums(sumBefore(c2Last_) - sumBefore(c2First_),
                                         sumSqBefore(c2Last_) - sumSqBefore(c2First_), c2Last_ - c2First_);
    Entry& entry = at(c2Next_);
    entry.flags.c2 = accStd < params_.acc_std_max_mps2;
    entry.flags.logStatistic = logOf(accStd);
    entry.flags.logThreshold = logOf(params_.acc_std_max_mps2);
    entry.flags.c = entry.flags.c1 && entry.flags.c2 && entry.flags.c3;
    entry.onesBefore = ones_;
    ones_ += entry.flags.c;
    ++c2Next_;
    return true;
}

/// The median of the next sample, once its window is closed and every c in it is decided.
bool CausalStanceDetector::decideNextStance(bool endOfData, std::deque<SampleStanceFlags>& decided)
{
    if (stanceNext_ == received())
        return false;
    const double centre = at(stanceNext_).time_s;
    const double half = params_.median_window_s / 2.0;
    while (beforeWindow(at(medianFirst_).time_s, centre, half))
        ++medianFirst_;
    while (medianLast_ < received() && withinWindowEnd(at(medianLast_).time_s, centre, half))
        ++medianLast_;
    if ((medianLast_ == received() && !endOfData) || medianLast_ > c2Next_)
        return false;
    Entry& entry = at(stanceNext_);
    entry.flags.stance = medianVote(onesBefore(medianLast_) - onesBefore(medianFirst_), medianLast_ - medianFirst_,
                                    entry.flags.c);
    decided.push_back(entry.flags);
    ++stanceNext_;
    return true;
}

void CausalStanceDetector::dropSamplesNoWindowNeeds()
{
    // Both windows only move forward, so nothing before the earlier of their starts is read again.
    // Dropped in batches of at least half the buffer, so the moves cost O(1) per sample.
    const std::size_t unneeded = std::min(c2First_, medianFirst_) - base_;
    if (unneeded < kMinimumDrop || 2 * unneeded < entries_.size())
        return;
    entries_.erase(entries_.begin(), entries_.begin() + static_cast<std::ptrdiff_t>(unneeded));
    base_ += unneeded;
}

}  // namespace footpath
