#pragma once

#include "xbus/MtData2.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace footpath {

// Legacy MTi / MTx / MTi-G (2005-2012) send MTData (0x32) with a fixed layout chosen by
// OutputMode and OutputSettings (docs/xbus.md §6); the Configuration message (0x0D)
// tells which, and is also the first message of every .mtb log.

/// OutputMode bits (§6.1): which blocks an MTData message carries.
namespace LegacyOutputMode {
constexpr std::uint16_t Temperature = 0x0001;
constexpr std::uint16_t Calibrated = 0x0002;
constexpr std::uint16_t Orientation = 0x0004;
constexpr std::uint16_t Auxiliary = 0x0008;
constexpr std::uint16_t Position = 0x0010;
constexpr std::uint16_t Velocity = 0x0020;
constexpr std::uint16_t Status = 0x0800;
constexpr std::uint16_t GpsPvt = 0x1000;
constexpr std::uint16_t Raw = 0x4000;
}  // namespace LegacyOutputMode

/// OutputSettings bits (§6.2): how the blocks look.
namespace LegacyOutputSettings {
constexpr std::uint32_t TimestampMask = 0x00000003;
constexpr std::uint32_t TimestampNone = 0x0;
constexpr std::uint32_t TimestampSampleCounter = 0x1;
constexpr std::uint32_t TimestampUtc = 0x2;
constexpr std::uint32_t OrientationMask = 0x0000000C;
constexpr std::uint32_t OrientationQuaternion = 0x0;
constexpr std::uint32_t OrientationEuler = 0x4;
constexpr std::uint32_t OrientationMatrix = 0x8;
constexpr std::uint32_t DisableAcc = 0x00000010;
constexpr std::uint32_t DisableGyr = 0x00000020;
constexpr std::uint32_t DisableMag = 0x00000040;
constexpr std::uint32_t FormatMask = 0x00000300;
constexpr unsigned FormatShift = 8;  ///< format values are the XdaPrecision values
constexpr std::uint32_t DisableAin1 = 0x00000400;
constexpr std::uint32_t DisableAin2 = 0x00000800;
constexpr std::uint32_t Ned = 0x80000000;
}  // namespace LegacyOutputSettings

/// What a legacy MTData payload contains. The defaults are the legacy factory settings:
/// orientation quaternion plus sample counter, float32.
struct LegacyDataLayout {
    std::uint16_t outputMode = LegacyOutputMode::Orientation;
    std::uint32_t outputSettings = LegacyOutputSettings::TimestampSampleCounter;

    XdaPrecision precision() const;
    /// Empty if the combination is one a device can send; else what is wrong.
    std::string validate() const;
    /// The MTData payload length this layout produces.
    std::size_t payloadSize() const;
};

/// The Configuration message (0x0D, §6.5): 98 bytes plus 20 per device.
struct XbusConfiguration {
    struct Device {
        std::uint32_t deviceId = 0;
        std::uint16_t dataLength = 0;  ///< legacy MTData length; 0 on MTData2 devices
        LegacyDataLayout layout;       ///< zero on MTData2 devices
        std::uint16_t filterProfile = 0;
        std::array<std::uint8_t, 3> firmware{};  ///< major, minor, revision
        char filterType = '\0';
        std::array<std::uint8_t, 2> filterVersion{};
    };

    std::uint32_t masterDeviceId = 0;
    std::uint16_t samplingPeriod = 1152;  ///< ticks of 1/115200 s (1152 = 100 Hz)
    std::uint16_t outputSkipFactor = 0;   ///< 0xFFFF: data only on request
    std::string date;  ///< "YYYYMMDD" as the logger wrote it (may be empty)
    std::string time;  ///< "HHMMSSss"
    std::vector<Device> devices;

    /// 115200 / (period * (skip + 1)); 0 if the period is 0 or data is only sent on request.
    double outputRate_hz() const;
};

struct XbusConfigurationParsed {
    XbusConfiguration configuration;
    std::string error;  ///< empty if the payload was well formed
    bool ok() const { return error.empty(); }
};

XbusConfigurationParsed parseConfiguration(const std::uint8_t* payload, std::size_t size);
inline XbusConfigurationParsed parseConfiguration(const std::vector<std::uint8_t>& payload)
{
    return parseConfiguration(payload.data(), payload.size());
}
std::vector<std::uint8_t> encodeConfiguration(const XbusConfiguration& configuration);

/// Decodes a legacy MTData payload (0x32) into the MTData2 sample: temperature, calibrated acc,
/// gyr and mag, quaternion or Euler orientation, status byte and sample counter (as packetCounter).
/// Raw, GPS, auxiliary, position, velocity, UTC and matrix blocks are stepped over. A payload
/// whose length does not match the layout is an error.
MtData2Decoded decodeLegacyMtData(const std::uint8_t* payload, std::size_t size, const LegacyDataLayout& layout);
inline MtData2Decoded decodeLegacyMtData(const std::vector<std::uint8_t>& payload, const LegacyDataLayout& layout)
{
    return decodeLegacyMtData(payload.data(), payload.size(), layout);
}
/// The MTData payload `layout` describes; blocks the sample lacks are written as zeros.
std::vector<std::uint8_t> encodeLegacyMtData(const MtData2Sample& sample, const LegacyDataLayout& layout);

}  // namespace footpath
