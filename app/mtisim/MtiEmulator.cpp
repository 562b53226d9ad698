#include "MtiEmulator.h"


#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

constexpr std::uint8_t kJunkMaxBytes = 16;
constexpr std::uint16_t kDefaultRate_hz = 100;
constexpr std::uint32_t kSampleTimeFineTicksPerSecond = 10000;  ///< SampleTimeFine counts 0.1 ms

bool isEveryMessageType(std::uint16_t type)
{
    return type == MtData2Id::PacketCounter || type == MtData2Id::SampleTimeFine || type == MtData2Id::StatusWord;
}

void append(MtiEmulator::Bytes& out, const XbusMessage& message)
{
    const std::vector<std::uint8_t> frame = encodeFrame(message);
    out.insert(out.end(), frame.begin(), frame.end());
}

void appendItemHeader(MtiEmulator::Bytes& out, std::uint16_t id, std::size_t size)
{
    appendBigEndian(out, id, 2);
    out.push_back(static_cast<std::uint8_t>(size));
}

void appendRealItem(MtiEmulator::Bytes& out, std::uint16_t id, const Eigen::Vector3d& value)
{
    const auto precision = static_cast<XdaPrecision>(id & MtData2Id::kPrecisionMask);
    appendItemHeader(out, id, 3 * xdaValueSize(precision));
    for (int axis = 0; axis < 3; ++axis)
        appendXdaReal(out, value[axis], precision);
}

}  // namespace

MtiEmulator::MtiEmulator(Recording playback, MtiEmulatorConfig config)
    : playback_(std::move(playback)), config_(std::move(config)), random_(config_.faults.seed)
{
    hasMag_ = playback_.hasMag();
    hasPressure_ = playback_.hasPressure();
    const std::size_t count = playback_.samples.size();
    if (count >= 2)
        playbackPeriod_s_ = playback_.duration_s() / static_cast<double>(count - 1);
    packetCounter_ = config_.firstPacketCounter;
    sampleTimeFine_ = config_.firstSampleTimeFine;
    // The stored configuration a device streams with when nobody answers its WakeUp (§4.1).
    using namespace MtData2Id;
    outputConfiguration_ = {{PacketCounter, OutputConfigEntry::kEveryMessage},
                            {SampleTimeFine, OutputConfigEntry::kEveryMessage},
                            {Acceleration, kDefaultRate_hz},
                            {RateOfTurn, kDefaultRate_hz}};
    if (hasMag_)
        outputConfiguration_.push_back({MagneticField, kDefaultRate_hz});
}

// ---- power and time -----------------------------------------------------------------------

MtiEmulator::Bytes MtiEmulator::powerOn(double now_s)
{
    decoder_.reset();
    packetCounter_ = config_.firstPacketCounter;
    sampleTimeFine_ = config_.firstSampleTimeFine;
    Bytes out;
    sendWakeUp(now_s, out);
    return out;
}

void MtiEmulator::powerOff()
{
    state_ = State::Off;
    deadline_s_ = std::numeric_limits<double>::infinity();
    decoder_.reset();
}

void MtiEmulator::sendWakeUp(double now_s, Bytes& out)
{
    append(out, wakeUpMessage());
    state_ = State::WakingUp;
    deadline_s_ = now_s + config_.wakeUpWindow_s;
}

MtiEmulator::Bytes MtiEmulator::advance(double now_s)
{
    Bytes out;
    if (state_ == State::Booting && now_s >= deadline_s_) {
        sendWakeUp(now_s, out);
    } else if (state_ == State::WakingUp && now_s >= deadline_s_) {
        // Nobody acknowledged the WakeUp: like an MTi-10/100 announce the configuration, then
        // measure with the stored output configuration.
        append(out, xbusMessage(XbusMid::Configuration, encodeConfiguration(configuration())));
        deadline_s_ = std::numeric_limits<double>::infinity();
        if (messageRate() > 0)
            startMeasurement(now_s, out);
        else
            state_ = State::Config;
    }
    if (state_ == State::Measurement)
        streamDue(now_s, out);
    return out;
}

