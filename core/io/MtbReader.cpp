#include "io/MtbReader.h"

#include "io/SampleLimit.h"

#include "xbus/LegacyMtData.h"
#include "xbus/MtData2.h"
#include "xbus/XbusFrame.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace footpath {

namespace {

constexpr std::size_t kChunkSize = 64 * 1024;
constexpr std::uint64_t kSampleTimeFineModulus = std::uint64_t{1} << 32;
constexpr std::uint64_t kPacketCounterModulus = 65536;
/// A stated rate further than this (relative) from the SampleTimeFine steps is not trusted.
constexpr double kRateTolerance = 0.05;
constexpr std::size_t kListedDamagePlaces = 5;

std::string formatNumber(double value)
{
    std::ostringstream out;
    out.precision(6);
    out << value;
    return out.str();
}

std::string hexByte(std::uint8_t value)
{
    char text[8];
    std::snprintf(text, sizeof text, "0x%02X", static_cast<unsigned>(value));
    return text;
}

/// How often something happened and where first: one warning instead of one per message.
struct Tally {
    std::size_t count = 0;
    std::uint64_t firstOffset = 0;
    std::string firstDetail;

    void add(std::uint64_t offset, const std::string& detail = {})
    {
        if (count++ == 0) {
            firstOffset = offset;
            firstDetail = detail;
        }
    }
    std::string where() const { return "first at byte offset " + std::to_string(firstOffset); }
};

enum class TimeBase { Undecided, SampleTimeFine, Counter, MessageOrder };

class MtbParser {
public:
    MtbParser(std::istream& in, std::string source, const ImportOptions& options, std::size_t totalBytes)
        : in_(in), options_(options), totalBytes_(totalBytes), sampleLimit_(sampleLimit(options))
    {
        result_.recording.source = std::move(source);
        result_.info.format = "xsens-mtb";
        lastMag_.setConstant(std::nan(""));
    }

    ImportResult run()
    {
        if (readAll())
            finish();
        return std::move(result_);
    }

private:
    bool fail(std::string message)
    {
        result_.error = ReadError{result_.recording.source, 0, 0, std::move(message)};
        return false;
    }
    void warn(std::string message) { result_.recording.warnings.push_back(std::move(message)); }

    bool readAll();
    bool reportProgress();
    void drainDecoder();
    void handleMessage(const XbusMessage& message);
    void handleConfiguration(const XbusMessage& message);
    void handleLegacyData(const XbusMessage& message);
    void handleDecoded(const MtData2Decoded& decoded);
    void addSample(const MtData2Sample& data);
    void chooseTimeBase(const MtData2Sample& data);
    std::optional<std::uint64_t> rawStamp(const MtData2Sample& data) const;
    bool reserveSamples(std::uint64_t offset);
    bool finish();
    void reportStreamDamage();
    std::string skippedBytesWarning() const;
    std::string missingDataMessage() const;
    bool resolveRate();
    std::optional<double> rateFromSampleTimeFine() const;
    void assignTimes();
    void warnAboutSkippedMessages();

    std::istream& in_;
    const ImportOptions& options_;
    std::size_t totalBytes_;
    std::size_t sampleLimit_;
    ImportResult result_;
    XbusFrameDecoder decoder_;
    XbusMessage message_;
    std::size_t frameSize_ = 0;  ///< of the message being handled
    std::uint64_t bytesRead_ = 0;
    bool readFailed_ = false;
    std::array<std::size_t, 256> messagesByMid_{};

    std::optional<XbusConfiguration> configuration_;
    TimeBase timeBase_ = TimeBase::Undecided;
    bool legacyData_ = false;  ///< the first sample came from legacy MTData
    std::optional<CounterUnwrapper> unwrapper_;
    std::uint64_t halfRange_ = 0;  ///< a step this large is a jump back seen as a wrap
    std::vector<std::uint64_t> ticks_;  ///< unwrapped stamp of each sample, in the time base's units
    Eigen::Vector3d lastMag_;
    double lastPressure_pa_ = std::nan("");
    bool sawMag_ = false;
    bool sawPressure_ = false;

