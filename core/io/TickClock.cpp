#include "io/TickClock.h"

#include <algorithm>

namespace footpath {

std::uint64_t CounterUnwrapper::next(std::uint64_t raw)
{
    if (!started_) {
        started_ = true;
        lastRaw_ = raw;
        total_ = raw;
        return total_;
    }
    total_ += (raw + modulus_ - lastRaw_) % modulus_;
    lastRaw_ = raw;
    return total_;
}

std::optional<double> rateFromMedianTickStep(const std::vector<std::uint64_t>& ticks, double ticksPerSecond)
{
    if (ticks.size() < 2)
        return std::nullopt;
    std::vector<std::uint64_t> steps(ticks.size() - 1);
    for (std::size_t i = 1; i < ticks.size(); ++i)
        steps[i - 1] = ticks[i] - ticks[i - 1];
    const auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), middle, steps.end());
    if (*middle == 0)
        return std::nullopt;
    return ticksPerSecond / static_cast<double>(*middle);
}

void assignTimesFromTicks(std::vector<ImuSample>& samples, const std::vector<std::uint64_t>& ticks,
                          double ticksPerSecond)
{
    for (std::size_t i = 0; i < samples.size() && i < ticks.size(); ++i)
        samples[i].time_s = static_cast<double>(ticks[i] - ticks.front()) / ticksPerSecond;
}

}  // namespace footpath