double MtiEmulator::nextEventAt() const
{
    switch (state_) {
    case State::Booting:
    case State::WakingUp: return deadline_s_;
    case State::Measurement:
        return segmentStart_s_ + static_cast<double>(segmentMessages_) / segmentRate_;
    default: return std::numeric_limits<double>::infinity();
    }
}

// ---- host messages ------------------------------------------------------------------------

MtiEmulator::Bytes MtiEmulator::receive(const std::uint8_t* data, std::size_t size, double now_s)
{
    Bytes out;
    if (state_ == State::Off || state_ == State::Booting || state_ == State::Disconnected)
        return out;  // nobody listens: the bytes are lost as on a real line
    decoder_.feed(data, size);
    XbusMessage message;
    // Frames with a bad checksum are dropped silently: the protocol has no NAK, the host resends.
    while (decoder_.next(message))  // after a Reset the decoder is empty: the rest is lost
        handleMessage(message, now_s, out);
    return out;
}

void MtiEmulator::handleMessage(const XbusMessage& message, double now_s, Bytes& out)
{
    if (state_ == State::WakingUp) {
        state_ = State::Config;  // any answer inside the window keeps the device in Config
        deadline_s_ = std::numeric_limits<double>::infinity();
        if (message.mid == XbusMid::WakeUpAck)
            return;
    }
    if (state_ == State::Measurement)
        handleInMeasurement(message, now_s, out);
    else if (state_ == State::Config)
        handleInConfig(message, now_s, out);
}

void MtiEmulator::handleInMeasurement(const XbusMessage& message, double now_s, Bytes& out)
{
    switch (message.mid) {
    case XbusMid::GoToConfig:  // any payload: XSP pads it on RS485
        append(out, ackMessage(message.mid));
        state_ = State::Config;
        break;
    case XbusMid::GoToMeasurement: append(out, ackMessage(message.mid)); break;
    case XbusMid::Reset: startReset(now_s, out); break;
    case XbusMid::WakeUpAck: break;  // a late answer to a WakeUp: nothing to do
    default: append(out, errorMessage(XbusErrorCode::InvalidMessage)); break;
    }
}

void MtiEmulator::handleInConfig(const XbusMessage& message, double now_s, Bytes& out)
{
    switch (message.mid) {
    case XbusMid::GoToConfig: append(out, ackMessage(message.mid)); break;
    case XbusMid::GoToMeasurement:
        if (messageRate() == 0) {
            append(out, errorMessage(XbusErrorCode::OutputConfigurationError));
        } else {
            append(out, ackMessage(message.mid));
            startMeasurement(now_s, out);
        }
        break;
    case XbusMid::ReqDid: append(out, deviceIdMessage(config_.deviceId)); break;
    case XbusMid::ReqProductCode: append(out, productCodeMessage(config_.productCode)); break;
    case XbusMid::ReqHardwareVersion: append(out, xbusMessage(XbusMid::HardwareVersion, {2, 0})); break;
    case XbusMid::ReqFwRev: append(out, firmwareRevMessage(config_.firmware)); break;
    case XbusMid::ReqConfiguration:
        append(out, xbusMessage(XbusMid::Configuration, encodeConfiguration(configuration())));
        break;
    case XbusMid::SetBaudrate:
        if (message.payload.empty()) {
            append(out, baudrateMessage(baudCode_));
        } else if (message.payload.size() == 1 && xbusBaudFromCode(message.payload.front())) {
            baudCode_ = message.payload.front();  // applies after the next Reset (§2.5); a pty has no baud
            append(out, ackMessage(message.mid));
        } else {
            append(out, errorMessage(XbusErrorCode::BaudRateInvalid));
        }
        break;
    case XbusMid::SetOutputConfiguration: handleOutputConfiguration(message, out); break;
    case XbusMid::Reset: startReset(now_s, out); break;
    case XbusMid::WakeUpAck: break;
    default: append(out, errorMessage(XbusErrorCode::InvalidMessage)); break;
    }
}

