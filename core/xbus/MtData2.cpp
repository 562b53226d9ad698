#include "xbus/MtData2.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <limits>

namespace footpath {

namespace {

constexpr double kTwoPow20 = 1048576.0;
constexpr double kTwoPow32 = 4294967296.0;

/// Rounds to the nearest integer, clamped to [low, high]; NaN becomes 0 (fixed point has no NaN).
std::int64_t saturatingRound(double value, std::int64_t low, std::int64_t high)
{
    if (std::isnan(value))
        return 0;
    if (value <= static_cast<double>(low))
        return low;
    if (value >= static_cast<double>(high))
        return high;
    return std::llround(value);
}

std::string hexId(std::uint16_t id)
{
    char text[8];
    std::snprintf(text, sizeof text, "0x%04X", static_cast<unsigned>(id));
    return text;
}

/// What a known quantity occupies: an unsigned integer of `integerBytes`, or `realCount` reals.
struct Quantity {
    std::uint16_t type;
    std::size_t integerBytes;
    std::size_t realCount;
};

const Quantity kQuantities[] = {
    {MtData2Id::Temperature, 0, 1},      {MtData2Id::PacketCounter, 2, 0},
    {MtData2Id::SampleTimeFine, 4, 0},   {MtData2Id::SampleTimeCoarse, 4, 0},
    {MtData2Id::Quaternion, 0, 4},       {MtData2Id::EulerAngles, 0, 3},
    {MtData2Id::BaroPressure, 4, 0},     {MtData2Id::DeltaV, 0, 3},
    {MtData2Id::Acceleration, 0, 3},     {MtData2Id::FreeAcceleration, 0, 3},
    {MtData2Id::RateOfTurn, 0, 3},       {MtData2Id::DeltaQ, 0, 4},
    {MtData2Id::MagneticField, 0, 3},    {MtData2Id::StatusByte, 1, 0},
    {MtData2Id::StatusWord, 4, 0},
};
constexpr std::size_t kMaxRealCount = 4;

const Quantity* findQuantity(std::uint16_t type)
{
    for (const Quantity& quantity : kQuantities)
        if (quantity.type == type)
            return &quantity;
    return nullptr;
}

void storeInteger(std::uint16_t type, std::uint64_t value, MtData2Sample& sample)
{
    switch (type) {
    case MtData2Id::PacketCounter: sample.packetCounter = static_cast<std::uint16_t>(value); break;
    case MtData2Id::SampleTimeFine: sample.sampleTimeFine = static_cast<std::uint32_t>(value); break;
    case MtData2Id::SampleTimeCoarse: sample.sampleTimeCoarse = static_cast<std::uint32_t>(value); break;
    case MtData2Id::BaroPressure: sample.pressure_pa = static_cast<double>(value); break;
    case MtData2Id::StatusByte: sample.statusByte = static_cast<std::uint8_t>(value); break;
    case MtData2Id::StatusWord: sample.statusWord = static_cast<std::uint32_t>(value); break;
    default: break;
    }
}

void storeReals(std::uint16_t type, const double* v, XdaCoordinateFrame frame, MtData2Sample& sample)
{
    switch (type) {
    case MtData2Id::Temperature: sample.temperature_degC = v[0]; break;
    case MtData2Id::Quaternion:
        sample.quaternion = Eigen::Quaterniond(v[0], v[1], v[2], v[3]);
        sample.orientationFrame = frame;
        break;
    case MtData2Id::EulerAngles:
        sample.euler_deg = Eigen::Vector3d(v[0], v[1], v[2]);
        sample.orientationFrame = frame;
        break;
    case MtData2Id::DeltaV: sample.deltaV = Eigen::Vector3d(v[0], v[1], v[2]); break;
    case MtData2Id::Acceleration: sample.acceleration = Eigen::Vector3d(v[0], v[1], v[2]); break;
    case MtData2Id::FreeAcceleration:
        sample.freeAcceleration = Eigen::Vector3d(v[0], v[1], v[2]);
        sample.freeAccelerationFrame = frame;
        break;
    case MtData2Id::RateOfTurn: sample.rateOfTurn = Eigen::Vector3d(v[0], v[1], v[2]); break;
    case MtData2Id::DeltaQ: sample.deltaQ = Eigen::Quaterniond(v[0], v[1], v[2], v[3]); break;
    case MtData2Id::MagneticField: sample.magneticField = Eigen::Vector3d(v[0], v[1], v[2]); break;
    default: break;
    }
}

/// Decodes one item whose bytes are known to lie inside the payload.
void decodeItem(std::uint16_t id, const std::uint8_t* data, std::size_t size, std::size_t offset, MtData2Decoded& result)
{
    const Quantity* quantity = findQuantity(id & MtData2Id::kTypeMask);
    const unsigned frameBits = (id & MtData2Id::kFrameMask) >> 2;
    if (quantity == nullptr || frameBits > static_cast<unsigned>(XdaCoordinateFrame::Nwu)) {
        ++result.unknownItems;  // newer outputs (GNSS, high-rate, ...) are simply not needed here
        return;
    }
    const auto precision = static_cast<XdaPrecision>(id & MtData2Id::kPrecisionMask);
    const std::size_t expected = quantity->integerBytes > 0 ? quantity->integerBytes
                                                            : quantity->realCount * xdaValueSize(precision);
    if (size != expected) {
        result.error = "MTData2 item " + hexId(id) + " at payload offset " + std::to_string(offset) + " has "
                       + std::to_string(size) + " bytes, expected " + std::to_string(expected);
        return;
    }
    XbusPayloadReader item(data, size);
    if (quantity->integerBytes > 0) {
        std::uint64_t value = 0;
        if (item.readUnsigned(quantity->integerBytes, value))
            storeInteger(quantity->type, value, result.sample);
        return;
    }
    double values[kMaxRealCount] = {};
    for (std::size_t i = 0; i < quantity->realCount; ++i)
        readXdaReal(item, precision, values[i]);
    storeReals(quantity->type, values, static_cast<XdaCoordinateFrame>(frameBits), result.sample);
}

void appendInteger(std::vector<std::uint8_t>& out, std::uint16_t id, std::uint64_t value, std::size_t byteCount)
{
    appendBigEndian(out, id, 2);
    out.push_back(static_cast<std::uint8_t>(byteCount));
    appendBigEndian(out, value, byteCount);
}

void appendReals(std::vector<std::uint8_t>& out, std::uint16_t type, XdaCoordinateFrame frame,
                 std::initializer_list<double> values, XdaPrecision precision)
{
    const auto id = static_cast<std::uint16_t>(type | static_cast<unsigned>(frame) << 2
                                               | static_cast<unsigned>(precision));
    appendBigEndian(out, id, 2);
    out.push_back(static_cast<std::uint8_t>(values.size() * xdaValueSize(precision)));
    for (double value : values)
        appendXdaReal(out, value, precision);
}

void appendVector(std::vector<std::uint8_t>& out, std::uint16_t type, const std::optional<Eigen::Vector3d>& v,
                  XdaPrecision precision, XdaCoordinateFrame frame = XdaCoordinateFrame::Enu)
{
    if (v)
        appendReals(out, type, frame, {v->x(), v->y(), v->z()}, precision);
}

void appendQuaternion(std::vector<std::uint8_t>& out, std::uint16_t type, const std::optional<Eigen::Quaterniond>& q,
                      XdaPrecision precision, XdaCoordinateFrame frame = XdaCoordinateFrame::Enu)
{
    if (q)
        appendReals(out, type, frame, {q->w(), q->x(), q->y(), q->z()}, precision);
}

}  // namespace

std::size_t xdaValueSize(XdaPrecision precision)
{
    switch (precision) {
    case XdaPrecision::Float32: return 4;
    case XdaPrecision::Fp1220: return 4;
    case XdaPrecision::Fp1632: return 6;
    case XdaPrecision::Float64: return 8;
    }
    return 4;
}

bool readXdaReal(XbusPayloadReader& reader, XdaPrecision precision, double& value)
{
    switch (precision) {
    case XdaPrecision::Float32: {
        std::uint32_t bits = 0;
        float number = 0.0f;
        if (!reader.readU32(bits))
            return false;
        std::memcpy(&number, &bits, sizeof number);
        value = number;
        return true;
    }
    case XdaPrecision::Fp1220: {
        std::uint32_t bits = 0;
        if (!reader.readU32(bits))
            return false;
        value = static_cast<double>(static_cast<std::int32_t>(bits)) / kTwoPow20;
        return true;
    }
    case XdaPrecision::Fp1632: {
        // Fraction first, integer part second (§1.2): -1.5 is 80 00 00 00 FF FE.
        std::uint32_t fraction = 0;
        std::uint16_t integer = 0;
        if (!reader.readU32(fraction) || !reader.readU16(integer))
            return false;
        value = static_cast<double>(static_cast<std::int16_t>(integer)) + static_cast<double>(fraction) / kTwoPow32;
        return true;
    }
    case XdaPrecision::Float64: {
        std::uint64_t bits = 0;
        if (!reader.readU64(bits))
            return false;
        std::memcpy(&value, &bits, sizeof value);
        return true;
    }
    }
    return false;
}

void appendXdaReal(std::vector<std::uint8_t>& out, double value, XdaPrecision precision)
{
    switch (precision) {
    case XdaPrecision::Float32: {
        const auto number = static_cast<float>(value);
        std::uint32_t bits = 0;
        std::memcpy(&bits, &number, sizeof bits);
        appendBigEndian(out, bits, 4);
        return;
    }
    case XdaPrecision::Fp1220: {
        const std::int64_t raw = saturatingRound(value * kTwoPow20, std::numeric_limits<std::int32_t>::min(),
                                                 std::numeric_limits<std::int32_t>::max());
        appendBigEndian(out, static_cast<std::uint64_t>(raw), 4);
        return;
    }
    case XdaPrecision::Fp1632: {
        constexpr std::int64_t kLow = std::int64_t{std::numeric_limits<std::int16_t>::min()} * (std::int64_t{1} << 32);
        constexpr std::int64_t kHigh = (std::int64_t{std::numeric_limits<std::int16_t>::max()} + 1) * (std::int64_t{1} << 32) - 1;
        const auto bits = static_cast<std::uint64_t>(saturatingRound(value * kTwoPow32, kLow, kHigh));
        appendBigEndian(out, bits & 0xFFFFFFFFu, 4);
        appendBigEndian(out, (bits >> 32) & 0xFFFFu, 2);
        return;
    }
    case XdaPrecision::Float64: {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &value, sizeof bits);
        appendBigEndian(out, bits, 8);
        return;
    }
    }
}