    Tally withoutImu_;
    Tally nonFinite_;
    Tally malformed_;
    Tally legacyUndecodable_;
    Tally missingStamp_;
    Tally repeated_;
    Tally jumpsBack_;
    Tally extraConfigurations_;
};

bool MtbParser::readAll()
{
    std::vector<char> chunk(kChunkSize);
    while (in_) {
        in_.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        const auto got = static_cast<std::size_t>(std::max<std::streamsize>(0, in_.gcount()));
        if (got == 0)
            break;
        decoder_.feed(reinterpret_cast<const std::uint8_t*>(chunk.data()), got);
        bytesRead_ += got;
        drainDecoder();
        if (result_.error || !reportProgress())
            return false;
    }
    readFailed_ = in_.bad();
    decoder_.finish();
    drainDecoder();
    return !result_.error;
}

bool MtbParser::reportProgress()
{
    if (!options_.progress || totalBytes_ == 0)
        return true;
    if (options_.progress(std::min(1.0, static_cast<double>(bytesRead_) / static_cast<double>(totalBytes_))))
        return true;
    return fail("reading cancelled");
}

void MtbParser::drainDecoder()
{
    while (!result_.error && decoder_.next(message_))
        handleMessage(message_);
}

void MtbParser::handleMessage(const XbusMessage& message)
{
    ++messagesByMid_[message.mid];
    frameSize_ = message.payload.size() + (message.payload.size() > kXbusMaxStandardPayload ? 7 : 5);
    switch (message.mid) {
    case XbusMid::Configuration: handleConfiguration(message); break;
    case XbusMid::MtData2: handleDecoded(decodeMtData2(message.payload)); break;
    case XbusMid::MtData: handleLegacyData(message); break;
    default: break;  // EMTS (encrypted calibration), acks, errors: nothing to read from them
    }
}

void MtbParser::handleConfiguration(const XbusMessage& message)
{
    // The logger writes the Configuration first; a later one (if any) cannot change how earlier
    // samples were laid out, so the first one describes the file.
    if (configuration_) {
        extraConfigurations_.add(decoder_.lastFrameOffset());
        return;
    }
    XbusConfigurationParsed parsed = parseConfiguration(message.payload);
    if (!parsed.ok()) {
        warn("ignored the Configuration message at byte offset " + std::to_string(decoder_.lastFrameOffset()) + ": "
             + parsed.error);
        return;
    }
    configuration_ = std::move(parsed.configuration);
}

void MtbParser::handleLegacyData(const XbusMessage& message)
{
    // Legacy MTData has no item identifiers: only the Configuration says what the bytes are.
    if (!configuration_) {
        legacyUndecodable_.add(decoder_.lastFrameOffset(), "no Configuration message before it describes its layout");
        return;
    }
    if (configuration_->devices.size() != 1) {
        legacyUndecodable_.add(decoder_.lastFrameOffset(),
                               "the Configuration lists " + std::to_string(configuration_->devices.size())
                                   + " devices; only single-device logs are read");
        return;
    }
    const bool beforeFirstSample = timeBase_ == TimeBase::Undecided;
    handleDecoded(decodeLegacyMtData(message.payload, configuration_->devices.front().layout));
    legacyData_ = legacyData_ || (beforeFirstSample && timeBase_ != TimeBase::Undecided);
}

void MtbParser::handleDecoded(const MtData2Decoded& decoded)
{
    if (!decoded.ok()) {
        malformed_.add(decoder_.lastFrameOffset(), decoded.error);
        return;
    }
    addSample(decoded.sample);
}

void MtbParser::chooseTimeBase(const MtData2Sample& data)
{
    if (data.sampleTimeFine) {
        timeBase_ = TimeBase::SampleTimeFine;
        unwrapper_.emplace(kSampleTimeFineModulus);
        halfRange_ = kSampleTimeFineModulus / 2;
    } else if (data.packetCounter) {
        timeBase_ = TimeBase::Counter;
        unwrapper_.emplace(kPacketCounterModulus);
        halfRange_ = kPacketCounterModulus / 2;
    } else {
        timeBase_ = TimeBase::MessageOrder;
    }
}

std::optional<std::uint64_t> MtbParser::rawStamp(const MtData2Sample& data) const
{
    switch (timeBase_) {
    case TimeBase::SampleTimeFine: return data.sampleTimeFine;
    case TimeBase::Counter: return data.packetCounter;
    default: return std::nullopt;
    }
}

void MtbParser::addSample(const MtData2Sample& data)
{
    const std::uint64_t offset = decoder_.lastFrameOffset();
    if (!data.acceleration || !data.rateOfTurn) {
        withoutImu_.add(offset);
        return;
    }
    // A valid checksum does not make a float finite; one NaN would turn every later state NaN.
    if (!data.acceleration->allFinite() || !data.rateOfTurn->allFinite()) {
        nonFinite_.add(offset);
        return;
    }
    if (timeBase_ == TimeBase::Undecided) {
        chooseTimeBase(data);
        if (!reserveSamples(offset))
            return;
    }
    const std::optional<std::uint64_t> raw = rawStamp(data);
    if (timeBase_ != TimeBase::MessageOrder && !raw) {
        missingStamp_.add(offset);
        return;
    }
    const std::uint64_t ticks = raw ? unwrapper_->next(*raw) : ticks_.size();
    if (!ticks_.empty() && ticks == ticks_.back()) {
        repeated_.add(offset);
        return;
    }
    if (!ticks_.empty() && halfRange_ > 0 && ticks - ticks_.back() >= halfRange_)
        jumpsBack_.add(offset);
    // Magnetometer and barometer often run slower than the IMU: hold their last value.
    if (data.magneticField && data.magneticField->allFinite())
        lastMag_ = *data.magneticField;
    if (data.pressure_pa && std::isfinite(*data.pressure_pa))
        lastPressure_pa_ = *data.pressure_pa;
    sawMag_ = sawMag_ || data.magneticField.has_value();
    sawPressure_ = sawPressure_ || data.pressure_pa.has_value();

    if (ticks_.size() == sampleLimit_) {
        fail(tooManySamplesMessage(sampleLimit_, {}, options_) + " (stopped at byte offset " + std::to_string(offset)
             + ")");
        return;
    }
    ImuSample sample;
    sample.acc_mps2 = *data.acceleration;
    sample.gyr_radps = *data.rateOfTurn;
    sample.mag = lastMag_;
    sample.pressure_pa = lastPressure_pa_;
    result_.recording.samples.push_back(sample);
    ticks_.push_back(ticks);
}

/// False, with the error, when the file clearly holds more samples than the limit: said before
/// reading on, not when the memory has run out.
bool MtbParser::reserveSamples(std::uint64_t offset)
{
    // The data messages of a log usually all have the size of the first one, so the rest of the
    // file holds about this many samples: allocating once avoids the peak of a doubling vector.
    if (totalBytes_ <= offset || frameSize_ == 0)
        return true;
    const auto remaining = static_cast<std::size_t>(totalBytes_ - offset);
    if (std::string problem = checkEstimatedSamples(remaining, frameSize_, "message", options_); !problem.empty())
        return fail(std::move(problem));
    const std::size_t expected = std::min(remaining / frameSize_ + 1, sampleLimit_);
    result_.recording.samples.reserve(expected);
    ticks_.reserve(expected);
    return true;
}

bool MtbParser::finish()
{
    reportStreamDamage();
    if (result_.recording.samples.empty())
        return fail(missingDataMessage());
    if (!resolveRate())
        return false;
    assignTimes();
    warnAboutSkippedMessages();
    RecordingInfo& info = result_.info;
    info.accUnitAsRead = AccUnit::MetresPerSecond2;
    info.gyrUnitAsRead = GyrUnit::RadiansPerSecond;
    info.timeUnitAsRead = TimeUnit::Seconds;
    info.channels = {"acc", "gyr"};
    if (sawMag_)
        info.channels.emplace_back("mag");
    if (sawPressure_)
        info.channels.emplace_back("pressure");
    return true;
}

void MtbParser::reportStreamDamage()
{
    const XbusDecodeStats& stats = decoder_.stats();
    if (stats.bytesSkipped > 0)
        warn(skippedBytesWarning());
    if (stats.bytesTruncated > 0) {
        result_.info.truncated = true;
        warn("the file ends inside a message that starts at byte offset "
             + std::to_string(bytesRead_ - stats.bytesTruncated) + " (" + std::to_string(stats.bytesTruncated)
             + " bytes not decoded); the samples before it were kept");
    }
    if (readFailed_) {
        result_.info.truncated = true;
        warn("reading failed at byte offset " + std::to_string(bytesRead_) + "; the samples before it were kept");
    }
}

std::string MtbParser::skippedBytesWarning() const
{
    const XbusDecodeStats& stats = decoder_.stats();
    std::string places;
    std::size_t listed = 0;
    for (const XbusStreamProblem& problem : stats.firstProblems) {
        if (problem.kind != XbusStreamProblem::Kind::SkippedBytes || listed == kListedDamagePlaces)
            continue;
        places += (listed++ == 0 ? "" : ", ") + std::to_string(problem.offset) + " (" + std::to_string(problem.size)
                  + " bytes)";
    }
    if (listed < stats.skippedRuns)
        places += ", ... (" + std::to_string(stats.skippedRuns) + " places)";
    std::string text = "skipped " + std::to_string(stats.bytesSkipped)
                       + " damaged byte(s) that form no valid Xbus message, at byte offset " + places;
    if (stats.damagedFrames > 0)  // each damaged message once, as the live counters count them
        text += "; " + std::to_string(stats.damagedFrames) + " checksum failure(s)";
    return text + "; reading resumed at the next valid message";
}

std::string MtbParser::missingDataMessage() const
{
    const std::string stopped = " (stopped at byte offset " + std::to_string(bytesRead_) + ")";
    if (bytesRead_ == 0)
        return "the file is empty: expected an Xsens .mtb log (Xbus messages starting with FA FF)";
    const XbusDecodeStats& stats = decoder_.stats();
    const std::string expected = "expected an Xsens .mtb log (Xbus messages starting with FA FF, first a "
                                 "Configuration FA FF 0D)";
    if (stats.framesDecoded == 0)
        return "no valid Xbus message in " + std::to_string(bytesRead_) + " bytes: " + expected + stopped;
    // Random data passes the 8-bit checksum now and then: a few "messages" in a sea of skipped
    // bytes say that this is not a log at all.
    if (2 * stats.bytesSkipped > bytesRead_)
        return std::to_string(stats.bytesSkipped) + " of " + std::to_string(bytesRead_)
               + " bytes are no valid Xbus message and none of the rest is a data message: " + expected + stopped;
    std::vector<std::string> reasons;
    if (withoutImu_.count > 0)
        reasons.push_back("none of the " + std::to_string(withoutImu_.count)
                          + " data message(s) carries both acceleration and rate of turn (" + withoutImu_.where()
                          + "): the device must output Acceleration (0x4020) and RateOfTurn (0x8020)");
    if (nonFinite_.count > 0)
        reasons.push_back(std::to_string(nonFinite_.count) + " data message(s) hold an acceleration or rate of turn "
                          "that is not a finite number (" + nonFinite_.where() + ")");
    if (malformed_.count > 0)
        reasons.push_back(std::to_string(malformed_.count) + " malformed data message(s), " + malformed_.where() + ": "
                          + malformed_.firstDetail);
    if (legacyUndecodable_.count > 0)
        reasons.push_back(std::to_string(legacyUndecodable_.count) + " legacy MTData message(s) cannot be decoded ("
                          + legacyUndecodable_.where() + "): " + legacyUndecodable_.firstDetail);
    if (reasons.empty()) {
        std::string found;
        for (std::size_t mid = 0; mid < messagesByMid_.size(); ++mid)
            if (messagesByMid_[mid] > 0)
                found += (found.empty() ? "" : ", ") + hexByte(static_cast<std::uint8_t>(mid)) + " x"
                         + std::to_string(messagesByMid_[mid]);
        reasons.push_back("no data message among the Xbus messages found (MID " + found
                          + "): expected MTData2 (0x36) or legacy MTData (0x32) with acceleration and rate of turn");
    }
    std::string text;
    for (const std::string& reason : reasons)
        text += (text.empty() ? "" : "; ") + reason;
    return text + stopped;
}

/// options.rate_hz, else the Configuration's rate unless SampleTimeFine contradicts it, else the
/// median SampleTimeFine step.
bool MtbParser::resolveRate()
{
    double& rate = result_.info.rate_hz;
    const double stated = configuration_ ? configuration_->outputRate_hz() : 0.0;
    const std::optional<double> measured = rateFromSampleTimeFine();
    const bool contradicted = stated > 0.0 && measured && std::abs(*measured - stated) > kRateTolerance * stated;
    if (options_.rate_hz > 0.0) {
        rate = options_.rate_hz;
        if (stated > 0.0 && std::abs(rate - stated) > 1e-6 * stated)
            warn("the rate given (" + formatNumber(rate) + " Hz) overrides the " + formatNumber(stated)
                 + " Hz the Configuration message states");
    } else if (stated > 0.0 && !contradicted) {
        rate = stated;
    } else if (measured) {
        rate = *measured;
        if (contradicted)
            warn("the Configuration message states " + formatNumber(stated) + " Hz but SampleTimeFine steps give "
                 + formatNumber(*measured) + " Hz; using " + formatNumber(*measured) + " Hz");
    }
    if (rate > 0.0 || timeBase_ == TimeBase::SampleTimeFine)
        return true;
    return fail("the data messages have no SampleTimeFine and the file states no rate: give the sample rate");
}

/// The median step is the nominal period even when some packets are lost.
std::optional<double> MtbParser::rateFromSampleTimeFine() const
{
    if (timeBase_ != TimeBase::SampleTimeFine)
        return std::nullopt;
    return rateFromMedianTickStep(ticks_, kSampleTimeFineHz);
}

void MtbParser::assignTimes()
{
    const bool fromSampleTimeFine = timeBase_ == TimeBase::SampleTimeFine;
    const double ticksPerSecond = fromSampleTimeFine ? kSampleTimeFineHz : result_.info.rate_hz;
    assignTimesFromTicks(result_.recording.samples, ticks_, ticksPerSecond);
    const std::string rate = formatNumber(result_.info.rate_hz) + " Hz";
    switch (timeBase_) {
    case TimeBase::SampleTimeFine: result_.info.timeSource = "SampleTimeFine (10 kHz)"; break;
    case TimeBase::Counter:
        result_.info.timeSource = (legacyData_ ? "sample counter at " : "PacketCounter at ") + rate;
        break;
    default:
        result_.info.timeSource = "message order at " + rate;
        warn("the data messages carry neither SampleTimeFine nor a counter: time assumes no message was lost");
        break;
    }
    ticks_ = {};
}

void MtbParser::warnAboutSkippedMessages()
{
    if (withoutImu_.count > 0)
        warn("skipped " + std::to_string(withoutImu_.count)
             + " data message(s) without both acceleration and rate of turn (" + withoutImu_.where() + ")");
    if (nonFinite_.count > 0)
        warn("skipped " + std::to_string(nonFinite_.count)
             + " data message(s) whose acceleration or rate of turn is not a finite number (" + nonFinite_.where() + ")");
    if (malformed_.count > 0)
        warn("skipped " + std::to_string(malformed_.count) + " malformed data message(s) (" + malformed_.where()
             + ": " + malformed_.firstDetail + ")");
    if (legacyUndecodable_.count > 0)
        warn("skipped " + std::to_string(legacyUndecodable_.count) + " legacy MTData message(s) ("
             + legacyUndecodable_.where() + "): " + legacyUndecodable_.firstDetail);
    if (missingStamp_.count > 0)
        warn("skipped " + std::to_string(missingStamp_.count) + " data message(s) without the "
             + (timeBase_ == TimeBase::SampleTimeFine ? "SampleTimeFine" : "counter") + " the first sample had ("
             + missingStamp_.where() + ")");
    if (repeated_.count > 0)
        warn("skipped " + std::to_string(repeated_.count) + " data message(s) repeating the previous message's time ("
             + repeated_.where() + ")");
    if (jumpsBack_.count > 0)
        warn("the time stamp jumps back in " + std::to_string(jumpsBack_.count) + " data message(s) ("
             + jumpsBack_.where() + "; a device restart or joined logs?): time runs on as if the counter had wrapped");
    if (extraConfigurations_.count > 0)
        warn("ignored " + std::to_string(extraConfigurations_.count) + " further Configuration message(s) ("
             + extraConfigurations_.where() + "); the first one describes the file");
}

}  // namespace

ImportResult readMtb(std::istream& in, const std::string& sourceName, const ImportOptions& options,
                     std::size_t totalBytes)
{
    return MtbParser(in, sourceName, options, totalBytes).run();
}

}  // namespace footpath
