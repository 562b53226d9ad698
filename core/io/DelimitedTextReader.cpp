#include "io/DelimitedTextReader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace footpath {

namespace {

enum class Role { Skip, TimeS, TimeMs, TimeUs, AccX, AccY, AccZ, GyrX, GyrY, GyrZ, MagX, MagY, MagZ, Pressure, RefX, RefY, RefZ };

struct RoleName {
    const char* name;
    Role role;
};

// Canonical role names first (they double as column-map roles), then accepted header aliases.
const RoleName kRoleNames[] = {
    {"time_s", Role::TimeS}, {"time_ms", Role::TimeMs}, {"time_us", Role::TimeUs},
    {"acc_x", Role::AccX}, {"acc_y", Role::AccY}, {"acc_z", Role::AccZ},
    {"gyr_x", Role::GyrX}, {"gyr_y", Role::GyrY}, {"gyr_z", Role::GyrZ},
    {"mag_x", Role::MagX}, {"mag_y", Role::MagY}, {"mag_z", Role::MagZ},
    {"pressure_pa", Role::Pressure}, {"skip", Role::Skip},
    {"t_s", Role::TimeS},
    {"acc_x_mps2", Role::AccX}, {"acc_y_mps2", Role::AccY}, {"acc_z_mps2", Role::AccZ},
    {"gyr_x_radps", Role::GyrX}, {"gyr_y_radps", Role::GyrY}, {"gyr_z_radps", Role::GyrZ},
};
constexpr std::size_t kCanonicalRoleCount = 14;

struct Column {
    Role role = Role::Skip;
    double scale = 1.0;  ///< unit conversion, or -1 for a negated reference axis
};

struct Layout {
    std::vector<Column> columns;
    std::vector<std::string> names;
    bool hasMag = false;
    bool hasPressure = false;
    bool hasReference = false;
};

std::string trim(const std::string& text)
{
    const auto first = text.find_first_not_of(" \t\r\n\"");
    if (first == std::string::npos)
        return {};
    const auto last = text.find_last_not_of(" \t\r\n\"");
    return text.substr(first, last - first + 1);
}

std::string lower(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char ch) { return std::tolower(ch); });
    return text;
}

std::optional<Role> roleByName(const std::string& name)
{
    for (const RoleName& entry : kRoleNames)
        if (name == entry.name)
            return entry.role;
    return std::nullopt;
}

double timeScale(Role role)
{
    return role == Role::TimeMs ? 1e-3 : role == Role::TimeUs ? 1e-6 : 1.0;
}

char detectDelimiter(const std::string& line)
{
    for (char candidate : {',', '\t', ';'})
        if (line.find(candidate) != std::string::npos)
            return candidate;
    return ' ';
}

/// Splits a line; a space delimiter means runs of blanks, as in aligned columns.
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

bool parseNumber(const std::string& cell, double& value)
{
    std::string text = trim(cell);
    if (text.size() > 1 && text.front() == '+')  // from_chars rejects an explicit plus sign
        text.erase(0, 1);
    if (text.empty())
        return false;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end && std::isfinite(value);
}

bool isBlank(const std::string& line)
{
    return line.find_first_not_of(" \t\r\n") == std::string::npos;
}

class TextParser {
public:
    TextParser(std::istream& in, std::string source, const TextReadOptions& options, std::size_t totalBytes)
        : in_(in), options_(options), totalBytes_(totalBytes)
    {
        result_.recording.source = std::move(source);
    }

    TextReadResult run();

private:
    bool fail(std::size_t column, std::string message)
    {
        result_.error = ReadError{result_.recording.source, lineNumber_, column, std::move(message)};
        return false;
    }
    bool nextContentLine(std::string& line);
    bool layoutFromMap();
    bool layoutFromHeader(const std::string& header);
    bool addReferenceColumns();
    bool checkRequiredRoles();
    bool parseRow(const std::string& line);
    bool reportProgress();