MtData2Decoded decodeMtData2(const std::uint8_t* payload, std::size_t size)
{
    MtData2Decoded result;
    XbusPayloadReader reader(payload, size);
    while (reader.remaining() > 0 && result.ok()) {
        const std::size_t offset = reader.offset();
        std::uint16_t id = 0;
        std::uint8_t itemSize = 0;
        const std::uint8_t* data = nullptr;
        if (!reader.readU16(id) || !reader.readU8(itemSize)) {
            result.error = "MTData2 payload ends inside an item header at offset " + std::to_string(offset) + " ("
                           + std::to_string(size - offset) + " bytes left, 3 needed)";
        } else if (!reader.view(itemSize, data)) {
            result.error = "MTData2 item " + hexId(id) + " at payload offset " + std::to_string(offset) + " claims "
                           + std::to_string(itemSize) + " bytes but only " + std::to_string(reader.remaining())
                           + " remain";
        } else {
            decodeItem(id, data, itemSize, offset, result);
        }
    }
    return result;
}

std::vector<std::uint8_t> encodeMtData2(const MtData2Sample& sample, XdaPrecision precision)
{
    using namespace MtData2Id;
    std::vector<std::uint8_t> out;
    if (sample.temperature_degC)
        appendReals(out, Temperature, XdaCoordinateFrame::Enu, {*sample.temperature_degC}, precision);
    if (sample.packetCounter)
        appendInteger(out, PacketCounter, *sample.packetCounter, 2);
    if (sample.sampleTimeFine)
        appendInteger(out, SampleTimeFine, *sample.sampleTimeFine, 4);
    if (sample.sampleTimeCoarse)
        appendInteger(out, SampleTimeCoarse, *sample.sampleTimeCoarse, 4);
    appendQuaternion(out, Quaternion, sample.quaternion, precision, sample.orientationFrame);
    appendVector(out, EulerAngles, sample.euler_deg, precision, sample.orientationFrame);
    if (sample.pressure_pa)  // BaroPressure is an unsigned integer in Pa
        appendInteger(out, BaroPressure, static_cast<std::uint64_t>(saturatingRound(*sample.pressure_pa, 0, UINT32_MAX)), 4);
    appendVector(out, DeltaV, sample.deltaV, precision);
    appendVector(out, Acceleration, sample.acceleration, precision);
    appendVector(out, FreeAcceleration, sample.freeAcceleration, precision, sample.freeAccelerationFrame);
    appendVector(out, RateOfTurn, sample.rateOfTurn, precision);
    appendQuaternion(out, DeltaQ, sample.deltaQ, precision);
    appendVector(out, MagneticField, sample.magneticField, precision);
    if (sample.statusByte)
        appendInteger(out, StatusByte, *sample.statusByte, 1);
    if (sample.statusWord)
        appendInteger(out, StatusWord, *sample.statusWord, 4);
    return out;
}

}  // namespace footpath
