#pragma once

#include "xbus/LegacyMtData.h"
#include "xbus/XbusFrame.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace footpath {

// The control messages of the host initialisation sequence (docs/xbus.md §4.2) and
// their replies: builders for both directions (the host driver sends requests, the emulator
// answers), parsers of the replies, and the device's Error codes in words. Pure: no I/O.

/// Message identifiers of the init sequence, beside the data MIDs of XbusFrame.h (§2.1-2.4).
namespace XbusMid {
constexpr std::uint8_t ReqDid = 0x00;
constexpr std::uint8_t DeviceId = 0x01;
constexpr std::uint8_t ReqConfiguration = 0x0C;
constexpr std::uint8_t GoToMeasurementAck = 0x11;
constexpr std::uint8_t ReqFwRev = 0x12;
constexpr std::uint8_t FirmwareRev = 0x13;
constexpr std::uint8_t SetBaudrate = 0x18;  ///< also ReqBaudrate (no payload)
constexpr std::uint8_t BaudrateAck = 0x19;
constexpr std::uint8_t ReqProductCode = 0x1C;
constexpr std::uint8_t ProductCode = 0x1D;
constexpr std::uint8_t ReqHardwareVersion = 0x1E;
constexpr std::uint8_t HardwareVersion = 0x1F;
constexpr std::uint8_t GoToConfigAck = 0x31;
constexpr std::uint8_t WakeUpAck = 0x3F;
constexpr std::uint8_t Reset = 0x40;
constexpr std::uint8_t ResetAck = 0x41;
constexpr std::uint8_t Warning = 0x43;
constexpr std::uint8_t SetOutputConfiguration = 0xC0;  ///< also ReqOutputConfiguration (no payload)
constexpr std::uint8_t OutputConfiguration = 0xC1;
}  // namespace XbusMid

/// The acknowledgement of a request is the next MID (§1.3).
constexpr std::uint8_t xbusReplyMid(std::uint8_t requestMid)
{
    return static_cast<std::uint8_t>(requestMid + 1);
}

/// A short name for log lines and messages: "GoToConfig", "ReqDID", ..., else "MID 0x5A".
std::string xbusMidName(std::uint8_t mid);

// ---- device error codes (§2.6) ------------------------------------------------------------

namespace XbusErrorCode {
constexpr std::uint8_t InvalidPeriod = 0x03;
constexpr std::uint8_t InvalidMessage = 0x04;  ///< unknown or not implemented MID
constexpr std::uint8_t TimerOverflow = 0x1E;
constexpr std::uint8_t BaudRateInvalid = 0x20;
constexpr std::uint8_t InvalidParameter = 0x21;
constexpr std::uint8_t DataOverflow = 0x29;
constexpr std::uint8_t OutputConfigurationError = 0x35;
}  // namespace XbusErrorCode

/// "message invalid or not implemented (error 4)"; unknown codes say so with their number.
std::string xbusErrorText(std::uint8_t code);
/// The text of an Error message's payload; an empty payload is "Error message without a code".
std::string xbusErrorText(const std::vector<std::uint8_t>& payload);

// ---- baud rates (§2.5) --------------------------------------------------------------------

/// The code for a baud rate; nothing for rates the protocol has no code for. 921600 is sent with
/// the legacy code 0x80 as XSP and the MTi documentation do.
std::optional<std::uint8_t> xbusBaudCode(std::uint32_t baud);
/// The baud rate of a code (both 0x0A and 0x80 mean 921600); nothing for unknown codes.
std::optional<std::uint32_t> xbusBaudFromCode(std::uint8_t code);
/// The order a scan tries rates in when the configured one does not answer (XSP's order, §4.3).
const std::vector<std::uint32_t>& xbusProbeBaudRates();

// ---- output configuration (§4.4) ----------------------------------------------------------

/// One entry of SetOutputConfiguration: a data identifier and its rate in Hz.
struct OutputConfigEntry {
    /// Counters, times and status are sent with every message: the device reports them at 0xFFFF.
    static constexpr std::uint16_t kEveryMessage = 0xFFFF;
    static constexpr std::size_t kMaxEntries = 32;

    std::uint16_t dataId = 0;
    std::uint16_t rate_hz = 0;

    bool operator==(const OutputConfigEntry& other) const
    {
        return dataId == other.dataId && rate_hz == other.rate_hz;
    }
    bool operator!=(const OutputConfigEntry& other) const { return !(*this == other); }
};