void MtiEmulator::startReset(double now_s, Bytes& out)
{
    append(out, ackMessage(XbusMid::Reset));
    state_ = State::Booting;
    deadline_s_ = now_s + config_.bootTime_s;
    decoder_.reset();
    packetCounter_ = config_.firstPacketCounter;
    sampleTimeFine_ = config_.firstSampleTimeFine;
}

void MtiEmulator::startMeasurement(double now_s, Bytes&)
{
    state_ = State::Measurement;
    streamMessages_ = 0;
    segmentStart_s_ = now_s;
    segmentMessages_ = 0;
    segmentRate_ = sendRate();
}

// ---- output configuration -----------------------------------------------------------------

void MtiEmulator::handleOutputConfiguration(const XbusMessage& message, Bytes& out)
{
    if (message.payload.empty()) {
        append(out, outputConfigurationMessage(outputConfiguration_));
        return;
    }
    XbusParsed<std::vector<OutputConfigEntry>> parsed = parseOutputConfiguration(message.payload);
    if (!parsed.ok()) {
        append(out, errorMessage(XbusErrorCode::InvalidParameter));
        return;
    }
    const bool emptyConfiguration = parsed.value.size() == 1 && parsed.value.front() == OutputConfigEntry{};
    if (emptyConfiguration) {  // "no output" is one all-zero entry (XSP)
        outputConfiguration_.clear();
        append(out, outputConfigurationMessage(parsed.value));
        return;
    }
    if (const std::uint8_t error = validateOutputConfiguration(parsed.value); error != 0) {
        append(out, errorMessage(error));
        return;
    }
    outputConfiguration_ = parsed.value;
    append(out, outputConfigurationMessage(outputConfiguration_));  // the echo says what was applied
}

/// Keeps the entries this device can deliver, at the rates it can deliver them; 0 if that went
/// well, else the Error code to answer with.
std::uint8_t MtiEmulator::validateOutputConfiguration(std::vector<OutputConfigEntry>& entries) const
{
    std::vector<OutputConfigEntry> applied;
    for (OutputConfigEntry entry : entries) {
        std::uint8_t error = 0;
        if (applyEntry(entry, error))
            applied.push_back(entry);
        if (error != 0)
            return error;
    }
    entries = applied;
    return 0;
}

/// True if the entry stays (its rate possibly reduced); `error` is set for what no MTi accepts.
bool MtiEmulator::applyEntry(OutputConfigEntry& entry, std::uint8_t& error) const
{
    const std::uint16_t type = entry.dataId & MtData2Id::kTypeMask;
    if (entry.rate_hz == 0)
        return false;  // rate 0 switches an output off
    if (isEveryMessageType(type)) {
        entry.rate_hz = OutputConfigEntry::kEveryMessage;
        return true;
    }
    std::uint16_t max = 0;
    switch (type) {
    case MtData2Id::Acceleration:
    case MtData2Id::RateOfTurn: max = kInertialMax_hz; break;
    case MtData2Id::MagneticField: max = hasMag_ ? kMagneticMax_hz : 0; break;
    case MtData2Id::BaroPressure: max = hasPressure_ ? kPressureMax_hz : 0; break;
    default: error = XbusErrorCode::InvalidParameter; return false;
    }
    if (max == 0)
        return false;  // a sensor this device lacks: left out of the echo, as a device does
    entry.rate_hz = std::min(entry.rate_hz, max);
    if (kInertialMax_hz % entry.rate_hz != 0) {
        error = XbusErrorCode::InvalidParameter;  // rates must divide the sensor clock
        return false;
    }
    return true;
}

std::uint16_t MtiEmulator::messageRate() const
{
    std::uint16_t rate = 0;
    for (const OutputConfigEntry& entry : outputConfiguration_)
        if (!isEveryMessageType(entry.dataId & MtData2Id::kTypeMask))
            rate = std::max(rate, entry.rate_hz);
    return rate;
}

XbusConfiguration MtiEmulator::configuration() const
{
    return mtData2Configuration(config_.deviceId, messageRate(), config_.firmware);
}

