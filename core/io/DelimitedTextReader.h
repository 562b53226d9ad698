#pragma once

#include "Recording.h"

#include <istream>
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

struct ImportOptions;
struct ImportResult;

/// Reads delimited numeric text: comma, semicolon, tab or blank separated, detected from the first
/// line; a decimal comma is recognised when the delimiter is not a comma. With a header, columns
/// are recognised by common names and the units those names state (see recogniseHeaderName);
/// without one, options.columnMap gives one role per column. The numbers are kept as in the file
/// except time (converted to seconds when its unit is known) and pressure (to Pa);
/// importRecording() resolves and applies the acc/gyr units. Every cell a role needs must be a
/// number, and time must not go backwards.
ImportResult readDelimitedText(std::istream& in, const std::string& sourceName, const ImportOptions& options,
                               std::size_t totalBytes = 0);

/// Number of cells in one line, with the delimiter detected as the reader does.
std::size_t columnCount(const std::string& line);

/// True if the text has a row of numbers (at least three numeric cells, more than half of the row)
/// or at least starts with a header naming two known columns: what sensor data looks like, unlike
/// a page of prose.
bool looksLikeSensorText(const std::string& firstKilobytes);

/// True if the first non-empty line of the text looks like column names rather than numbers.
bool startsWithHeaderRow(const std::string& firstKilobytes);

/// One line of delimited text split into cells as the reader splits it, with its line number in
/// the file (1-based, counting blank lines, as the reader's messages count them).
struct TextRow {
    std::size_t line = 0;
    std::vector<std::string> cells;  ///< trimmed of blanks and quotes
};
/// The first maxRows non-blank lines of text, the delimiter detected from the first of them (a
/// spreadsheet's byte-order mark removed).
std::vector<TextRow> splitTextRows(const std::string& text, std::size_t maxRows);
/// A cell as a number, with a decimal point or a decimal comma; false for anything else.
bool parseCell(const std::string& cell, double& value);
/// A row of names with not one number among them: a header row (a damaged data row keeps
/// numbers). What the reader skips before a column map, and what the column guess reads names from.
bool isHeaderRow(const std::vector<std::string>& cells);

}  // namespace footpath
