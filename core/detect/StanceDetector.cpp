#include "detect/StanceDetector.h"

#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

// Timestamps are rounded decimals: 0.15 s from t = 0.01 may be 0.15000000000000002 away.
constexpr double kTimeTolerance_s = 1e-9;

/// Half-open index ranges [first, last) of the samples within +-half of each sample's time.
template <typename Visit>
void forEachCentredWindow(const std::vector<double>& times, double half, Visit visit)
{
    std::size_t first = 0;
    std::size_t last = 0;
    for (std::size_t k = 0; k < times.size(); ++k) {
        while (times[first] < times[k] - half - kTimeTolerance_s)
            ++first;
        while (last < times.size() && times[last] <= times[k] + half + kTimeTolerance_s)
            ++last;
        visit(k, first, last);
    }
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
        const double n = static_cast<double>(last - first);
        const double mean = (sum[last] - sum[first]) / n;
        const double variance = (sumSq[last] - sumSq[first]) / n - mean * mean;
        result[k] = std::sqrt(std::max(variance, 0.0));
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
        const std::size_t count = last - first;
        const std::size_t set = ones[last] - ones[first];
        if (2 * set == count)
            result[k] = flags[k];
        else
            result[k] = 2 * set > count ? 1 : 0;
    });
    return result;
}

StanceFlags detectStance(const std::vector<ImuSample>& samples, const Parameters& params)
{
    const std::size_t n = samples.size();
    std::vector<double> times(n), accNorm(n);
    StanceFlags flags;
    flags.c1.resize(n);
    flags.c3.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        times[k] = samples[k].time_s;
        accNorm[k] = samples[k].acc_mps2.norm();
        flags.c1[k] = accNorm[k] > params.acc_min_mps2 && accNorm[k] < params.acc_max_mps2;
        flags.c3[k] = samples[k].gyr_radps.norm() < params.gyr_max_radps;
    }
    const std::vector<double> accStd = centredStdDev(times, accNorm, params.window_half_s);
    flags.c2.resize(n);
    flags.c.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        flags.c2[k] = accStd[k] < params.acc_std_max_mps2;
        flags.c[k] = flags.c1[k] && flags.c2[k] && flags.c3[k];
    }
    flags.stance = medianFilter(times, flags.c, params.median_window_s);
    return flags;
}

}  // namespace footpath
