#pragma once

#include "io/Import.h"

#include <optional>
#include <string>
#include <vector>

namespace footpath {

/// What a column holds, recognised from a header name or a column-map role.
enum class ColumnRole {
    Skip, Time, Counter, AccX, AccY, AccZ, GyrX, GyrY, GyrZ, MagX, MagY, MagZ, Pressure, RefX, RefY, RefZ,
    RefStance  ///< a reference stance flag (pyshoe's zv_vicon_opt), for display beside the detector's
};

/// A recognised column and the unit its name states (Unknown where it states none).
struct ColumnMeaning {
    ColumnRole role = ColumnRole::Skip;
    AccUnit accUnit = AccUnit::Unknown;
    GyrUnit gyrUnit = GyrUnit::Unknown;
    TimeUnit timeUnit = TimeUnit::Unknown;
    double pressureToPa = 1.0;  ///< hPa/mbar 100, kPa 1000
};

/// Recognises common header spellings: "time", "timestamp", "t_s", "Time (ms)"; "acc_x", "AccX",
/// "ax", "accel_x_g", "Acc X [m/s^2]"; "gyr_x", "gyro_x_dps", "wx", "gx", "Gyr_X (deg/s)"; "mag_x",
/// "mx"; "pressure", "baro", "pressure_hpa"; "counter", "packetcounter"; a node prefix and
/// "scaled" are read past ("inertial-6253.76535:scaledAccelX", MicroStrain). Returns nothing for
/// names it does not know (those columns are skipped), so an unexpected column never becomes
/// data by accident.
std::optional<ColumnMeaning> recogniseHeaderName(const std::string& name);

/// Column-map roles (--columns): time_s, time_ms, time_us, counter, acc_x..z, gyr_x..z,
/// mag_x..z, pressure_pa, pressure_hpa, pressure_kpa, skip. Returns nothing for an unknown role.
std::optional<ColumnMeaning> columnMapRole(const std::string& role);

/// The roles a column map may name, for messages and help texts.
const std::vector<std::string>& columnRoleNames();

/// Whether a shortened list of column names ends by saying how many there were.
enum class ColumnCount { Omitted, Stated };

/// The names joined by ", " for a message. Longer than 300 characters (a header of thousands of
/// names, or a binary file's "header line"), the list would flood the message: it is cut there
/// and ends with " ...", and with " (N columns)" when `count` is Stated.
std::string listedColumnNames(const std::vector<std::string>& names, ColumnCount count);

}  // namespace footpath
