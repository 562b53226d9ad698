#include "SampleAssembler.h"

namespace footpath {

namespace {

constexpr std::uint64_t kPacketCounterModulus = 65536;
constexpr std::uint64_t kSampleTimeFineModulus = std::uint64_t{1} << 32;

}  // namespace

std::optional<LiveSample> SampleAssembler::add(const MtData2Sample& data)
{
    if (data.packetCounter)
        countLoss(*data.packetCounter);
    // The same order of checks as the .mtb reader, so both keep the same samples and values.
    if (!data.acceleration || !data.rateOfTurn) {
        ++incomplete_;
        return std::nullopt;
    }
    const std::optional<double> time = timeOf(data);
    if (!time) {
        ++incomplete_;  // lacks the stamp the first sample had, or repeats the previous one
        return std::nullopt;
    }
    if (data.magneticField)
        lastMag_ = *data.magneticField;
    if (data.pressure_pa)
        lastPressure_pa_ = *data.pressure_pa;
    LiveSample sample;
    sample.imu.time_s = *time;
    sample.imu.acc_mps2 = *data.acceleration;
    sample.imu.gyr_radps = *data.rateOfTurn;
    sample.imu.mag = lastMag_;
    sample.imu.pressure_pa = lastPressure_pa_;
    sample.packetCounter = data.packetCounter;
    sample.sampleTimeFine = data.sampleTimeFine;
    ++samples_;
    return sample;
}

void SampleAssembler::countLoss(std::uint16_t counter)
{
    if (lastCounter_) {
        const std::uint64_t gap = (counter + kPacketCounterModulus - *lastCounter_ - 1) % kPacketCounterModulus;
        // A step back (a restarted device) looks like a gap of almost 65536: not a loss.
        if (gap < kPacketCounterModulus / 2)
            packetsLost_ += gap;
        else
            ++counterRestarts_;
    }
    lastCounter_ = counter;
}

std::optional<double> SampleAssembler::timeOf(const MtData2Sample& data)
{
    if (timeBase_ == TimeBase::Undecided) {
        timeBase_ = data.sampleTimeFine ? TimeBase::SampleTimeFine
                    : data.packetCounter ? TimeBase::Counter
                                         : TimeBase::Arrival;
        if (timeBase_ != TimeBase::Arrival)
            unwrapper_.emplace(timeBase_ == TimeBase::SampleTimeFine ? kSampleTimeFineModulus : kPacketCounterModulus);
    }
    std::uint64_t tick = samples_;
    if (timeBase_ == TimeBase::SampleTimeFine) {
        if (!data.sampleTimeFine)
            return std::nullopt;
        tick = unwrapper_->next(*data.sampleTimeFine);
    } else if (timeBase_ == TimeBase::Counter) {
        if (!data.packetCounter)
            return std::nullopt;
        tick = unwrapper_->next(*data.packetCounter);
    }
    if (samples_ == 0)
        firstTick_ = tick;
    else if (tick == lastTick_)
        return std::nullopt;
    lastTick_ = tick;
    const double ticksPerSecond = timeBase_ == TimeBase::SampleTimeFine ? kSampleTimeFineHz : rate_hz_;
    return static_cast<double>(tick - firstTick_) / ticksPerSecond;
}

}  // namespace footpath
