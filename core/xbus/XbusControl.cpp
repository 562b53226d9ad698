#include "xbus/XbusControl.h"

#include "xbus/MtData2.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace footpath {

namespace {

std::string hex(std::uint64_t value, int digits)
{
    char text[24];
    std::snprintf(text, sizeof text, "%0*llX", digits, static_cast<unsigned long long>(value));
    return text;
}

const std::map<std::uint8_t, const char*>& midNames()
{
    static const std::map<std::uint8_t, const char*> names = {
        {XbusMid::ReqDid, "ReqDID"},
        {XbusMid::DeviceId, "DeviceID"},
        {XbusMid::ReqConfiguration, "ReqConfiguration"},
        {XbusMid::Configuration, "Configuration"},
        {XbusMid::GoToMeasurement, "GoToMeasurement"},
        {XbusMid::GoToMeasurementAck, "GoToMeasurementAck"},
        {XbusMid::ReqFwRev, "ReqFWRev"},
        {XbusMid::FirmwareRev, "FirmwareRev"},
        {XbusMid::SetBaudrate, "SetBaudrate"},
        {XbusMid::BaudrateAck, "BaudrateAck"},
        {XbusMid::ReqProductCode, "ReqProductCode"},
        {XbusMid::ProductCode, "ProductCode"},
        {XbusMid::ReqHardwareVersion, "ReqHardwareVersion"},
        {XbusMid::HardwareVersion, "HardwareVersion"},
        {XbusMid::GoToConfig, "GoToConfig"},
        {XbusMid::GoToConfigAck, "GoToConfigAck"},
        {XbusMid::MtData, "MTData"},
        {XbusMid::MtData2, "MTData2"},
        {XbusMid::WakeUp, "WakeUp"},
        {XbusMid::WakeUpAck, "WakeUpAck"},
        {XbusMid::Reset, "Reset"},
        {XbusMid::ResetAck, "ResetAck"},
        {XbusMid::Error, "Error"},
        {XbusMid::Warning, "Warning"},
        {XbusMid::EmtsData, "EMTSData"},
        {XbusMid::SetOutputConfiguration, "SetOutputConfiguration"},
        {XbusMid::OutputConfiguration, "OutputConfiguration"},
    };
    return names;
}

/// §2.6, device-side codes; the host-library codes >= 256 are never transmitted.
const std::map<std::uint8_t, const char*>& errorTexts()
{
    static const std::map<std::uint8_t, const char*> texts = {
        {0x01, "no bus communication possible"},
        {0x02, "InitBus/SetBID not issued (bus not ready)"},
        {0x03, "invalid period"},
        {0x04, "message invalid or not implemented"},
        {0x10, "InitBus failure (Xbus Master)"},
        {0x11, "InitBus failure (Xbus Master)"},
        {0x12, "InitBus failure (Xbus Master)"},
        {0x14, "SetBID failure (Xbus Master)"},
        {0x15, "SetBID failure (Xbus Master)"},
        {0x18, "measurement failure (Xbus Master)"},
        {0x19, "measurement failure (Xbus Master)"},
        {0x1A, "measurement failure (Xbus Master)"},
        {0x1B, "measurement failure (Xbus Master)"},
        {0x1C, "measurement failure (Xbus Master)"},
        {0x1D, "measurement failure (Xbus Master)"},
        {0x1E, "timer overflow: the output period is too short"},
        {0x20, "baud rate not in the valid range"},
        {0x21, "invalid parameter"},
        {0x23, "transmit buffer full"},
        {0x24, "transmit buffer overflow"},
        {0x25, "wireless subsystem failed"},
        {0x28, "device error: update the firmware"},
        {0x29, "data overflow: more data than the link can carry (baud rate too low)"},
        {0x2A, "sample buffer full during a communication outage"},
        {0x2B, "external trigger misbehaving"},
        {0x2C, "sample stream ordering error"},
        {0x2D, "power dip recovered"},
        {0x2E, "over-current: the device is shutting down"},
        {0x2F, "temperature out of range"},
        {0x30, "battery low"},
        {0x31, "invalid filter profile"},
        {0x32, "stored settings invalid"},
        {0x33, "access denied"},
        {0x34, "file error"},
        {0x35, "output configuration error: cannot go to measurement"},
        {0x36, "file system corrupt"},
        {0x37, "battery system error"},
    };
    return texts;
}

/// Name and whether the quantity comes with every message (counters, times, status).
struct DataIdName {
    std::uint16_t type;
    const char* name;
    bool everyMessage;
};

const DataIdName kDataIdNames[] = {
    {MtData2Id::PacketCounter, "PacketCounter", true},
    {MtData2Id::SampleTimeFine, "SampleTimeFine", true},
    {MtData2Id::SampleTimeCoarse, "SampleTimeCoarse", true},
    {MtData2Id::Temperature, "Temperature", false},
    {MtData2Id::Quaternion, "Quaternion", false},
    {MtData2Id::EulerAngles, "EulerAngles", false},
    {MtData2Id::BaroPressure, "BaroPressure", false},
    {MtData2Id::DeltaV, "DeltaV", false},
    {MtData2Id::Acceleration, "Acceleration", false},
    {MtData2Id::FreeAcceleration, "FreeAcceleration", false},
    {MtData2Id::RateOfTurn, "RateOfTurn", false},
    {MtData2Id::DeltaQ, "DeltaQ", false},
    {MtData2Id::MagneticField, "MagneticField", false},
    {MtData2Id::StatusByte, "StatusByte", true},
    {MtData2Id::StatusWord, "StatusWord", true},
};

std::string dataIdName(std::uint16_t dataId)
{
    for (const DataIdName& known : kDataIdNames)
        if (known.type == (dataId & MtData2Id::kTypeMask))
            return known.name;
    return "data 0x" + hex(dataId, 4);
}

XbusParsed<std::uint64_t> unexpectedSize(const char* what, std::size_t size, const char* expected)
{
    XbusParsed<std::uint64_t> parsed;
    parsed.error = std::string(what) + " has " + std::to_string(size) + " bytes, expected " + expected;
    return parsed;
}

}  // namespace