// ---- streaming ----------------------------------------------------------------------------

bool MtiEmulator::inBurst() const
{
    const MtiFaults& f = config_.faults;
    return f.burstLength_s > 0.0 && deviceTime_s_ >= f.burstAt_s - 1e-9
           && deviceTime_s_ < f.burstAt_s + f.burstLength_s - 1e-9;
}

double MtiEmulator::sendRate() const
{
    return messageRate() * config_.speed * (inBurst() ? config_.faults.burstFactor : 1.0);
}

/// A burst starting or ending: the next message leaves when it would have at the old rate, the
/// ones after it at the new rate.
void MtiEmulator::rescheduleIfRateChanged()
{
    const double rate = sendRate();
    if (rate == segmentRate_)
        return;
    segmentStart_s_ += static_cast<double>(segmentMessages_) / segmentRate_;
    segmentMessages_ = 0;
    segmentRate_ = rate;
}

void MtiEmulator::streamDue(double now_s, Bytes& out)
{
    // Message k of the segment is due at segmentStart + k / rate, compared as floor((now - start)
    // * rate) >= k so that times on the rate's grid count exactly.
    while (state_ == State::Measurement
           && std::floor((now_s - segmentStart_s_) * segmentRate_) >= static_cast<double>(segmentMessages_)) {
        const double disconnectAfter = config_.faults.disconnectAfter_s;
        if (disconnectAfter > 0.0 && deviceTime_s_ >= disconnectAfter - 1e-9) {
            state_ = State::Disconnected;
            break;
        }
        if (!config_.loop && deviceTime_s_ > playback_.duration_s() + 1e-9) {
            state_ = State::Disconnected;  // played once: the device goes away
            break;
        }
        emitDataMessage(out);
        rescheduleIfRateChanged();
    }
}

void MtiEmulator::emitDataMessage(Bytes& out)
{
    const Bytes payload = encodeDataPayload(sampleForMessage());
    DataRecord record;
    record.sample = decodeMtData2(payload).sample;  // exactly what the host can decode
    emitWithFaults(encodeFrame(xbusMessage(XbusMid::MtData2, payload)), record, out);
    if (observer_)
        observer_(record);
    ++injected_.dataMessages;
    injected_.burstMessages += inBurst();
    const std::uint16_t rate = messageRate();
    ++packetCounter_;
    sampleTimeFine_ += kSampleTimeFineTicksPerSecond / rate;
    deviceTime_s_ += 1.0 / rate;
    ++streamMessages_;
    ++segmentMessages_;
}

void MtiEmulator::emitWithFaults(Bytes frame, DataRecord& record, Bytes& out)
{
    // Every draw happens for every message, so a fault rate changes which messages are hit but
    // not the random sequence behind the other faults.
    std::uniform_real_distribution<double> chance(0.0, 1.0);
    const bool junk = chance(random_) < config_.faults.junkRate;
    const bool drop = chance(random_) < config_.faults.dropRate;
    const bool corrupt = chance(random_) < config_.faults.corruptRate;
    const std::uint32_t junkLength = 1 + random_() % kJunkMaxBytes;
    // BID, MID, payload or checksum, never the preamble (the receiver would see junk, not a
    // damaged frame) nor the length: after a damaged length no receiver can tell where the frame
    // ended, so nobody could count damaged frames exactly (tst_xbusframe covers that resync).
    const std::size_t headerSize = frame.at(3) == kXbusExtendedLength ? 6 : 4;
    const std::size_t pick = random_() % (2 + frame.size() - headerSize);
    const std::size_t corruptAt = pick < 2 ? 1 + pick : headerSize + pick - 2;
    const auto corruptMask = static_cast<std::uint8_t>(1 + random_() % 255);
    if (junk) {
        injected_.junkBytes += junkLength;
        ++injected_.junkRuns;
        for (std::uint32_t i = 0; i < junkLength; ++i) {
            // Junk never contains the preamble: a false frame start in junk could, by a 1 in 256
            // checksum accident, swallow the next real frame and make runs unrepeatable to judge.
            const auto byte = static_cast<std::uint8_t>(random_() % 255);
            out.push_back(byte == kXbusPreamble ? std::uint8_t{0xFF} : byte);
        }
    }
    if (drop) {
        record.fate = DataRecord::Fate::Dropped;
        ++injected_.dropped;
        return;
    }
    if (corrupt) {
        frame[corruptAt] ^= corruptMask;  // one altered byte always breaks the 8-bit checksum
        record.fate = DataRecord::Fate::Corrupted;
        ++injected_.corrupted;
        injected_.corruptedBytes += frame.size();
    }
    out.insert(out.end(), frame.begin(), frame.end());
}

