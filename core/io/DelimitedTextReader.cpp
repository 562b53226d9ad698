#include "io/DelimitedTextReader.h"

#include "io/ColumnNames.h"
#include "io/Import.h"
#include "io/LineReader.h"
#include "io/SampleLimit.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

namespace footpath {

namespace {

struct Column {
    ColumnMeaning meaning;
    double sign = 1.0;  ///< -1 for a negated reference axis
    bool needed = false;
};

std::string trim(const std::string& text)
{
    const auto first = text.find_first_not_of(" \t\r\n\"");
    if (first == std::string::npos)
        return {};
    const auto last = text.find_last_not_of(" \t\r\n\"");
    return text.substr(first, last - first + 1);
}

bool isBlank(const std::string& line)
{
    return line.find_first_not_of(" \t\r\n") == std::string::npos;
}

char detectDelimiter(const std::string& line)
{
    for (char candidate : {'\t', ';', ','})
        if (line.find(candidate) != std::string::npos)
            return candidate;
    return ' ';
}

/// Splits a line; a blank delimiter means runs of blanks, as in aligned columns.
void splitLine(const std::string& line, char delimiter, std::vector<std::string>& cells)
{
    cells.clear();
    if (delimiter != ' ') {
        std::size_t start = 0;
        for (std::size_t pos; (pos = line.find(delimiter, start)) != std::string::npos; start = pos + 1)
            cells.push_back(line.substr(start, pos - start));
        cells.push_back(line.substr(start));
        return;
    }
    std::istringstream words(line);
    for (std::string word; words >> word;)
        cells.push_back(word);
}

bool parseNumber(std::string text, bool decimalComma, double& value)
{
    text = trim(text);
    if (text.size() > 1 && text.front() == '+')  // from_chars rejects an explicit plus sign
        text.erase(0, 1);
    if (decimalComma)
        std::replace(text.begin(), text.end(), ',', '.');
    if (text.empty())
        return false;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end && std::isfinite(value);
}

bool isNumeric(const std::string& cell)
{
    double value = 0.0;
    return parseNumber(cell, false, value) || parseNumber(cell, true, value);
}

int axisOf(ColumnRole role, ColumnRole x)
{
    return static_cast<int>(role) - static_cast<int>(x);
}

/// How a data row ended: kept, skipped as damaged (the rest of the file is still good), or fatal
/// (time going backwards makes the earlier samples wrong too; a cancel stops everything).
enum class RowOutcome { Kept, Skipped, Fatal };

/// Rows skipped because a cell could not be read: the first few in full, the rest as a count.
struct SkippedRows {
    static constexpr std::size_t kShown = 3;
    std::vector<ReadError> shown;
    ReadError last;
    std::size_t count = 0;

    void add(ReadError problem)
    {
        ++count;
        last = problem;
        if (shown.size() < kShown)
            shown.push_back(std::move(problem));
    }
};

/// "line 12, column 4 (message)", as the warnings about skipped rows name the place.
std::string placeOf(const ReadError& problem)
{
    std::string where = "line " + std::to_string(problem.line);
    if (problem.column > 0)
        where += ", column " + std::to_string(problem.column);
    return where + " (" + problem.message + ")";
}

class TextParser {
public:
    TextParser(std::istream& in, std::string source, const ImportOptions& options, std::size_t totalBytes)
        : lines_(in), options_(options), totalBytes_(totalBytes), sampleLimit_(sampleLimit(options))
    {
        result_.recording.source = std::move(source);
        result_.info.format = "delimited";
        result_.info.timeUnitAsRead = TimeUnit::Unknown;
    }