std::string xbusMidName(std::uint8_t mid)
{
    const auto found = midNames().find(mid);
    return found != midNames().end() ? found->second : "MID 0x" + hex(mid, 2);
}

std::string xbusErrorText(std::uint8_t code)
{
    const auto found = errorTexts().find(code);
    const std::string number = " (error " + std::to_string(code) + ")";
    return found != errorTexts().end() ? found->second + number : "unknown device error" + number;
}

std::string xbusErrorText(const std::vector<std::uint8_t>& payload)
{
    return payload.empty() ? "Error message without a code" : xbusErrorText(payload.front());
}

// ---- baud rates ---------------------------------------------------------------------------

std::optional<std::uint8_t> xbusBaudCode(std::uint32_t baud)
{
    switch (baud) {
    case 460800: return 0x00;
    case 230400: return 0x01;
    case 115200: return 0x02;
    case 76800: return 0x03;
    case 57600: return 0x04;
    case 38400: return 0x05;
    case 28800: return 0x06;
    case 19200: return 0x07;
    case 14400: return 0x08;
    case 9600: return 0x09;
    case 921600: return 0x80;
    case 4800: return 0x0B;
    case 2000000: return 0x0C;
    default: return std::nullopt;  // 3.5/3.6864/4 Mbaud codes conflict between sources (§2.5)
    }
}

std::optional<std::uint32_t> xbusBaudFromCode(std::uint8_t code)
{
    static const std::uint32_t kByCode[] = {460800, 230400, 115200, 76800, 57600, 38400, 28800,
                                            19200,  14400,  9600,   921600, 4800,  2000000};
    if (code < std::size(kByCode))
        return kByCode[code];
    if (code == 0x80)
        return 921600;
    return std::nullopt;
}

const std::vector<std::uint32_t>& xbusProbeBaudRates()
{
    static const std::vector<std::uint32_t> rates = {115200, 2000000, 921600, 460800, 230400,
                                                     57600,  38400,   19200,  9600};
    return rates;
}

// ---- output configuration -----------------------------------------------------------------

std::vector<OutputConfigEntry> footpathOutputConfiguration(std::uint16_t rate_hz)
{
    using namespace MtData2Id;
    return {
        {PacketCounter, OutputConfigEntry::kEveryMessage},
        {SampleTimeFine, OutputConfigEntry::kEveryMessage},
        {Acceleration, rate_hz},
        {RateOfTurn, rate_hz},
        {MagneticField, rate_hz},
        {BaroPressure, rate_hz},
    };
}

std::string describeOutputConfiguration(const std::vector<OutputConfigEntry>& entries)
{
    std::string text;
    for (const OutputConfigEntry& entry : entries) {
        text += text.empty() ? "" : ", ";
        text += dataIdName(entry.dataId);
        text += entry.rate_hz == OutputConfigEntry::kEveryMessage ? " (every message)"
                                                                  : " " + std::to_string(entry.rate_hz) + " Hz";
    }
    return text.empty() ? "nothing" : text;
}

