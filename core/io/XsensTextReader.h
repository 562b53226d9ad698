#pragma once

#include "io/Import.h"

#include <cstddef>
#include <istream>
#include <string>

namespace footpath {

/// Reads an MT Manager text export (docs/xbus.md section 7.2): `//` metadata lines or an
/// `Acquisition frequency: 100 Hz` line, then a column line (PacketCounter, SampleTimeFine, Acc_X..,
/// Gyr_X.., Mag_X.., Pressure, ...; other columns are ignored, FreeAcc_* is never taken as Acc_*),
/// then one packet a line, separated by tab, comma or semicolon, with empty cells for values the
/// packet did not carry.
///
/// Time comes from SampleTimeFine (10 kHz, wraps at 2^32) when present, else from PacketCounter
/// (wraps at 65536) divided by the rate (options.rate_hz, else the rate the metadata states), and
/// starts at 0; lost packets show as gaps in time (importRecording's finishing step reports them). Rows without Acc or Gyr values are skipped (one
/// warning); missing Mag or Pressure repeats the last value (NaN before the first). Values are SI as
/// exported, except Pressure, which is converted to Pa. Reads line by line; `totalBytes` (0 if
/// unknown) drives progress and the initial reservation. Never throws for bad input: problems come
/// back as ImportResult::error naming the line and 1-based column.
ImportResult readXsensText(std::istream& in, const std::string& sourceName, const ImportOptions& options,
                           std::size_t totalBytes);

/// True when the text before the first data row looks like an MT Manager export: its column line
/// names PacketCounter or SampleTimeFine. Used to detect the format from a file's first kilobytes.
bool looksLikeXsensText(const std::string& firstKilobytes);

}  // namespace footpath