    ImportResult run();

private:
    bool fail(std::size_t column, std::string message)
    {
        result_.error = ReadError{result_.recording.source, lineNumber_, column, std::move(message)};
        return false;
    }
    RowOutcome skip(std::size_t column, std::string message)
    {
        skipped_.add(ReadError{result_.recording.source, lineNumber_, column, std::move(message)});
        return RowOutcome::Skipped;
    }
    bool nextContentLine(std::string& line);
    bool isNamesOnly(const std::string& line);
    bool skipHeader(std::string& line, bool layoutFromIt);
    bool layoutFromMap();
    bool layoutFromHeader(const std::string& header);
    bool addReferenceColumns();
    bool checkRequiredRoles();
    bool resolveUnits();
    RowOutcome parseRow(const std::string& line);
    bool readNumbers(ImuSample& sample, Eigen::Vector3d& reference, double& counter, std::size_t& badColumn);
    bool reportProgress();
    bool reserveSamples(std::size_t firstLineLength);
    void readRows(std::string& line, bool more);
    void judgeSkippedRows();
    void warnAboutSkippedRows();

    LineReader lines_;
    const ImportOptions& options_;
    std::size_t totalBytes_;
    std::size_t sampleLimit_;
    ImportResult result_;
    std::vector<Column> columns_;
    std::vector<std::string> names_;
    char delimiter_ = ',';
    bool decimalComma_ = false;
    bool hasMag_ = false;
    bool hasPressure_ = false;
    bool hasReferenceStance_ = false;
    bool referenceStance_ = false;  ///< the row's reference stance flag, read with its numbers
    bool hasReference_ = false;
    double timeScale_ = 1.0;
    double counterPeriod_s_ = 0.0;
    SkippedRows skipped_;
    bool lineTerminated_ = true;  ///< the last line read ended with a newline (not cut off)
    std::size_t lineNumber_ = 0;
    std::size_t bytesRead_ = 0;
    std::vector<std::string> cells_;
};

/// False at the end of the file, and with an error for a line beyond the bound (a file without
/// line breaks), which is never read whole.
bool TextParser::nextContentLine(std::string& line)
{
    while (lines_.next(line)) {
        lineNumber_ = lines_.lineNumber();
        bytesRead_ = lines_.bytesRead();
        lineTerminated_ = lines_.terminated();
        if (lines_.overlong())
            return fail(0, lines_.overlongMessage() + "; expected one sample a line");
        if (!isBlank(line))
            return true;
    }
    return false;
}

bool TextParser::isNamesOnly(const std::string& line)
{
    splitLine(line, delimiter_, cells_);
    return isHeaderRow(cells_);
}

/// Moves past the header row. One the column map replaces (isNamesOnly split it into cells_) is
/// said, not reported as a damaged row.
bool TextParser::skipHeader(std::string& line, bool layoutFromIt)
{
    if (!layoutFromIt) {
        std::vector<std::string> names;
        for (const std::string& cell : cells_)
            names.push_back(trim(cell));
        result_.recording.warnings.push_back("line " + std::to_string(lineNumber_) + " is a header row ("
                                             + listedColumnNames(names, ColumnCount::Stated)
                                             + "); the column map replaces it");
    }
    return nextContentLine(line);
}

bool TextParser::layoutFromMap()
{
    if (!options_.referenceColumns.empty())
        return fail(0, "reference columns are named by the header row; this file is read with a column map");
    for (const std::string& entry : options_.columnMap) {
        const std::optional<ColumnMeaning> meaning = columnMapRole(trim(entry));
        if (!meaning) {
            std::string known;
            for (const std::string& name : columnRoleNames())
                known += (known.empty() ? "" : ", ") + name;
            return fail(0, "unknown column role '" + entry + "' in the column map; expected one of " + known);
        }
        columns_.push_back({*meaning, 1.0, false});
        names_.push_back(trim(entry));
    }
    return true;
}

bool TextParser::layoutFromHeader(const std::string& header)
{
    splitLine(header, delimiter_, cells_);
    for (const std::string& cell : cells_) {
        const std::string name = trim(cell);
        columns_.push_back({recogniseHeaderName(name).value_or(ColumnMeaning{}), 1.0, false});
        names_.push_back(name);
    }
    return addReferenceColumns();
}

bool TextParser::addReferenceColumns()
{
    const ColumnRole axes[] = {ColumnRole::RefX, ColumnRole::RefY, ColumnRole::RefZ};
    if (options_.referenceColumns.empty())
        return true;
    if (options_.referenceColumns.size() != 3)
        return fail(0, "expected three reference columns x,y,z, got " + std::to_string(options_.referenceColumns.size()));
    for (std::size_t axis = 0; axis < 3; ++axis) {
        std::string name = trim(options_.referenceColumns[axis]);
        const bool negate = !name.empty() && name.front() == '-';
        if (negate)
            name.erase(0, 1);
        const auto found = std::find(names_.begin(), names_.end(), name);
        if (found == names_.end())
            return fail(0, "reference column '" + name + "' is not in the header");
        Column& column = columns_[static_cast<std::size_t>(found - names_.begin())];
        column.meaning = ColumnMeaning{};
        column.meaning.role = axes[axis];
        column.sign = negate ? -1.0 : 1.0;
    }
    hasReference_ = true;
    return true;
}

bool TextParser::checkRequiredRoles()
{
    std::vector<int> counts(static_cast<std::size_t>(ColumnRole::RefStance) + 1, 0);
    for (const Column& column : columns_)
        ++counts[static_cast<std::size_t>(column.meaning.role)];
    const auto count = [&counts](ColumnRole role) { return counts[static_cast<std::size_t>(role)]; };
    std::string missing;
    const int clocks = count(ColumnRole::Time) + count(ColumnRole::Counter);
    if (clocks == 0)
        missing += " time (or a counter, with the sample rate given)";
    else if (count(ColumnRole::Time) > 1 || count(ColumnRole::Counter) > 1)
        missing += " exactly one time column";
    const std::pair<ColumnRole, const char*> required[] = {
        {ColumnRole::AccX, "acc_x"}, {ColumnRole::AccY, "acc_y"}, {ColumnRole::AccZ, "acc_z"},
        {ColumnRole::GyrX, "gyr_x"}, {ColumnRole::GyrY, "gyr_y"}, {ColumnRole::GyrZ, "gyr_z"}};
    for (const auto& [role, name] : required)
        if (count(role) != 1)
            missing += std::string(" ") + name;
    if (!missing.empty()) {
        const std::string found = listedColumnNames(names_, ColumnCount::Stated);
        if (!options_.columnMap.empty())
            return fail(0, "the column map lacks:" + missing + "; it has: " + found);
        const std::string hint = names_.size() == 1 ? " (one column only: columns must be separated by commas, "
                                                      "semicolons, tabs or blanks)"
                                                    : "";
        return fail(0, "missing column(s):" + missing + "; the header has: " + found + hint);
    }
    hasMag_ = count(ColumnRole::MagX) == 1 && count(ColumnRole::MagY) == 1 && count(ColumnRole::MagZ) == 1;
    hasPressure_ = count(ColumnRole::Pressure) == 1;
    hasReferenceStance_ = count(ColumnRole::RefStance) == 1;
    for (Column& column : columns_) {
        const ColumnRole role = column.meaning.role;
        column.needed = role != ColumnRole::Skip && !(role >= ColumnRole::MagX && role <= ColumnRole::MagZ && !hasMag_)
                        && !(role == ColumnRole::Pressure && !hasPressure_)
                        && !(role == ColumnRole::RefStance && !hasReferenceStance_)
                        && !(role == ColumnRole::Counter && count(ColumnRole::Time) == 1);
    }
    return resolveUnits();
}

/// Records the units the names state; time is converted here because gaps need seconds.
bool TextParser::resolveUnits()
{
    RecordingInfo& info = result_.info;
    for (const Column& column : columns_) {
        const ColumnMeaning& m = column.meaning;
        if (m.role >= ColumnRole::AccX && m.role <= ColumnRole::AccZ && m.accUnit != AccUnit::Unknown)
            info.accUnitAsRead = m.accUnit;
        if (m.role >= ColumnRole::GyrX && m.role <= ColumnRole::GyrZ && m.gyrUnit != GyrUnit::Unknown)
            info.gyrUnitAsRead = m.gyrUnit;
        if (m.role == ColumnRole::Time && column.needed) {
            info.timeUnitAsRead = options_.timeUnit != TimeUnit::Unknown ? options_.timeUnit : m.timeUnit;
            info.timeSource = "time column '" + names_[static_cast<std::size_t>(&column - columns_.data())] + "'";
        }
        if (m.role == ColumnRole::Counter && column.needed) {
            if (!(options_.rate_hz > 0.0))
                return fail(0, "time comes from a counter column: give the sample rate");
            counterPeriod_s_ = 1.0 / options_.rate_hz;
            info.timeUnitAsRead = TimeUnit::Seconds;
            info.rate_hz = options_.rate_hz;
            info.timeSource = "counter at " + std::to_string(options_.rate_hz) + " Hz";
        }
    }
    switch (info.timeUnitAsRead) {
    case TimeUnit::Milliseconds: timeScale_ = 1e-3; break;
    case TimeUnit::Microseconds: timeScale_ = 1e-6; break;
    default: timeScale_ = 1.0; break;
    }
    return true;
}

/// The needed cells of cells_ into a sample; false with the 1-based column of the first cell
/// that is not a number.
bool TextParser::readNumbers(ImuSample& sample, Eigen::Vector3d& reference, double& counter, std::size_t& badColumn)
{
    for (std::size_t c = 0; c < columns_.size(); ++c) {
        const Column& column = columns_[c];
        if (!column.needed)
            continue;
        double value = 0.0;
        if (!parseNumber(cells_[c], decimalComma_, value)) {
            badColumn = c + 1;
            return false;
        }
        const ColumnRole role = column.meaning.role;
        if (role == ColumnRole::Time)
            sample.time_s = value * timeScale_;
        else if (role == ColumnRole::Counter)
            counter = value;
        else if (role <= ColumnRole::AccZ)
            sample.acc_mps2[axisOf(role, ColumnRole::AccX)] = value;
        else if (role <= ColumnRole::GyrZ)
            sample.gyr_radps[axisOf(role, ColumnRole::GyrX)] = value;
        else if (role <= ColumnRole::MagZ)
            sample.mag[axisOf(role, ColumnRole::MagX)] = value;
        else if (role == ColumnRole::Pressure)
            sample.pressure_pa = value * column.meaning.pressureToPa;
        else if (role == ColumnRole::RefStance)
            referenceStance_ = value != 0.0;
        else
            reference[axisOf(role, ColumnRole::RefX)] = value * column.sign;
    }
    return true;
}

RowOutcome TextParser::parseRow(const std::string& line)
{
    splitLine(line, delimiter_, cells_);
    if (cells_.size() < columns_.size())
        return skip(cells_.size() + 1, "expected " + std::to_string(columns_.size())
                                           + (columns_.size() == 1 ? " column, found " : " columns, found ")
                                           + std::to_string(cells_.size()));
    ImuSample sample;
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();
    double counter = 0.0;
    if (std::size_t c = 0; !readNumbers(sample, reference, counter, c))
        return skip(c, "expected a number in column '" + names_[c - 1] + "', got '" + trim(cells_[c - 1]) + "'");
    if (counterPeriod_s_ > 0.0)
        sample.time_s = counter * counterPeriod_s_;
    std::vector<ImuSample>& samples = result_.recording.samples;
    if (samples.size() == sampleLimit_) {
        fail(0, tooManySamplesMessage(sampleLimit_, {}, options_));
        return RowOutcome::Fatal;
    }
    if (!samples.empty() && sample.time_s < samples.back().time_s) {
        std::ostringstream message;
        message.precision(12);
        message << "time goes backwards: " << sample.time_s << " after " << samples.back().time_s;
        fail(0, message.str());
        return RowOutcome::Fatal;
    }
    samples.push_back(sample);
    if (hasReference_)
        result_.recording.reference.positions_m.push_back(reference);
    if (hasReferenceStance_)
        result_.recording.reference.stance.push_back(referenceStance_ ? 1 : 0);
    return RowOutcome::Kept;
}

bool TextParser::reportProgress()
{
    if (!options_.progress || totalBytes_ == 0 || lineNumber_ % 4096 != 0)
        return true;
    if (options_.progress(std::min(1.0, static_cast<double>(bytesRead_) / static_cast<double>(totalBytes_))))
        return true;
    return fail(0, "reading cancelled");
}

/// Damaged rows (a corrupted block, a stray word, a file cut off mid-line) are skipped so one bad
/// cell does not cost the rest of the recording; but when at least half the rows are damaged the
/// file is not what the columns say, and reading it is refused with the first problem.
void TextParser::judgeSkippedRows()
{
    const std::size_t kept = result_.recording.samples.size();
    if (skipped_.count == 0 || result_.error)
        return;
    if (skipped_.count >= kept) {
        ReadError first = skipped_.shown.front();
        if (skipped_.count + kept > 1)
            first.message += "; " + std::to_string(skipped_.count) + " of " + std::to_string(skipped_.count + kept)
                             + " data rows could not be read";
        result_.error = std::move(first);
        return;
    }
    warnAboutSkippedRows();
}

void TextParser::warnAboutSkippedRows()
{
    std::vector<std::string>& warnings = result_.recording.warnings;
    const bool cutOff = !lineTerminated_ && skipped_.last.line == lineNumber_;
    const std::size_t damaged = skipped_.count - (cutOff ? 1 : 0);  // the cut line is said apart
    std::size_t listed = 0;
    for (; listed < std::min(damaged, skipped_.shown.size()); ++listed)
        warnings.push_back(placeOf(skipped_.shown[listed]) + ": the row was skipped");
    if (damaged > listed)
        warnings.push_back(std::to_string(damaged - listed) + " more damaged row(s) were skipped");
    if (cutOff) {
        result_.info.truncated = true;
        warnings.push_back("the file ends in the middle of " + placeOf(skipped_.last) + "; the "
                           + std::to_string(result_.recording.samples.size()) + " samples before it were kept");
    }
}

/// False, with the error, when the file clearly holds more samples than the limit: said before
/// reading on, not when the memory has run out.
bool TextParser::reserveSamples(std::size_t firstLineLength)
{
    if (totalBytes_ > bytesRead_) {
        const std::string problem = checkEstimatedSamples(totalBytes_ - bytesRead_, firstLineLength + 1, "row", options_);
        if (!problem.empty()) {
            result_.error = ReadError{result_.recording.source, 0, 0, problem};
            return false;
        }
    }
    // Growing a vector by doubling holds old and new copies at once; an estimate from the file size
    // with a margin avoids that (pages reserved but never written cost no memory).
    if (totalBytes_ > 0 && firstLineLength > 0) {
        const std::size_t estimate = totalBytes_ / (firstLineLength + 1) + 16;
        result_.recording.samples.reserve(std::min({estimate + estimate / 8, totalBytes_ / 8 + 16, sampleLimit_}));
    }
    return true;
}

void TextParser::readRows(std::string& line, bool more)
{
    for (; more; more = nextContentLine(line))
        if (parseRow(line) == RowOutcome::Fatal || !reportProgress())
            return;
}

ImportResult TextParser::run()
{
    std::string line;
    if (!nextContentLine(line)) {
        if (!result_.error) {
            lineNumber_ = 0;
            fail(0, "the file is empty: expected a header row and numeric samples");
        }
        return std::move(result_);
    }
    if (line.rfind("\xEF\xBB\xBF", 0) == 0)  // spreadsheet "CSV UTF-8" exports start with a BOM
        line.erase(0, 3);
    delimiter_ = detectDelimiter(line);
    const bool hasHeader = options_.columnMap.empty();
    const std::size_t firstLine = lineNumber_;
    if (!hasHeader)
        lineNumber_ = 0;  // problems with the map are problems of the option, not of a line
    const bool laidOut = hasHeader ? layoutFromHeader(line) : layoutFromMap();
    if (!laidOut || !checkRequiredRoles())
        return std::move(result_);
    lineNumber_ = firstLine;
    bool more = hasHeader || isNamesOnly(line) ? skipHeader(line, hasHeader) : true;
    if (more) {
        // "9,81" with a semicolon or tab delimiter is a decimal comma, not two cells.
        decimalComma_ = delimiter_ != ',' && line.find(',') != std::string::npos;
        if (!reserveSamples(line.size()))
            return std::move(result_);
    }
    readRows(line, more);
    if (result_.error)
        return std::move(result_);
    judgeSkippedRows();
    if (!result_.error && result_.recording.samples.empty())
        fail(0, "no samples after the header");
    else if (!result_.error && result_.recording.samples.size() == 1)
        fail(0, "only one sample row: a recording needs at least two");
    return std::move(result_);
}

}  // namespace

std::string ReadError::text() const
{
    std::string out = file;
    if (line > 0)
        out += ":" + std::to_string(line);
    if (column > 0)
        out += ":" + std::to_string(column);
    return out + ": " + message;
}

std::size_t columnCount(const std::string& line)
{
    std::vector<std::string> cells;
    splitLine(line, detectDelimiter(line), cells);
    return cells.size();
}

namespace {

/// Numbers in cells, or a line mostly of digits whose separator the reader may not know ("0|1|2"):
/// the reader then says what is wrong with the columns, which helps more than "not data".
bool isNumericRow(const std::string& line, const std::vector<std::string>& cells)
{
    const auto numbers = std::count_if(cells.begin(), cells.end(), isNumeric);
    if (numbers >= 3 && 2 * static_cast<std::size_t>(numbers) > cells.size())
        return true;
    const auto digits = std::count_if(line.begin(), line.end(), [](unsigned char ch) { return std::isdigit(ch); });
    const auto visible = std::count_if(line.begin(), line.end(), [](unsigned char ch) { return std::isgraph(ch); });
    return digits >= 3 && 2 * digits > visible;
}

std::size_t knownColumnNames(const std::vector<std::string>& cells)
{
    return static_cast<std::size_t>(std::count_if(cells.begin(), cells.end(), [](const std::string& cell) {
        const std::optional<ColumnMeaning> meaning = recogniseHeaderName(trim(cell));
        return meaning && meaning->role != ColumnRole::Skip;
    }));
}

}  // namespace

bool looksLikeSensorText(const std::string& firstKilobytes)
{
    std::istringstream in(firstKilobytes);
    std::vector<std::string> cells;
    bool first = true;
    for (std::string line; std::getline(in, line);) {
        if (isBlank(line))
            continue;
        if (first && line.rfind("\xEF\xBB\xBF", 0) == 0)
            line.erase(0, 3);
        splitLine(line, detectDelimiter(line), cells);
        if (isNumericRow(line, cells) || (first && knownColumnNames(cells) >= 2))
            return true;
        first = false;
    }
    return false;
}

bool startsWithHeaderRow(const std::string& firstKilobytes)
{
    std::istringstream in(firstKilobytes);
    std::string line;
    while (std::getline(in, line) && isBlank(line)) {
    }
    if (line.rfind("\xEF\xBB\xBF", 0) == 0)
        line.erase(0, 3);
    std::vector<std::string> cells;
    splitLine(line, detectDelimiter(line), cells);
    return std::any_of(cells.begin(), cells.end(), [](const std::string& cell) {
        return !trim(cell).empty() && !isNumeric(cell);
    });
}

std::vector<TextRow> splitTextRows(const std::string& text, std::size_t maxRows)
{
    std::vector<TextRow> rows;
    char delimiter = 0;
    std::size_t lineNumber = 0;
    std::istringstream in(text);
    for (std::string line; rows.size() < maxRows && std::getline(in, line);) {
        ++lineNumber;
        if (lineNumber == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
            line.erase(0, 3);
        if (isBlank(line))
            continue;
        if (delimiter == 0)
            delimiter = detectDelimiter(line);
        TextRow row{lineNumber, {}};
        splitLine(line, delimiter, row.cells);
        for (std::string& cell : row.cells)
            cell = trim(cell);
        rows.push_back(std::move(row));
    }
    return rows;
}

bool parseCell(const std::string& cell, double& value)
{
    return parseNumber(cell, false, value) || parseNumber(cell, true, value);
}

bool isHeaderRow(const std::vector<std::string>& cells)
{
    return std::none_of(cells.begin(), cells.end(), isNumeric)
           && std::any_of(cells.begin(), cells.end(), [](const std::string& cell) { return !trim(cell).empty(); });
}

ImportResult readDelimitedText(std::istream& in, const std::string& sourceName, const ImportOptions& options,
                               std::size_t totalBytes)
{
    return TextParser(in, sourceName, options, totalBytes).run();
}

}  // namespace footpath