std::optional<OutputConfigEntry> findOutputEntry(const std::vector<OutputConfigEntry>& entries,
                                                 std::uint16_t dataId)
{
    const auto found = std::find_if(entries.begin(), entries.end(), [dataId](const OutputConfigEntry& entry) {
        return (entry.dataId & MtData2Id::kTypeMask) == (dataId & MtData2Id::kTypeMask);
    });
    return found != entries.end() ? std::optional<OutputConfigEntry>(*found) : std::nullopt;
}

std::vector<std::uint8_t> encodeOutputConfiguration(const std::vector<OutputConfigEntry>& entries)
{
    std::vector<std::uint8_t> payload;
    payload.reserve(4 * entries.size());
    for (const OutputConfigEntry& entry : entries) {
        appendBigEndian(payload, entry.dataId, 2);
        appendBigEndian(payload, entry.rate_hz, 2);
    }
    return payload;
}

// ---- replies ------------------------------------------------------------------------------

std::string FirmwareRevision::toString() const
{
    std::string text = std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(revision);
    if (build)
        text += " build " + std::to_string(*build);
    if (svnRevision)
        text += " rev " + std::to_string(*svnRevision);
    return text;
}

XbusParsed<std::uint64_t> parseDeviceId(const std::vector<std::uint8_t>& payload)
{
    if (payload.size() != 4 && payload.size() != 8)
        return unexpectedSize("DeviceID", payload.size(), "4 or 8");
    XbusParsed<std::uint64_t> parsed;
    XbusPayloadReader reader(payload.data(), payload.size());
    reader.readUnsigned(payload.size(), parsed.value);
    return parsed;
}

std::string formatDeviceId(std::uint64_t deviceId)
{
    return hex(deviceId, deviceId > 0xFFFFFFFFu ? 16 : 8);
}

XbusParsed<std::string> parseProductCode(const std::vector<std::uint8_t>& payload)
{
    XbusParsed<std::string> parsed;
    for (const std::uint8_t byte : payload) {
        if (byte == ' ' || byte == 0)
            break;
        if (byte < 0x20 || byte > 0x7E) {
            parsed.error = "ProductCode contains the non-ASCII byte 0x" + hex(byte, 2);
            return parsed;
        }
        parsed.value.push_back(static_cast<char>(byte));
    }
    if (parsed.value.empty())
        parsed.error = "ProductCode is empty";
    return parsed;
}

XbusParsed<FirmwareRevision> parseFirmwareRevision(const std::vector<std::uint8_t>& payload)
{
    XbusParsed<FirmwareRevision> parsed;
    if (payload.size() != 3 && payload.size() != 11) {
        parsed.error = "FirmwareRev has " + std::to_string(payload.size()) + " bytes, expected 3 or 11";
        return parsed;
    }
    XbusPayloadReader reader(payload.data(), payload.size());
    FirmwareRevision& firmware = parsed.value;
    reader.readU8(firmware.major);
    reader.readU8(firmware.minor);
    reader.readU8(firmware.revision);
    std::uint32_t build = 0;
    std::uint32_t svn = 0;
    if (reader.readU32(build) && reader.readU32(svn)) {
        firmware.build = build;
        firmware.svnRevision = svn;
    }
    return parsed;
}

XbusParsed<std::vector<OutputConfigEntry>> parseOutputConfiguration(const std::vector<std::uint8_t>& payload)
{
    XbusParsed<std::vector<OutputConfigEntry>> parsed;
    if (payload.size() % 4 != 0) {
        parsed.error = "output configuration has " + std::to_string(payload.size())
                       + " bytes, not a multiple of 4 (identifier and rate per entry)";
        return parsed;
    }
    if (payload.size() / 4 > OutputConfigEntry::kMaxEntries) {
        parsed.error = "output configuration has " + std::to_string(payload.size() / 4) + " entries, at most "
                       + std::to_string(OutputConfigEntry::kMaxEntries) + " are allowed";
        return parsed;
    }
    XbusPayloadReader reader(payload.data(), payload.size());
    OutputConfigEntry entry;
    while (reader.readU16(entry.dataId) && reader.readU16(entry.rate_hz))
        parsed.value.push_back(entry);
    return parsed;
}

XbusParsed<std::uint8_t> parseBaudCode(const std::vector<std::uint8_t>& payload)
{
    XbusParsed<std::uint8_t> parsed;
    if (payload.size() != 1)
        parsed.error = "baud rate reply has " + std::to_string(payload.size()) + " bytes, expected 1";
    else
        parsed.value = payload.front();
    return parsed;
}

// ---- builders -----------------------------------------------------------------------------

XbusMessage xbusMessage(std::uint8_t mid, std::vector<std::uint8_t> payload)
{
    XbusMessage message;
    message.busId = kXbusMasterBusId;
    message.mid = mid;
    message.payload = std::move(payload);
    return message;
}

