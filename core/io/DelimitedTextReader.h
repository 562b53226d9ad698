#pragma once

#include "Recording.h"

#include <functional>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace footpath {

/// Where and why a file could not be read: "walk.csv:12:4: expected a number in acc_x, got 'abc'".
struct ReadError {
    std::string file;
    std::size_t line = 0;    ///< 1-based; 0 if the problem is not tied to a line
    std::size_t column = 0;  ///< 1-based; 0 if not tied to a column
    std::string message;

    std::string text() const;
};

struct TextReadOptions {
    /// Column roles for a file without a header row, in file order ("time_ms", "acc_x", ...,
    /// "skip"); empty means the first non-empty line is a header naming the columns.
    std::vector<std::string> columnMap;
    /// Header names of reference position columns x,y,z; a leading '-' negates that axis
    /// (pyshoe-vicon's mirrored y: "vicon_x_m,-vicon_y_m,vicon_z_m").
    std::vector<std::string> referenceColumns;
    /// Called with the fraction of bytes read; return false to cancel.
    std::function<bool(double)> progress;
};

struct TextReadResult {
    Recording recording;
    std::optional<ReadError> error;
    bool ok() const { return !error.has_value(); }
};

/// Reads delimited numeric text: comma, semicolon, tab or whitespace separated, detected from the
/// first data line. With a header, recognised names are time_s/t_s/time_ms, acc_x..z (or
/// acc_x_mps2), gyr_x..z (or gyr_x_radps), mag_x..z, pressure_pa; other columns are ignored unless
/// named as reference columns. Time must not go backwards; every cell must be a number.
TextReadResult readDelimitedText(const std::string& path, const TextReadOptions& options = {});
TextReadResult parseDelimitedText(std::istream& in, const std::string& sourceName, const TextReadOptions& options = {},
                                  std::size_t totalBytes = 0);

/// The roles a column map may name, for messages and help texts.
const std::vector<std::string>& columnRoleNames();

}  // namespace footpath