    std::istream& in_;
    const TextReadOptions& options_;
    std::size_t totalBytes_;
    TextReadResult result_;
    Layout layout_;
    char delimiter_ = ',';
    std::size_t lineNumber_ = 0;
    std::size_t bytesRead_ = 0;
    std::vector<std::string> cells_;
};

bool TextParser::nextContentLine(std::string& line)
{
    while (std::getline(in_, line)) {
        ++lineNumber_;
        bytesRead_ += line.size() + 1;
        if (!isBlank(line))
            return true;
    }
    return false;
}

bool TextParser::layoutFromMap()
{
    if (!options_.referenceColumns.empty())
        return fail(0, "reference columns are named by the header row; this file is read with a column map");
    for (const std::string& entry : options_.columnMap) {
        const std::optional<Role> role = roleByName(lower(trim(entry)));
        if (!role) {
            std::string known;
            for (const std::string& name : columnRoleNames())
                known += (known.empty() ? "" : ", ") + name;
            return fail(0, "unknown column role '" + entry + "' in the column map; expected one of " + known);
        }
        layout_.columns.push_back({*role, timeScale(*role)});
        layout_.names.push_back(entry);
    }
    return true;
}

bool TextParser::layoutFromHeader(const std::string& header)
{
    splitLine(header, delimiter_, cells_);
    for (const std::string& cell : cells_) {
        const std::string name = trim(cell);
        const std::optional<Role> role = roleByName(lower(name));
        layout_.columns.push_back({role.value_or(Role::Skip), role ? timeScale(*role) : 1.0});
        layout_.names.push_back(name);
    }
    return addReferenceColumns();
}

bool TextParser::addReferenceColumns()
{
    const Role axes[] = {Role::RefX, Role::RefY, Role::RefZ};
    if (options_.referenceColumns.empty())
        return true;
    if (options_.referenceColumns.size() != 3)
        return fail(0, "expected three reference columns x,y,z, got " + std::to_string(options_.referenceColumns.size()));
    for (std::size_t axis = 0; axis < 3; ++axis) {
        std::string name = trim(options_.referenceColumns[axis]);
        const bool negate = !name.empty() && name.front() == '-';
        if (negate)
            name.erase(0, 1);
        const auto found = std::find(layout_.names.begin(), layout_.names.end(), name);
        if (found == layout_.names.end())
            return fail(0, "reference column '" + name + "' is not in the header");
        layout_.columns[static_cast<std::size_t>(found - layout_.names.begin())] = {axes[axis], negate ? -1.0 : 1.0};
    }
    layout_.hasReference = true;
    return true;
}

bool TextParser::checkRequiredRoles()
{
    std::map<Role, int> counts;
    for (const Column& column : layout_.columns)
        ++counts[column.role];
    const int times = counts[Role::TimeS] + counts[Role::TimeMs] + counts[Role::TimeUs];
    std::string missing;
    if (times != 1)
        missing += times == 0 ? " time_s (or t_s, time_ms)" : " exactly one time column";
    const std::pair<Role, const char*> required[] = {{Role::AccX, "acc_x"}, {Role::AccY, "acc_y"}, {Role::AccZ, "acc_z"},
                                                     {Role::GyrX, "gyr_x"}, {Role::GyrY, "gyr_y"}, {Role::GyrZ, "gyr_z"}};
    for (const auto& [role, name] : required)
        if (counts[role] != 1)
            missing += std::string(" ") + name;
    if (!missing.empty()) {
        std::string found;
        for (const std::string& name : layout_.names)
            found += (found.empty() ? "" : ", ") + name;
        if (!options_.columnMap.empty())
            return fail(0, "the column map lacks:" + missing + "; it has: " + found);
        return fail(0, "missing column(s):" + missing + "; the header has: " + found);
    }
    layout_.hasMag = counts[Role::MagX] == 1 && counts[Role::MagY] == 1 && counts[Role::MagZ] == 1;
    layout_.hasPressure = counts[Role::Pressure] == 1;
    return true;
}