XbusMessage goToConfigMessage() { return xbusMessage(XbusMid::GoToConfig); }
XbusMessage goToMeasurementMessage() { return xbusMessage(XbusMid::GoToMeasurement); }
XbusMessage wakeUpAckMessage() { return xbusMessage(XbusMid::WakeUpAck); }
XbusMessage resetMessage() { return xbusMessage(XbusMid::Reset); }
XbusMessage reqDeviceIdMessage() { return xbusMessage(XbusMid::ReqDid); }
XbusMessage reqProductCodeMessage() { return xbusMessage(XbusMid::ReqProductCode); }
XbusMessage reqFirmwareRevMessage() { return xbusMessage(XbusMid::ReqFwRev); }
XbusMessage reqBaudrateMessage() { return xbusMessage(XbusMid::SetBaudrate); }
XbusMessage setBaudrateMessage(std::uint8_t baudCode) { return xbusMessage(XbusMid::SetBaudrate, {baudCode}); }
XbusMessage reqOutputConfigurationMessage() { return xbusMessage(XbusMid::SetOutputConfiguration); }

std::optional<XbusMessage> setOutputConfigurationMessage(const std::vector<OutputConfigEntry>& entries)
{
    // An empty list would be the *request* for the current configuration (LEN 0, §1.3).
    if (entries.empty() || entries.size() > OutputConfigEntry::kMaxEntries)
        return std::nullopt;
    return xbusMessage(XbusMid::SetOutputConfiguration, encodeOutputConfiguration(entries));
}

XbusMessage wakeUpMessage() { return xbusMessage(XbusMid::WakeUp); }
XbusMessage ackMessage(std::uint8_t requestMid) { return xbusMessage(xbusReplyMid(requestMid)); }

XbusMessage deviceIdMessage(std::uint64_t deviceId)
{
    std::vector<std::uint8_t> payload;
    appendBigEndian(payload, deviceId, deviceId > 0xFFFFFFFFu ? 8 : 4);
    return xbusMessage(XbusMid::DeviceId, std::move(payload));
}

XbusMessage productCodeMessage(const std::string& productCode)
{
    const std::size_t size = std::min<std::size_t>(productCode.size(), 20);
    return xbusMessage(XbusMid::ProductCode, std::vector<std::uint8_t>(productCode.begin(), productCode.begin()
                                                                           + static_cast<std::ptrdiff_t>(size)));
}

XbusMessage firmwareRevMessage(const FirmwareRevision& firmware)
{
    std::vector<std::uint8_t> payload = {firmware.major, firmware.minor, firmware.revision};
    if (firmware.build || firmware.svnRevision) {
        appendBigEndian(payload, firmware.build.value_or(0), 4);
        appendBigEndian(payload, firmware.svnRevision.value_or(0), 4);
    }
    return xbusMessage(XbusMid::FirmwareRev, std::move(payload));
}

XbusMessage baudrateMessage(std::uint8_t baudCode) { return xbusMessage(XbusMid::BaudrateAck, {baudCode}); }

XbusMessage outputConfigurationMessage(const std::vector<OutputConfigEntry>& entries)
{
    return xbusMessage(XbusMid::OutputConfiguration, encodeOutputConfiguration(entries));
}

XbusMessage errorMessage(std::uint8_t code) { return xbusMessage(XbusMid::Error, {code}); }

XbusConfiguration mtData2Configuration(std::uint64_t deviceId, std::uint16_t rate_hz, const FirmwareRevision& firmware)
{
    constexpr std::uint32_t kLegacyClock_hz = 115200;  // the period counts ticks of this clock (§6.4)
    XbusConfiguration configuration;
    configuration.masterDeviceId = static_cast<std::uint32_t>(deviceId);
    // 0 when the rate is no whole divisor of the clock or its period does not fit 16 bits (below 2 Hz).
    const bool periodFits = rate_hz > 0 && kLegacyClock_hz % rate_hz == 0 && kLegacyClock_hz / rate_hz <= UINT16_MAX;
    configuration.samplingPeriod = periodFits ? static_cast<std::uint16_t>(kLegacyClock_hz / rate_hz) : std::uint16_t{0};
    XbusConfiguration::Device device;
    device.deviceId = static_cast<std::uint32_t>(deviceId);
    device.layout.outputMode = 0;  // MTData2 devices leave the legacy layout empty
    device.layout.outputSettings = 0;
    device.firmware = {firmware.major, firmware.minor, firmware.revision};
    configuration.devices.push_back(device);
    return configuration;
}

}  // namespace footpath
