#pragma once

#include "xbus/XbusFrame.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace footpath {

/// Number format of real values (data-identifier bits 1..0, and legacy OutputSettings bits 9..8).
enum class XdaPrecision : std::uint8_t {
    Float32 = 0,  ///< IEEE-754, 4 bytes
    Fp1220 = 1,   ///< signed 12.20 fixed point, 4 bytes
    Fp1632 = 2,   ///< 6 bytes: unsigned 32-bit fraction, then signed 16-bit integer part
    Float64 = 3,  ///< IEEE-754, 8 bytes
};

/// Local frame of orientation and free acceleration (identifier bits 3..2).
enum class XdaCoordinateFrame : std::uint8_t { Enu = 0, Ned = 1, Nwu = 2 };

std::size_t xdaValueSize(XdaPrecision precision);
/// Reads one real value; false if the payload has too few bytes left.
bool readXdaReal(XbusPayloadReader& reader, XdaPrecision precision, double& value);
/// Appends one real value; fixed-point values outside their range saturate.
void appendXdaReal(std::vector<std::uint8_t>& out, double value, XdaPrecision precision);

/// MTData2 data identifiers (§3.3), float32 / ENU variants; compare `id & kTypeMask` with them.
namespace MtData2Id {
constexpr std::uint16_t kTypeMask = 0xFFF0;
constexpr std::uint16_t kFrameMask = 0x000C;
constexpr std::uint16_t kPrecisionMask = 0x0003;

constexpr std::uint16_t Temperature = 0x0810;
constexpr std::uint16_t PacketCounter = 0x1020;
constexpr std::uint16_t SampleTimeFine = 0x1060;
constexpr std::uint16_t SampleTimeCoarse = 0x1070;
constexpr std::uint16_t Quaternion = 0x2010;
constexpr std::uint16_t EulerAngles = 0x2030;
constexpr std::uint16_t BaroPressure = 0x3010;
constexpr std::uint16_t DeltaV = 0x4010;
constexpr std::uint16_t Acceleration = 0x4020;
constexpr std::uint16_t FreeAcceleration = 0x4030;
constexpr std::uint16_t RateOfTurn = 0x8020;
constexpr std::uint16_t DeltaQ = 0x8030;
constexpr std::uint16_t MagneticField = 0xC020;
constexpr std::uint16_t StatusByte = 0xE010;
constexpr std::uint16_t StatusWord = 0xE020;
}  // namespace MtData2Id

/// One data message, MTData2 or legacy MTData: every quantity is present only if the message
/// carried it. Units are those of the device, which are SI except the magnetic field.
struct MtData2Sample {
    std::optional<std::uint16_t> packetCounter;     ///< +1 per message, wraps at 65536
    std::optional<std::uint32_t> sampleTimeFine;    ///< 10 kHz device clock ticks, wraps at 2^32
    std::optional<std::uint32_t> sampleTimeCoarse;  ///< whole seconds
    std::optional<Eigen::Vector3d> acceleration;      ///< m/s^2, sensor frame, gravity included
    std::optional<Eigen::Vector3d> freeAcceleration;  ///< m/s^2, local frame, gravity removed
    std::optional<Eigen::Vector3d> rateOfTurn;        ///< rad/s, sensor frame
    std::optional<Eigen::Vector3d> magneticField;     ///< a.u. (1 = earth field at calibration)
    std::optional<Eigen::Vector3d> deltaV;            ///< m/s over the output interval, sensor frame
    std::optional<Eigen::Quaterniond> deltaQ;         ///< orientation increment over the output interval
    std::optional<double> pressure_pa;                ///< BaroPressure is an integer in Pa
    std::optional<Eigen::Quaterniond> quaternion;     ///< sensor to local frame
    std::optional<Eigen::Vector3d> euler_deg;         ///< roll, pitch, yaw
    std::optional<std::uint32_t> statusWord;
    std::optional<std::uint8_t> statusByte;           ///< MTData2 StatusByte or the legacy status
    std::optional<double> temperature_degC;
    XdaCoordinateFrame orientationFrame = XdaCoordinateFrame::Enu;       ///< of quaternion and Euler angles
    XdaCoordinateFrame freeAccelerationFrame = XdaCoordinateFrame::Enu;
};

struct MtData2Decoded {
    MtData2Sample sample;
    std::size_t unknownItems = 0;  ///< items skipped by their size: identifiers not decoded here
    std::string error;             ///< empty if the payload was well formed; else what and at which offset
    bool ok() const { return error.empty(); }
};

/// Decodes an MTData2 payload (MID 0x36). A known item with the wrong size or an item running
/// past the payload makes the message malformed: `error` names the identifier and payload offset,
/// and the sample keeps what came before.
MtData2Decoded decodeMtData2(const std::uint8_t* payload, std::size_t size);
inline MtData2Decoded decodeMtData2(const std::vector<std::uint8_t>& payload)
{
    return decodeMtData2(payload.data(), payload.size());
}

/// An MTData2 payload with every present quantity, real values in `precision`, items in the order
/// a device sends them (ascending groups).
std::vector<std::uint8_t> encodeMtData2(const MtData2Sample& sample, XdaPrecision precision = XdaPrecision::Float32);

}  // namespace footpath