bool TextParser::parseRow(const std::string& line)
{
    splitLine(line, delimiter_, cells_);
    if (cells_.size() < layout_.columns.size())
        return fail(cells_.size() + 1, "expected " + std::to_string(layout_.columns.size()) + " columns, found "
                                           + std::to_string(cells_.size()));
    ImuSample sample;
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();
    for (std::size_t c = 0; c < layout_.columns.size(); ++c) {
        const Column& column = layout_.columns[c];
        if (column.role == Role::Skip || (column.role >= Role::MagX && column.role <= Role::Pressure
                                          && !(column.role == Role::Pressure ? layout_.hasPressure : layout_.hasMag)))
            continue;
        double value = 0.0;
        if (!parseNumber(cells_[c], value))
            return fail(c + 1, "expected a number in column '" + layout_.names[c] + "', got '" + trim(cells_[c]) + "'");
        value *= column.scale;
        switch (column.role) {
        case Role::TimeS: case Role::TimeMs: case Role::TimeUs: sample.time_s = value; break;
        case Role::AccX: case Role::AccY: case Role::AccZ: sample.acc_mps2[int(column.role) - int(Role::AccX)] = value; break;
        case Role::GyrX: case Role::GyrY: case Role::GyrZ: sample.gyr_radps[int(column.role) - int(Role::GyrX)] = value; break;
        case Role::MagX: case Role::MagY: case Role::MagZ: sample.mag[int(column.role) - int(Role::MagX)] = value; break;
        case Role::Pressure: sample.pressure_pa = value; break;
        case Role::RefX: case Role::RefY: case Role::RefZ: reference[int(column.role) - int(Role::RefX)] = value; break;
        case Role::Skip: break;
        }
    }
    std::vector<ImuSample>& samples = result_.recording.samples;
    if (!samples.empty() && sample.time_s < samples.back().time_s) {
        std::ostringstream message;
        message.precision(12);
        message << "time goes backwards: " << sample.time_s << " s after " << samples.back().time_s << " s";
        return fail(0, message.str());
    }
    samples.push_back(sample);
    if (layout_.hasReference)
        result_.recording.reference.positions_m.push_back(reference);
    return true;
}

bool TextParser::reportProgress()
{
    if (!options_.progress || totalBytes_ == 0 || lineNumber_ % 4096 != 0)
        return true;
    if (options_.progress(std::min(1.0, static_cast<double>(bytesRead_) / static_cast<double>(totalBytes_))))
        return true;
    return fail(0, "reading cancelled");
}

TextReadResult TextParser::run()
{
    std::string line;
    if (!nextContentLine(line)) {
        lineNumber_ = 0;
        fail(0, "the file is empty: expected a header row and numeric samples");
        return std::move(result_);
    }
    // Spreadsheet "CSV UTF-8" exports start with a byte-order mark.
    if (line.rfind("\xEF\xBB\xBF", 0) == 0)
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
    bool more = hasHeader ? nextContentLine(line) : true;
    for (; more; more = nextContentLine(line))
        if (!parseRow(line) || !reportProgress())
            return std::move(result_);
    if (result_.recording.samples.empty())
        fail(0, "no samples after the header");
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

const std::vector<std::string>& columnRoleNames()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> list;
        for (std::size_t i = 0; i < kCanonicalRoleCount; ++i)
            list.emplace_back(kRoleNames[i].name);
        return list;
    }();
    return names;
}

TextReadResult parseDelimitedText(std::istream& in, const std::string& sourceName, const TextReadOptions& options,
                                  std::size_t totalBytes)
{
    return TextParser(in, sourceName, options, totalBytes).run();
}

TextReadResult readDelimitedText(const std::string& path, const TextReadOptions& options)
{
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) {
        TextReadResult result;
        result.error = ReadError{path, 0, 0, "cannot open the file for reading"};
        return result;
    }
    const auto size = static_cast<std::size_t>(std::max<std::streamoff>(0, in.tellg()));
    in.seekg(0);
    return parseDelimitedText(in, path, options, size);
}

}  // namespace footpath