/// What Footpath asks a live MTi for: packet counter and SampleTimeFine with every message, and
/// acceleration, rate of turn, magnetic field and pressure at `rate_hz` (float32, sensor frame).
std::vector<OutputConfigEntry> footpathOutputConfiguration(std::uint16_t rate_hz);
/// "Acceleration 100 Hz, PacketCounter (every message), ...".
std::string describeOutputConfiguration(const std::vector<OutputConfigEntry>& entries);
/// The entry whose identifier has the type of `dataId` (precision and frame bits ignored).
std::optional<OutputConfigEntry> findOutputEntry(const std::vector<OutputConfigEntry>& entries,
                                                 std::uint16_t dataId);

// ---- replies ------------------------------------------------------------------------------

/// FirmwareRev: 3 bytes on older firmware, 11 with build and SVN revision on newer (§2.2).
struct FirmwareRevision {
    std::uint8_t major = 0;
    std::uint8_t minor = 0;
    std::uint8_t revision = 0;
    std::optional<std::uint32_t> build;
    std::optional<std::uint32_t> svnRevision;

    std::string toString() const;  ///< "1.8.2" or "1.8.2 build 37 rev 70964"
};

/// A parsed reply: the value, or in `error` what was wrong with the payload.
template <typename T>
struct XbusParsed {
    T value{};
    std::string error;
    bool ok() const { return error.empty(); }
};

/// DeviceID: 4 bytes, or 8 on devices with 64-bit identifiers.
XbusParsed<std::uint64_t> parseDeviceId(const std::vector<std::uint8_t>& payload);
/// "037003F8" (8 hex digits, 16 for 64-bit identifiers), as MT Manager shows it.
std::string formatDeviceId(std::uint64_t deviceId);
/// ProductCode: ASCII up to 20 bytes, cut at the first space or NUL as XSP does.
XbusParsed<std::string> parseProductCode(const std::vector<std::uint8_t>& payload);
XbusParsed<FirmwareRevision> parseFirmwareRevision(const std::vector<std::uint8_t>& payload);
/// OutputConfiguration (and the payload of SetOutputConfiguration): N x (id u16, rate u16).
XbusParsed<std::vector<OutputConfigEntry>> parseOutputConfiguration(const std::vector<std::uint8_t>& payload);
XbusParsed<std::uint8_t> parseBaudCode(const std::vector<std::uint8_t>& payload);

// ---- builders -----------------------------------------------------------------------------

/// A message to or from the single device on a serial line (bus id 0xFF).
XbusMessage xbusMessage(std::uint8_t mid, std::vector<std::uint8_t> payload = {});

// Host to device.
XbusMessage goToConfigMessage();
XbusMessage goToMeasurementMessage();
XbusMessage wakeUpAckMessage();
XbusMessage resetMessage();
XbusMessage reqDeviceIdMessage();
XbusMessage reqProductCodeMessage();
XbusMessage reqFirmwareRevMessage();
XbusMessage reqBaudrateMessage();
XbusMessage setBaudrateMessage(std::uint8_t baudCode);
XbusMessage reqOutputConfigurationMessage();
/// Empty when more than OutputConfigEntry::kMaxEntries entries are given (no device accepts it).
std::optional<XbusMessage> setOutputConfigurationMessage(const std::vector<OutputConfigEntry>& entries);

// Device to host.
XbusMessage wakeUpMessage();
/// The empty acknowledgement of `requestMid` (GoToConfigAck, ResetAck, BaudrateAck, ...).
XbusMessage ackMessage(std::uint8_t requestMid);
/// 4 bytes unless the identifier needs 8.
XbusMessage deviceIdMessage(std::uint64_t deviceId);
XbusMessage productCodeMessage(const std::string& productCode);
XbusMessage firmwareRevMessage(const FirmwareRevision& firmware);
XbusMessage baudrateMessage(std::uint8_t baudCode);
XbusMessage outputConfigurationMessage(const std::vector<OutputConfigEntry>& entries);
XbusMessage errorMessage(std::uint8_t code);

/// The Configuration (0x0D) of a single MTData2 device, as a device sends it before streaming and
/// a logger writes it first into an .mtb file (§7.1). The sampling period is stated only when
/// 115200 / rate is whole; otherwise it is 0 and readers take the rate from SampleTimeFine.
XbusConfiguration mtData2Configuration(std::uint64_t deviceId, std::uint16_t rate_hz, const FirmwareRevision& firmware);

/// The payload of an output configuration (shared by the Set request and its echo).
std::vector<std::uint8_t> encodeOutputConfiguration(const std::vector<OutputConfigEntry>& entries);

}  // namespace footpath
