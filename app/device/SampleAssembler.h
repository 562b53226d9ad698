#pragma once

#include "DeviceTypes.h"
#include "io/TickClock.h"
#include "xbus/MtData2.h"

#include <optional>

namespace footpath {

/// Turns decoded data messages into LiveSamples the way the .mtb reader turns a log into a
/// Recording, so that a live session, its CSV and its re-read .mtb agree sample for sample:
/// time from SampleTimeFine if the first intact message has it (else the packet counter at the
/// configured rate, else arrival order), starting at 0; magnetic field and pressure hold their
/// last value. It also finds lost packets from gaps in the packet counter.
class SampleAssembler {
public:
    explicit SampleAssembler(double rate_hz = 100.0) : rate_hz_(rate_hz) {}

    /// The sample of an intact message (acceleration and rate of turn present), else nothing.
    /// Every message with a packet counter, intact or not, advances the loss count.
    std::optional<LiveSample> add(const MtData2Sample& data);

    std::uint64_t packetsLost() const { return packetsLost_; }
    std::uint64_t counterRestarts() const { return counterRestarts_; }
    std::uint64_t incompleteMessages() const { return incomplete_; }
    std::uint64_t samples() const { return samples_; }

private:
    enum class TimeBase { Undecided, SampleTimeFine, Counter, Arrival };

    void countLoss(std::uint16_t counter);
    std::optional<double> timeOf(const MtData2Sample& data);

    double rate_hz_;
    TimeBase timeBase_ = TimeBase::Undecided;
    std::optional<CounterUnwrapper> unwrapper_;
    std::uint64_t firstTick_ = 0;
    std::uint64_t lastTick_ = 0;
    std::optional<std::uint16_t> lastCounter_;
    std::uint64_t packetsLost_ = 0;
    std::uint64_t counterRestarts_ = 0;
    std::uint64_t incomplete_ = 0;
    std::uint64_t samples_ = 0;
    Eigen::Vector3d lastMag_ = Eigen::Vector3d::Constant(std::nan(""));
    double lastPressure_pa_ = std::nan("");
};

}  // namespace footpath
