#include "io/ColumnMapGuess.h"

#include "io/ColumnNames.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace footpath {

namespace {

constexpr std::size_t kGuessRows = 2000;  // enough rows for medians; the check reads the whole head
// What an IMU on a foot records: its rate, gravity at rest (the median of a walk is close to it),
// and the air pressure where people walk (the Dead Sea shore to 9 km up a mountain).
constexpr double kMinRate_hz = 10.0, kMaxRate_hz = 2000.0;
constexpr double kMinPlausibleRate_hz = 1.0;
constexpr double kMinGravity_mps2 = 7.0, kMaxGravity_mps2 = 13.0;
constexpr double kMinAnyGravity_mps2 = 2.0, kMaxAnyGravity_mps2 = 30.0;
constexpr double kMinAirPressure_pa = 30e3, kMaxAirPressure_pa = 110e3;
constexpr double kMinAnyPressure_pa = 10e3, kMaxAnyPressure_pa = 200e3;

std::string figure(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

double median(std::vector<double> values)
{
    if (values.empty())
        return std::nan("");
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

std::string columnName(const ColumnMapGuess& guess, std::size_t column)
{
    std::string name = "column " + std::to_string(column + 1);
    if (column < guess.headerNames.size() && !guess.headerNames[column].empty())
        name += " '" + guess.headerNames[column] + "'";
    return name;
}

/// The column-map role of a recognised header name; unitStated says whether the name gave the
/// unit (then the values do not decide it).
std::string roleName(const ColumnMeaning& meaning, bool& unitStated)
{
    static const char* const axes[] = {"x", "y", "z"};
    const auto axis = [&](ColumnRole x) { return axes[static_cast<int>(meaning.role) - static_cast<int>(x)]; };
    unitStated = true;
    switch (meaning.role) {
    case ColumnRole::Time:
        unitStated = meaning.timeUnit != TimeUnit::Unknown;
        return meaning.timeUnit == TimeUnit::Milliseconds   ? "time_ms"
               : meaning.timeUnit == TimeUnit::Microseconds ? "time_us"
                                                            : "time_s";
    case ColumnRole::Counter: return "counter";
    case ColumnRole::AccX: case ColumnRole::AccY: case ColumnRole::AccZ: return std::string("acc_") + axis(ColumnRole::AccX);
    case ColumnRole::GyrX: case ColumnRole::GyrY: case ColumnRole::GyrZ: return std::string("gyr_") + axis(ColumnRole::GyrX);
    case ColumnRole::MagX: case ColumnRole::MagY: case ColumnRole::MagZ: return std::string("mag_") + axis(ColumnRole::MagX);
    case ColumnRole::Pressure:
        unitStated = meaning.pressureToPa != 1.0;
        return meaning.pressureToPa == 100.0 ? "pressure_hpa" : meaning.pressureToPa == 1000.0 ? "pressure_kpa" : "pressure_pa";
    default: return "skip";  // reference columns are named by --reference-columns, not by a map
    }
}

std::vector<std::string> usualColumnMap(std::size_t columns)
{
    std::vector<std::string> roles = {"time_ms", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"};
    for (std::size_t c = roles.size(); c < columns; ++c)
        roles.emplace_back(c == 7 ? "pressure_pa" : "skip");
    roles.resize(columns);
    return roles;
}

std::vector<double> columnValues(const std::vector<TextRow>& rows, std::size_t column)
{
    std::vector<double> values;
    double value = 0.0;
    for (const TextRow& row : rows)
        if (column < row.cells.size() && parseCell(row.cells[column], value))
            values.push_back(value);
    return values;
}

/// The time unit under which the column's steps give an IMU's rate.
void chooseTimeUnit(ColumnMapGuess& guess, const std::vector<TextRow>& rows, std::size_t column)
{
    const std::vector<double> times = columnValues(rows, column);
    std::vector<double> steps;
    for (std::size_t k = 1; k < times.size(); ++k)
        if (times[k] > times[k - 1])
            steps.push_back(times[k] - times[k - 1]);
    const double step = median(steps);
    if (!(step > 0.0))
        return;
    for (const auto& [role, unit, scale] : {std::tuple{"time_s", "seconds", 1.0}, std::tuple{"time_ms", "milliseconds", 1e-3},
                                            std::tuple{"time_us", "microseconds", 1e-6}}) {
        const double rate = 1.0 / (step * scale);
        if (rate >= kMinRate_hz && rate <= kMaxRate_hz) {
            guess.columnMap[column] = role;
            guess.notes.push_back(columnName(guess, column) + " steps by " + figure(step) + ": time in " + unit + ", "
                                  + figure(rate) + " Hz");
            return;
        }
    }
    guess.notes.push_back(columnName(guess, column) + " steps by " + figure(step)
                          + ": no time unit (s, ms, us) gives an IMU's rate of 10-2000 Hz");
}

/// Pa, hPa or kPa as the values say, or no pressure at all (a magnetometer's unit-norm values
/// once became a barometric height of +-3000 m).
void choosePressure(ColumnMapGuess& guess, const std::vector<TextRow>& rows, std::size_t column)
{
    const double value = median(columnValues(rows, column));
    for (const auto& [role, toPa] : {std::pair{"pressure_pa", 1.0}, std::pair{"pressure_hpa", 100.0},
                                     std::pair{"pressure_kpa", 1000.0}}) {
        if (value * toPa >= kMinAirPressure_pa && value * toPa <= kMaxAirPressure_pa) {
            guess.columnMap[column] = role;
            return;
        }
    }
    guess.columnMap[column] = "skip";
    guess.notes.push_back(columnName(guess, column) + " holds values near " + figure(value)
                          + ": no air pressure in Pa, hPa or kPa, so it is skipped");
}

/// Roles from the header's names; a name it does not know is skipped (and said).
void rolesFromHeader(ColumnMapGuess& guess, std::vector<bool>& unitStated)
{
    std::vector<std::string> unknown;
    for (std::size_t c = 0; c < guess.headerNames.size(); ++c) {
        const std::optional<ColumnMeaning> meaning = recogniseHeaderName(guess.headerNames[c]);
        bool stated = true;
        guess.columnMap.push_back(meaning ? roleName(*meaning, stated) : "skip");
        unitStated.push_back(stated);
        if (!meaning && !guess.headerNames[c].empty())
            unknown.push_back(guess.headerNames[c]);
    }
    if (!unknown.empty())
        guess.notes.push_back("names it does not know, skipped: " + listedColumnNames(unknown, ColumnCount::Stated));
}

/// A reading checked against what can be (outside: refused) and what is usual (outside: a doubt).
struct Expected {
    double anyLow, anyHigh;          ///< beyond these the reading cannot be right
    double usualLow, usualHigh;      ///< beyond these it is unusual
    const char* refusal;             ///< appended to the reading's text when refused
    const char* doubt;               ///< ... when doubted
};

void checkReading(double value, const std::string& reading, const Expected& expected, ColumnMapCheck& check)
{
    if (!(value >= expected.anyLow && value <= expected.anyHigh))
        check.refusals.push_back(reading + expected.refusal);
    else if (value < expected.usualLow || value > expected.usualHigh)
        check.doubts.push_back(reading + expected.doubt);
}

template <typename F>
double medianOver(const std::vector<ImuSample>& samples, F value)
{
    std::vector<double> values;
    values.reserve(samples.size());
    for (const ImuSample& sample : samples)
        values.push_back(value(sample));
    return median(std::move(values));
}

void checkReadings(const ImportResult& read, ColumnMapCheck& check)
{
    const double rate = read.info.rate_hz;
    checkReading(rate, "read so, the rate is " + figure(rate) + " Hz",
                 {kMinPlausibleRate_hz, kMaxImportRate_hz, kMinRate_hz, kMaxRate_hz,
                  ", no IMU's: check the time column and its unit", ", unusual for an IMU on a foot (10-2000 Hz)"},
                 check);
    const std::vector<ImuSample>& samples = read.recording.samples;
    const double gravity = medianOver(samples, [](const ImuSample& s) { return s.acc_mps2.norm(); });
    checkReading(gravity, "read so, the median |a| is " + figure(gravity) + " m/s\u00b2, not gravity",
                 {kMinAnyGravity_mps2, kMaxAnyGravity_mps2, kMinGravity_mps2, kMaxGravity_mps2,
                  " (9.8 m/s\u00b2 or 1 g): check the accelerometer columns and their unit",
                  " (9.8 m/s\u00b2 or 1 g at rest)"},
                 check);
    if (!read.recording.hasPressure())
        return;
    const double pressure = medianOver(samples, [](const ImuSample& s) { return s.pressure_pa; });
    checkReading(pressure, "read so, the pressure is " + figure(pressure / 1000.0) + " kPa",
                 {kMinAnyPressure_pa, kMaxAnyPressure_pa, kMinAirPressure_pa, kMaxAirPressure_pa,
                  ", no air pressure (30-110 kPa where people walk): that column is no barometer",
                  ", outside the 30-110 kPa where people walk"},
                 check);
}

}  // namespace

std::string headOfFile(const std::string& path, std::size_t bytes)
{
    std::ifstream in(path, std::ios::binary);
    std::string head(bytes, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
    if (const auto lastBreak = head.rfind('\n'); head.size() == bytes && lastBreak != std::string::npos)
        head.resize(lastBreak + 1);
    return head;
}

ColumnMapCheck checkColumnMap(const std::string& head, const std::string& path, const ImportOptions& options)
{
    ColumnMapCheck check;
    ImportOptions tried = options;
    tried.progress = nullptr;
    std::istringstream in(head);
    const ImportResult read = importStream(in, head.size(), path, tried);
    if (!read.ok()) {
        // The dialog names the file already: the place in it and the message.
        const ReadError& error = *read.error;
        check.refusals.push_back((error.line > 0 ? "line " + std::to_string(error.line) + ": " : std::string()) + error.message);
        return check;
    }
    checkReadings(read, check);
    check.reading = figure(read.info.rate_hz) + " Hz, acc in " + unitName(read.info.accUnitAsRead) + ", gyr in "
                    + unitName(read.info.gyrUnitAsRead) + ", channels";
    for (const std::string& channel : read.info.channels)
        check.reading += " " + channel;
    return check;
}

ColumnMapGuess guessColumnMap(const std::string& path, const ImportOptions& options)
{
    // A few thousand rows tell as well as the whole file, and a dialog opening must not wait for
    // a long recording to be read.
    return guessColumnMapFromHead(headOfFile(path, kColumnGuessBytes), path, options);
}

ColumnMapGuess guessColumnMapFromHead(const std::string& head, const std::string& path, const ImportOptions& options)
{
    ColumnMapGuess guess;
    std::vector<TextRow> rows = splitTextRows(head, kGuessRows);
    if (!rows.empty() && isHeaderRow(rows.front().cells)) {
        guess.headerNames = rows.front().cells;
        guess.headerLine = rows.front().line;
        rows.erase(rows.begin());
    }
    std::vector<bool> unitStated;
    if (!options.columnMap.empty()) {
        guess.columnMap = options.columnMap;
        unitStated.assign(guess.columnMap.size(), true);  // the user's map is the user's
    } else if (!guess.headerNames.empty()) {
        rolesFromHeader(guess, unitStated);
    } else {
        guess.columnMap = usualColumnMap(rows.empty() ? 0 : rows.front().cells.size());
        unitStated.assign(guess.columnMap.size(), false);
    }
    for (std::size_t c = 0; c < guess.columnMap.size(); ++c) {
        if (unitStated[c])
            continue;
        if (guess.columnMap[c].rfind("time_", 0) == 0)
            chooseTimeUnit(guess, rows, c);
        else if (guess.columnMap[c].rfind("pressure_", 0) == 0)
            choosePressure(guess, rows, c);
    }
    ImportOptions tried = options;
    tried.columnMap = guess.columnMap;
    guess.check = checkColumnMap(head, path, tried);
    guess.confident = guess.check.fine();
    if (!guess.check.refusals.empty())
        guess.doubt = guess.check.refusals.front();
    else if (!guess.check.doubts.empty())
        guess.doubt = guess.check.doubts.front();
    return guess;
}

}  // namespace footpath
