#pragma once

#include "io/Import.h"

#include <string>
#include <vector>

namespace footpath {

/// What reading the first part of a file with a column map gives, and whether that can be right.
/// The import dialog shows it under its preview and checks it again at every change; nothing is
/// opened that it refuses.
struct ColumnMapCheck {
    /// Readings that cannot be an IMU walk: the file cannot be read so, a rate above 10 kHz or
    /// under 1 Hz, |a| nowhere near gravity in any unit, a pressure under 10 kPa. Open is refused.
    std::vector<std::string> refusals;
    /// Readings that are unusual but possible (a rate outside 10-2000 Hz, a median |a| away from
    /// gravity, a pressure outside 30-110 kPa): said, the user decides.
    std::vector<std::string> doubts;
    /// What was read, for the user to judge: "200 Hz, median |a| 9.80 m/s² (file in g), ...".
    std::string reading;
    bool fine() const { return refusals.empty() && doubts.empty(); }
};

/// Reads `head` (the first part of the file at `path`) with `options` and checks the rate, the
/// gravity and the pressure it gives against what an IMU on a foot records.
ColumnMapCheck checkColumnMap(const std::string& head, const std::string& path, const ImportOptions& options);

/// What a text file that does not describe itself most likely holds.
struct ColumnMapGuess {
    std::vector<std::string> columnMap;
    /// The file's header row, when its first line is one (names, no numbers), and its line number:
    /// the roles came from those names where the names say, the values decided the rest.
    std::vector<std::string> headerNames;
    std::size_t headerLine = 0;
    /// What the values decided ("column 1 steps by 0.005: time in seconds, 200 Hz", "column 8 holds
    /// values near 0.52, no pressure: skipped"), for the dialog to show.
    std::vector<std::string> notes;
    ColumnMapCheck check;    ///< the file read with columnMap
    bool confident = false;  ///< read with it, the file gives gravity and an IMU's rate (check.fine())
    std::string doubt;       ///< why not, when not confident
};

/// The column map the import dialog starts with: options.columnMap when given; else the roles
/// the header names (recogniseHeaderName), or without a header the usual layout of a headerless
/// IMU log (time, acc, gyr, then pressure, the rest skipped); then the time unit and the pressure
/// column are chosen from the values (the steps of the time column give an IMU's rate, a pressure
/// column holds 30-110 kPa or is skipped). Reads only the first 256 KiB.
ColumnMapGuess guessColumnMap(const std::string& path, const ImportOptions& options);
/// The same for the first part of the file at path, already read (headOfFile).
ColumnMapGuess guessColumnMapFromHead(const std::string& head, const std::string& path, const ImportOptions& options);

/// The first `bytes` of a file, cut at its last line break when the file is longer.
std::string headOfFile(const std::string& path, std::size_t bytes);

/// How much of a file the guess and the dialog's checks read.
constexpr std::size_t kColumnGuessBytes = 256 * 1024;  // some 4000 rows of a headerless IMU log

}  // namespace footpath