const ImuSample* MtiEmulator::playbackSample() const
{
    const std::vector<ImuSample>& samples = playback_.samples;
    if (samples.empty())
        return nullptr;
    double t = deviceTime_s_;
    if (config_.loop)
        t = std::fmod(t, playback_.duration_s() + playbackPeriod_s_);
    const double at = samples.front().time_s + t + 1e-9;
    const auto after = std::upper_bound(samples.begin(), samples.end(), at,
                                        [](double time, const ImuSample& s) { return time < s.time_s; });
    return after == samples.begin() ? &samples.front() : &*(after - 1);
}

MtData2Sample MtiEmulator::sampleForMessage() const
{
    MtData2Sample sample;
    sample.packetCounter = packetCounter_;
    sample.sampleTimeFine = sampleTimeFine_;
    sample.statusWord = 0x00000003;  // self-test OK, filter valid
    sample.acceleration = Eigen::Vector3d::Zero();
    sample.rateOfTurn = Eigen::Vector3d::Zero();
    if (const ImuSample* s = playbackSample()) {
        sample.acceleration = s->acc_mps2;
        sample.rateOfTurn = s->gyr_radps;
        if (hasMag_)
            sample.magneticField = s->mag;
        if (hasPressure_)
            sample.pressure_pa = s->pressure_pa;
    }
    return sample;
}

bool MtiEmulator::itemDue(std::uint16_t rate_hz) const
{
    const std::uint64_t messageRate_hz = messageRate();
    const std::uint64_t k = streamMessages_;
    return k == 0 || k * rate_hz / messageRate_hz > (k - 1) * rate_hz / messageRate_hz;
}

/// Items in the order of the output configuration, as devices send them (§3.1).
MtiEmulator::Bytes MtiEmulator::encodeDataPayload(const MtData2Sample& sample) const
{
    Bytes out;
    for (const OutputConfigEntry& entry : outputConfiguration_) {
        const std::uint16_t type = entry.dataId & MtData2Id::kTypeMask;
        if (!isEveryMessageType(type) && !itemDue(entry.rate_hz))
            continue;
        switch (type) {
        case MtData2Id::PacketCounter:
            appendItemHeader(out, entry.dataId, 2);
            appendBigEndian(out, *sample.packetCounter, 2);
            break;
        case MtData2Id::SampleTimeFine:
            appendItemHeader(out, entry.dataId, 4);
            appendBigEndian(out, *sample.sampleTimeFine, 4);
            break;
        case MtData2Id::StatusWord:
            appendItemHeader(out, entry.dataId, 4);
            appendBigEndian(out, *sample.statusWord, 4);
            break;
        case MtData2Id::Acceleration: appendRealItem(out, entry.dataId, *sample.acceleration); break;
        case MtData2Id::RateOfTurn: appendRealItem(out, entry.dataId, *sample.rateOfTurn); break;
        case MtData2Id::MagneticField: appendRealItem(out, entry.dataId, *sample.magneticField); break;
        case MtData2Id::BaroPressure:
            appendItemHeader(out, entry.dataId, 4);
            appendBigEndian(out, static_cast<std::uint32_t>(std::lround(std::max(0.0, *sample.pressure_pa))), 4);
            break;
        default: break;
        }
    }
    return out;
}

}  // namespace footpath
