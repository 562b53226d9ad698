#include "xbus/LegacyMtData.h"

#include <cstdio>

namespace footpath {

namespace {

using namespace LegacyOutputSettings;
namespace Mode = LegacyOutputMode;

constexpr std::size_t kConfigurationHeaderSize = 98;
constexpr std::size_t kConfigurationDeviceSize = 20;
constexpr std::size_t kConfigurationTextSize = 8;  ///< date and time fields
constexpr double kLegacyClock_hz = 115200.0;
constexpr std::size_t kRawBlockSize = 20;      ///< 10 x u16 ADC counts
constexpr std::size_t kGpsPvtBlockSize = 44;   ///< pressure, iTOW, LLA, NED velocity, accuracies
constexpr std::size_t kUtcBlockSize = 12;

std::string hex(std::uint32_t value, int digits)
{
    char text[16];
    std::snprintf(text, sizeof text, "0x%0*X", digits, static_cast<unsigned>(value));
    return text;
}

bool has(std::uint16_t mode, std::uint16_t flag)
{
    return (mode & flag) != 0;
}

bool enabled(std::uint32_t settings, std::uint32_t disableFlag)
{
    return (settings & disableFlag) == 0;
}

std::size_t orientationValueCount(std::uint32_t settings)
{
    switch (settings & OrientationMask) {
    case OrientationQuaternion: return 4;
    case OrientationEuler: return 3;
    default: return 9;  // matrix
    }
}

std::size_t calibratedVectorCount(std::uint32_t settings)
{
    return std::size_t{enabled(settings, DisableAcc)} + enabled(settings, DisableGyr) + enabled(settings, DisableMag);
}

std::string readText(XbusPayloadReader& reader, std::size_t size)
{
    const std::uint8_t* bytes = nullptr;
    if (!reader.view(size, bytes))
        return {};
    std::string text(reinterpret_cast<const char*>(bytes), size);
    return text.substr(0, text.find('\0'));
}

void appendText(std::vector<std::uint8_t>& out, const std::string& text, std::size_t size)
{
    for (std::size_t i = 0; i < size; ++i)
        out.push_back(i < text.size() ? static_cast<std::uint8_t>(text[i]) : 0);
}

XbusConfiguration::Device readDevice(XbusPayloadReader& reader)
{
    XbusConfiguration::Device device;
    std::uint8_t filterType = 0;
    reader.readU32(device.deviceId);
    reader.readU16(device.dataLength);
    reader.readU16(device.layout.outputMode);
    reader.readU32(device.layout.outputSettings);
    reader.readU16(device.filterProfile);
    for (std::uint8_t& part : device.firmware)
        reader.readU8(part);
    reader.readU8(filterType);
    device.filterType = static_cast<char>(filterType);
    for (std::uint8_t& part : device.filterVersion)
        reader.readU8(part);
    return device;
}

bool readVector(XbusPayloadReader& reader, XdaPrecision precision, Eigen::Vector3d& v)
{
    return readXdaReal(reader, precision, v.x()) && readXdaReal(reader, precision, v.y())
           && readXdaReal(reader, precision, v.z());
}

/// Reads the calibrated block: each of acc, gyr, mag unless disabled.
void readCalibrated(XbusPayloadReader& reader, const LegacyDataLayout& layout, MtData2Sample& sample)
{
    const XdaPrecision precision = layout.precision();
    const std::uint32_t settings = layout.outputSettings;
    Eigen::Vector3d v;
    if (enabled(settings, DisableAcc) && readVector(reader, precision, v))
        sample.acceleration = v;
    if (enabled(settings, DisableGyr) && readVector(reader, precision, v))
        sample.rateOfTurn = v;
    if (enabled(settings, DisableMag) && readVector(reader, precision, v))
        sample.magneticField = v;
}

void readOrientation(XbusPayloadReader& reader, const LegacyDataLayout& layout, MtData2Sample& sample)
{
    const XdaPrecision precision = layout.precision();
    const std::size_t count = orientationValueCount(layout.outputSettings);
    double values[9] = {};
    for (std::size_t i = 0; i < count; ++i)
        readXdaReal(reader, precision, values[i]);
    if (count == 4)
        sample.quaternion = Eigen::Quaterniond(values[0], values[1], values[2], values[3]);
    else if (count == 3)
        sample.euler_deg = Eigen::Vector3d(values[0], values[1], values[2]);
    // A rotation matrix has no place in the sample; it is stepped over.
    // Legacy devices use X north, Z up (NWU) unless the NED bit is set (§6.2).
    sample.orientationFrame = (layout.outputSettings & Ned) ? XdaCoordinateFrame::Ned : XdaCoordinateFrame::Nwu;
}

/// Reads the blocks after orientation: auxiliary, position, velocity, status, timestamp.
void readTrailer(XbusPayloadReader& reader, const LegacyDataLayout& layout, MtData2Sample& sample)
{
    const std::uint16_t mode = layout.outputMode;
    const std::uint32_t settings = layout.outputSettings;
    const std::size_t valueSize = xdaValueSize(layout.precision());
    if (has(mode, Mode::Auxiliary))
        reader.skip(2 * (std::size_t{enabled(settings, DisableAin1)} + enabled(settings, DisableAin2)));
    if (has(mode, Mode::Position))
        reader.skip(3 * valueSize);
    if (has(mode, Mode::Velocity))
        reader.skip(3 * valueSize);
    std::uint8_t status = 0;
    if (has(mode, Mode::Status) && reader.readU8(status))
        sample.statusByte = status;
    std::uint16_t counter = 0;
    if ((settings & TimestampMask) == TimestampSampleCounter && reader.readU16(counter))
        sample.packetCounter = counter;
}

void appendVector(std::vector<std::uint8_t>& out, const std::optional<Eigen::Vector3d>& v, XdaPrecision precision)
{
    const Eigen::Vector3d value = v.value_or(Eigen::Vector3d::Zero());
    for (int i = 0; i < 3; ++i)
        appendXdaReal(out, value[i], precision);
}

void appendOrientation(std::vector<std::uint8_t>& out, const MtData2Sample& sample, const LegacyDataLayout& layout)
{
    const XdaPrecision precision = layout.precision();
    switch (layout.outputSettings & OrientationMask) {
    case OrientationQuaternion: {
        const Eigen::Quaterniond q = sample.quaternion.value_or(Eigen::Quaterniond(0, 0, 0, 0));
        for (double value : {q.w(), q.x(), q.y(), q.z()})
            appendXdaReal(out, value, precision);
        return;
    }
    case OrientationEuler: appendVector(out, sample.euler_deg, precision); return;
    default: out.insert(out.end(), 9 * xdaValueSize(precision), 0); return;
    }
}

void appendTrailer(std::vector<std::uint8_t>& out, const MtData2Sample& sample, const LegacyDataLayout& layout)
{
    const std::uint16_t mode = layout.outputMode;
    const std::uint32_t settings = layout.outputSettings;
    const std::size_t valueSize = xdaValueSize(layout.precision());
    std::size_t zeros = 0;
    if (has(mode, Mode::Auxiliary))
        zeros += 2 * (std::size_t{enabled(settings, DisableAin1)} + enabled(settings, DisableAin2));
    if (has(mode, Mode::Position))
        zeros += 3 * valueSize;
    if (has(mode, Mode::Velocity))
        zeros += 3 * valueSize;
    out.insert(out.end(), zeros, 0);
    if (has(mode, Mode::Status))
        out.push_back(sample.statusByte.value_or(0));
    if ((settings & TimestampMask) == TimestampSampleCounter)
        appendBigEndian(out, sample.packetCounter.value_or(0), 2);
    if ((settings & TimestampMask) == TimestampUtc)
        out.insert(out.end(), kUtcBlockSize, 0);
}

}  // namespace

XdaPrecision LegacyDataLayout::precision() const
{
    return static_cast<XdaPrecision>((outputSettings & FormatMask) >> FormatShift);
}

std::string LegacyDataLayout::validate() const
{
    if ((outputSettings & TimestampMask) == 0x3)
        return "output settings " + hex(outputSettings, 8) + " select an undefined timestamp (3)";
    if ((outputSettings & OrientationMask) == 0xC)
        return "output settings " + hex(outputSettings, 8) + " select an undefined orientation format (0xC)";
    if (has(outputMode, Mode::Raw) && has(outputMode, Mode::Calibrated | Mode::Orientation))
        return "output mode " + hex(outputMode, 4) + " combines raw with calibrated or orientation data";
    return {};
}

std::size_t LegacyDataLayout::payloadSize() const
{
    const std::size_t valueSize = xdaValueSize(precision());
    std::size_t size = 0;
    size += has(outputMode, Mode::Raw) ? kRawBlockSize : 0;
    size += has(outputMode, Mode::GpsPvt) ? kGpsPvtBlockSize : 0;
    size += has(outputMode, Mode::Temperature) ? valueSize : 0;
    size += has(outputMode, Mode::Calibrated) ? 3 * valueSize * calibratedVectorCount(outputSettings) : 0;
    size += has(outputMode, Mode::Orientation) ? valueSize * orientationValueCount(outputSettings) : 0;
    if (has(outputMode, Mode::Auxiliary))
        size += 2 * (std::size_t{enabled(outputSettings, DisableAin1)} + enabled(outputSettings, DisableAin2));
    size += has(outputMode, Mode::Position) ? 3 * valueSize : 0;
    size += has(outputMode, Mode::Velocity) ? 3 * valueSize : 0;
    size += has(outputMode, Mode::Status) ? 1 : 0;
    const std::uint32_t timestamp = outputSettings & TimestampMask;
    size += timestamp == TimestampSampleCounter ? 2 : timestamp == TimestampUtc ? kUtcBlockSize : 0;
    return size;
}

double XbusConfiguration::outputRate_hz() const
{
    if (samplingPeriod == 0 || outputSkipFactor == 0xFFFF)
        return 0.0;
    return kLegacyClock_hz / (static_cast<double>(samplingPeriod) * (outputSkipFactor + 1.0));
}

XbusConfigurationParsed parseConfiguration(const std::uint8_t* payload, std::size_t size)
{
    XbusConfigurationParsed result;
    XbusConfiguration& configuration = result.configuration;
    if (size < kConfigurationHeaderSize) {
        result.error = "Configuration message has " + std::to_string(size) + " bytes, at least "
                       + std::to_string(kConfigurationHeaderSize) + " expected";
        return result;
    }
    XbusPayloadReader reader(payload, size);
    std::uint16_t deviceCount = 0;
    reader.readU32(configuration.masterDeviceId);
    reader.readU16(configuration.samplingPeriod);
    reader.readU16(configuration.outputSkipFactor);
    reader.skip(8);  // SyncIn mode, skip factor and offset (legacy) or reserved
    configuration.date = readText(reader, kConfigurationTextSize);
    configuration.time = readText(reader, kConfigurationTextSize);
    reader.skip(64);  // reserved for host and client (product code on newer devices)
    reader.readU16(deviceCount);
    const std::size_t expected = kConfigurationHeaderSize + kConfigurationDeviceSize * deviceCount;
    if (size != expected) {
        result.error = "Configuration message has " + std::to_string(size) + " bytes, but announces "
                       + std::to_string(deviceCount) + " device(s), which take " + std::to_string(expected);
        return result;
    }
    for (std::uint16_t i = 0; i < deviceCount; ++i)
        configuration.devices.push_back(readDevice(reader));
    return result;
}

std::vector<std::uint8_t> encodeConfiguration(const XbusConfiguration& configuration)
{
    std::vector<std::uint8_t> out;
    out.reserve(kConfigurationHeaderSize + kConfigurationDeviceSize * configuration.devices.size());
    appendBigEndian(out, configuration.masterDeviceId, 4);
    appendBigEndian(out, configuration.samplingPeriod, 2);
    appendBigEndian(out, configuration.outputSkipFactor, 2);
    out.insert(out.end(), 8, 0);
    appendText(out, configuration.date, kConfigurationTextSize);
    appendText(out, configuration.time, kConfigurationTextSize);
    out.insert(out.end(), 64, 0);
    appendBigEndian(out, configuration.devices.size(), 2);
    for (const XbusConfiguration::Device& device : configuration.devices) {
        appendBigEndian(out, device.deviceId, 4);
        appendBigEndian(out, device.dataLength, 2);
        appendBigEndian(out, device.layout.outputMode, 2);
        appendBigEndian(out, device.layout.outputSettings, 4);
        appendBigEndian(out, device.filterProfile, 2);
        out.insert(out.end(), device.firmware.begin(), device.firmware.end());
        out.push_back(static_cast<std::uint8_t>(device.filterType));
        out.insert(out.end(), device.filterVersion.begin(), device.filterVersion.end());
    }
    return out;
}

MtData2Decoded decodeLegacyMtData(const std::uint8_t* payload, std::size_t size, const LegacyDataLayout& layout)
{
    MtData2Decoded result;
    result.error = layout.validate();
    if (!result.ok())
        return result;
    if (size != layout.payloadSize()) {
        result.error = "legacy MTData has " + std::to_string(size) + " bytes, but output mode "
                       + hex(layout.outputMode, 4) + " with settings " + hex(layout.outputSettings, 8) + " gives "
                       + std::to_string(layout.payloadSize());
        return result;
    }
    // The length check above guarantees every read below has its bytes (§6.3 block order).
    XbusPayloadReader reader(payload, size);
    const std::uint16_t mode = layout.outputMode;
    reader.skip(has(mode, Mode::Raw) ? kRawBlockSize : 0);
    reader.skip(has(mode, Mode::GpsPvt) ? kGpsPvtBlockSize : 0);
    double temperature = 0.0;
    if (has(mode, Mode::Temperature) && readXdaReal(reader, layout.precision(), temperature))
        result.sample.temperature_degC = temperature;
    if (has(mode, Mode::Calibrated))
        readCalibrated(reader, layout, result.sample);
    if (has(mode, Mode::Orientation))
        readOrientation(reader, layout, result.sample);
    readTrailer(reader, layout, result.sample);
    return result;
}

std::vector<std::uint8_t> encodeLegacyMtData(const MtData2Sample& sample, const LegacyDataLayout& layout)
{
    const XdaPrecision precision = layout.precision();
    const std::uint16_t mode = layout.outputMode;
    const std::uint32_t settings = layout.outputSettings;
    std::vector<std::uint8_t> out;
    out.reserve(layout.payloadSize());
    out.insert(out.end(), has(mode, Mode::Raw) ? kRawBlockSize : 0, 0);
    out.insert(out.end(), has(mode, Mode::GpsPvt) ? kGpsPvtBlockSize : 0, 0);
    if (has(mode, Mode::Temperature))
        appendXdaReal(out, sample.temperature_degC.value_or(0.0), precision);
    if (has(mode, Mode::Calibrated)) {
        if (enabled(settings, DisableAcc))
            appendVector(out, sample.acceleration, precision);
        if (enabled(settings, DisableGyr))
            appendVector(out, sample.rateOfTurn, precision);
        if (enabled(settings, DisableMag))
            appendVector(out, sample.magneticField, precision);
    }
    if (has(mode, Mode::Orientation))
        appendOrientation(out, sample, layout);
    appendTrailer(out, sample, layout);
    return out;
}

}  // namespace footpath
