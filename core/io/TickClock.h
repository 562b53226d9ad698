#pragma once

#include "Recording.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace footpath {

/// Xsens' SampleTimeFine counts a 10 kHz device clock.
constexpr double kSampleTimeFineHz = 10000.0;

/// Unwraps a counter that wraps at `modulus` (PacketCounter: 65536; SampleTimeFine: 2^32) into a
/// monotonic 64-bit count. The first value is taken as is; each step forward is (new - old) mod
/// modulus, so one wrap per step is handled and a step of 0 stays 0.
class CounterUnwrapper {
public:
    explicit CounterUnwrapper(std::uint64_t modulus) : modulus_(modulus) {}
    std::uint64_t next(std::uint64_t raw);

private:
    std::uint64_t modulus_;
    bool started_ = false;
    std::uint64_t lastRaw_ = 0;
    std::uint64_t total_ = 0;
};

/// The rate of a clock from the median step of its unwrapped ticks: the nominal period even when
/// packets were lost. Nothing for fewer than two ticks.
std::optional<double> rateFromMedianTickStep(const std::vector<std::uint64_t>& ticks, double ticksPerSecond);

/// Sets each sample's time from its unwrapped tick, the first sample at 0 s; lost packets show as
/// longer steps, never as a shifted row index.
void assignTimesFromTicks(std::vector<ImuSample>& samples, const std::vector<std::uint64_t>& ticks,
                          double ticksPerSecond);

}  // namespace footpath
