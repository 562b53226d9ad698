#include "io/XsensTextReader.h"

#include "io/ColumnNames.h"
#include "io/LineReader.h"
#include "io/SampleLimit.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

namespace footpath {

namespace {

constexpr std::uint64_t kPacketCounterModulus = 65536;           // u16 (MTData2 0x1020)
constexpr std::uint64_t kSampleTimeFineModulus = 4294967296ULL;  // u32 (MTData2 0x1060)
// Counters are read as doubles ("0.0" in the IPOL files); above 2^53 they are no longer exact.
constexpr double kLargestExactCounter = 9007199254740992.0;
constexpr std::size_t kProgressIntervalLines = 1024;
constexpr std::size_t kDamagedRowsShown = 3;  // more are counted, not listed
// No row is shorter: bounds the up-front reservation should totalBytes be wrong.
constexpr std::size_t kShortestRow_bytes = 8;

enum class Field { Counter, SampleTimeFine, AccX, AccY, AccZ, GyrX, GyrY, GyrZ, MagX, MagY, MagZ, Pressure, Count };
constexpr std::size_t kFieldCount = static_cast<std::size_t>(Field::Count);
constexpr std::size_t kNoColumn = std::numeric_limits<std::size_t>::max();

constexpr std::size_t index(Field field) { return static_cast<std::size_t>(field); }

const char* const kFieldDisplayNames[kFieldCount] = {"PacketCounter", "SampleTimeFine", "Acc_X", "Acc_Y", "Acc_Z",
                                                     "Gyr_X", "Gyr_Y", "Gyr_Z", "Mag_X", "Mag_Y", "Mag_Z", "Pressure"};

struct FieldName {
    const char* lowerCaseName;
    Field field;
};

// Compared case-insensitively; the MTw manual calls the packet counter "Counter". Only exact names
// match, so FreeAcc_* (gravity removed, earth frame) can never stand in for Acc_*.
const FieldName kFieldNames[] = {
    {"packetcounter", Field::Counter}, {"counter", Field::Counter}, {"sampletimefine", Field::SampleTimeFine},
    {"acc_x", Field::AccX}, {"acc_y", Field::AccY}, {"acc_z", Field::AccZ},
    {"gyr_x", Field::GyrX}, {"gyr_y", Field::GyrY}, {"gyr_z", Field::GyrZ},
    {"mag_x", Field::MagX}, {"mag_y", Field::MagY}, {"mag_z", Field::MagZ},
    {"pressure", Field::Pressure},
};

// Metadata keys that state the sample rate ("// Update Rate: 100.0Hz", "Acquisition frequency: 100 Hz").
const char* const kRateKeys[] = {"update rate", "acquisition frequency", "sample rate", "sampling rate",
                                 "sampling frequency", "output rate"};

// Columns only Xsens DOT exports have; their SampleTimeFine counts microseconds, not 0.1 ms.
const char* const kDotOnlyColumns[] = {"euler_x", "dq_w", "dv[1]"};

std::string_view trimmed(std::string_view text)
{
    const auto first = text.find_first_not_of(" \t\r\n\"");
    if (first == std::string_view::npos)
        return {};
    const auto last = text.find_last_not_of(" \t\r\n\"");
    return text.substr(first, last - first + 1);
}

std::string lowerCase(std::string_view text)
{
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return out;
}

bool startsWith(std::string_view text, std::string_view prefix)
{
    return text.substr(0, prefix.size()) == prefix;
}

std::string_view withoutByteOrderMark(std::string_view text)
{
    return startsWith(text, "\xEF\xBB\xBF") ? text.substr(3) : text;
}

bool isBlank(std::string_view line)
{
    return trimmed(line).empty();
}

/// Before the column line, `//` lines and `key: value` lines (the IPOL files' "Acquisition
/// frequency: 100 Hz") are metadata; no Xsens column name contains a colon.
bool isMetadataLine(std::string_view line)
{
    return startsWith(trimmed(line), "//") || line.find(':') != std::string_view::npos;
}

char detectDelimiter(std::string_view header)
{
    for (char candidate : {'\t', ';', ','})
        if (header.find(candidate) != std::string_view::npos)
            return candidate;
    return '\t';
}

void splitCells(std::string_view line, char delimiter, std::vector<std::string_view>& cells)
{
    cells.clear();
    std::size_t start = 0;
    for (std::size_t pos; (pos = line.find(delimiter, start)) != std::string_view::npos; start = pos + 1)
        cells.push_back(line.substr(start, pos - start));
    cells.push_back(line.substr(start));
}

/// The whole text must be one finite number.
bool parseNumber(std::string_view text, double& value)
{
    if (text.size() > 1 && text.front() == '+')  // from_chars rejects an explicit plus sign
        text.remove_prefix(1);
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end && std::isfinite(value);
}

enum class Cell { Empty, Number, NotANumber };

/// Semicolon-separated exports come from locales that write a decimal comma.
Cell readCell(std::string_view cell, char delimiter, double& value)
{
    const std::string_view text = trimmed(cell);
    if (text.empty())
        return Cell::Empty;
    if (delimiter == ';' && text.find(',') != std::string_view::npos) {
        std::string pointed(text);
        std::replace(pointed.begin(), pointed.end(), ',', '.');
        return parseNumber(pointed, value) ? Cell::Number : Cell::NotANumber;
    }
    return parseNumber(text, value) ? Cell::Number : Cell::NotANumber;
}

/// "100.0Hz", "100 Hz", "100".
std::optional<double> parseRate(std::string_view value)
{
    double rate = 0.0;
    const char* end = value.data() + value.size();
    const auto [ptr, ec] = std::from_chars(value.data(), end, rate);
    if (ec != std::errc())
        return std::nullopt;
    const std::string unit = lowerCase(trimmed(std::string_view(ptr, static_cast<std::size_t>(end - ptr))));
    if ((!unit.empty() && unit != "hz") || !(rate > 0.0 && rate <= 100000.0))
        return std::nullopt;
    return rate;
}

std::string formatNumber(double value)
{
    std::ostringstream out;
    out << value;
    return out.str();
}

/// Unwraps a counter that wraps at `modulus` into a monotonic count. A step is (new - old) mod
/// modulus; a step longer than half the range is the counter going back, not that many lost packets
/// (half of 65536 packets is 5.5 min at 100 Hz). Values at or above the modulus mean the export
/// already unwrapped the counter; then it simply must not decrease.
class WrapCounter {
public:
    explicit WrapCounter(std::uint64_t modulus) : modulus_(modulus) {}

    std::optional<std::uint64_t> next(std::uint64_t raw);
    std::uint64_t lastRaw() const { return lastRaw_; }
    std::uint64_t modulus() const { return modulus_; }

private:
    std::uint64_t modulus_;
    bool started_ = false;
    std::uint64_t lastRaw_ = 0;
    std::uint64_t total_ = 0;
};

std::optional<std::uint64_t> WrapCounter::next(std::uint64_t raw)
{
    if (!started_) {
        started_ = true;
        lastRaw_ = total_ = raw;
        return total_;
    }
    const bool wraps = raw < modulus_ && lastRaw_ < modulus_;
    if (!wraps && raw < lastRaw_)
        return std::nullopt;
    const std::uint64_t step = wraps ? (raw + modulus_ - lastRaw_) % modulus_ : raw - lastRaw_;
    if (wraps && step > modulus_ / 2)
        return std::nullopt;
    lastRaw_ = raw;
    total_ += step;
    return total_;
}

/// Rows left out for one reason: how many and the first line, for one summarising warning.
struct SkippedRows {
    std::size_t count = 0;
    std::size_t firstLine = 0;

    void add(std::size_t line)
    {
        if (count++ == 0)
            firstLine = line;
    }
};

struct Layout {
    std::array<std::size_t, kFieldCount> columnOf;
    std::vector<std::string> names;  ///< as the column line spells them
    char delimiter = '\t';

    Layout() { columnOf.fill(kNoColumn); }
    bool has(Field field) const { return columnOf[index(field)] != kNoColumn; }
};

struct Row {
    std::array<double, kFieldCount> value{};
    std::array<bool, kFieldCount> present{};
    bool damaged = false;  ///< a cell is not a number: the row is skipped

    bool hasAll(Field first, Field last) const
    {
        for (std::size_t i = index(first); i <= index(last); ++i)
            if (!present[i])
                return false;
        return true;
    }
    Eigen::Vector3d vector(Field x) const { return {value[index(x)], value[index(x) + 1], value[index(x) + 2]}; }
};

class XsensTextParser {
public:
    XsensTextParser(std::istream& in, const std::string& source, const ImportOptions& options, std::size_t totalBytes)
        : lines_(in), options_(options), totalBytes_(totalBytes), sampleLimit_(sampleLimit(options))
    {
        result_.recording.source = source;
    }

    ImportResult run();

private:
    bool fail(std::size_t line, std::size_t column, std::string message)
    {
        result_.error = ReadError{result_.recording.source, line, column, std::move(message)};
        return false;
    }
    void warn(std::string message) { result_.recording.warnings.push_back(std::move(message)); }

    bool readColumnLine(std::string& header);
    void readMetadata(std::string_view line);
    bool layOut(std::string_view header);
    bool checkRequiredColumns();
    bool readRows();
    bool readRow(const std::string& line);
    bool readCells(Row& row, bool& truncated);
    bool unwrapCounters(const Row& row, std::optional<std::uint64_t>& ticks);
    void holdMagAndPressure(const Row& row);
    double toPascal(double pressure);
    bool keepSample(const Row& row, std::uint64_t ticks, std::size_t lineLength);
    bool reserveSamples(std::size_t lineLength);
    bool reportProgress();
    bool finish();
    bool resolveRate();
    std::optional<double> rateFromSampleTimeFine() const;
    void assignTimes();
    void warnAboutSkippedRows();

    LineReader lines_;
    const ImportOptions& options_;
    std::size_t totalBytes_;
    std::size_t sampleLimit_;
    ImportResult result_;
    Layout layout_;
    std::size_t columnLine_ = 0;
    double statedRate_hz_ = 0.0;  ///< from the metadata, 0 if none
    WrapCounter packetCounter_{kPacketCounterModulus};
    WrapCounter sampleTimeFine_{kSampleTimeFineModulus};
    std::vector<std::uint64_t> ticks_;  ///< unwrapped time-source count of each kept sample
    Eigen::Vector3d lastMag_ = Eigen::Vector3d::Constant(std::nan(""));
    double lastPressure_pa_ = std::nan("");
    double pressureScale_ = 0.0;  ///< to Pa; 0 until the first value decides
    bool sawMag_ = false;
    SkippedRows incompleteRows_;
    SkippedRows damagedRows_;           ///< a cell that is not a number: the row is left out
    std::vector<ReadError> damageShown_;  ///< the first few damaged rows, for the warnings
    SkippedRows repeatedRows_;
    std::vector<std::string_view> cells_;
};

bool XsensTextParser::readColumnLine(std::string& header)
{
    std::size_t metadataLines = 0;
    while (lines_.next(header)) {
        if (lines_.overlong())
            return fail(lines_.lineNumber(), 0, lines_.overlongMessage() + "; this is not an MT Manager text export");
        const std::string_view line = lines_.lineNumber() == 1 ? withoutByteOrderMark(header) : header;
        if (isBlank(line))
            continue;
        if (!isMetadataLine(line)) {
            columnLine_ = lines_.lineNumber();
            header.erase(0, header.size() - line.size());
            return true;
        }
        readMetadata(line);
        ++metadataLines;
    }
    if (metadataLines == 0)
        return fail(0, 0, "the file is empty: expected an MT Manager text export");
    return fail(0, 0, "no column line after " + std::to_string(metadataLines) + " metadata line(s)");
}

void XsensTextParser::readMetadata(std::string_view line)
{
    std::string_view text = trimmed(line);
    if (startsWith(text, "//"))
        text = trimmed(text.substr(2));
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos)
        return;
    const std::string key = lowerCase(trimmed(text.substr(0, colon)));
    if (std::find(std::begin(kRateKeys), std::end(kRateKeys), key) == std::end(kRateKeys))
        return;
    const std::string_view value = trimmed(text.substr(colon + 1));
    if (const std::optional<double> rate = parseRate(value))
        statedRate_hz_ = *rate;
    else
        warn("line " + std::to_string(lines_.lineNumber()) + ": could not read a rate from '" + std::string(value)
             + "'; the rate comes from elsewhere");
}

bool XsensTextParser::layOut(std::string_view header)
{
    layout_.delimiter = detectDelimiter(header);
    splitCells(header, layout_.delimiter, cells_);
    for (std::size_t column = 0; column < cells_.size(); ++column) {
        const std::string_view name = trimmed(cells_[column]);
        layout_.names.emplace_back(name);
        const std::string lower = lowerCase(name);
        if (std::find(std::begin(kDotOnlyColumns), std::end(kDotOnlyColumns), lower) != std::end(kDotOnlyColumns))
            return fail(columnLine_, column + 1, "column '" + std::string(name)
                                                     + "' marks an Xsens DOT export, whose SampleTimeFine counts"
                                                       " microseconds; this reader reads MT Manager exports");
        for (const FieldName& known : kFieldNames) {
            if (lower != known.lowerCaseName)
                continue;
            if (layout_.has(known.field))
                return fail(columnLine_, column + 1, "column '" + std::string(name) + "' appears twice (first in column "
                                                         + std::to_string(layout_.columnOf[index(known.field)] + 1) + ")");
            layout_.columnOf[index(known.field)] = column;
        }
    }
    return checkRequiredColumns();
}

bool XsensTextParser::checkRequiredColumns()
{
    std::string missing;
    for (std::size_t i = index(Field::AccX); i <= index(Field::GyrZ); ++i)
        if (layout_.columnOf[i] == kNoColumn)
            missing += std::string(missing.empty() ? "" : ", ") + kFieldDisplayNames[i];
    const std::string found = listedColumnNames(layout_.names, ColumnCount::Omitted);
    if (!missing.empty()) {
        const bool hasFreeAcc = lowerCase(found).find("freeacc_") != std::string::npos;
        return fail(columnLine_, 0, "missing column(s) " + missing + "; the column line has: " + found
                                        + (hasFreeAcc ? " (FreeAcc_* has gravity removed and cannot stand in for Acc_*)" : ""));
    }
    if (!layout_.has(Field::Counter) && !layout_.has(Field::SampleTimeFine))
        return fail(columnLine_, 0, "no time column: expected PacketCounter or SampleTimeFine; the column line has: " + found);
    return true;
}

bool XsensTextParser::readRows()
{
    std::string line;
    while (lines_.next(line)) {
        if (lines_.overlong())
            return fail(lines_.lineNumber(), 0, lines_.overlongMessage() + "; expected one packet a line");
        if (!isBlank(line) && !startsWith(trimmed(line), "//") && !readRow(line))
            return false;
        if (lines_.lineNumber() % kProgressIntervalLines == 0 && !reportProgress())
            return false;
    }
    return true;
}

bool XsensTextParser::readRow(const std::string& line)
{
    splitCells(line, layout_.delimiter, cells_);
    Row row;
    bool truncated = !lines_.terminated() && cells_.size() < layout_.names.size();
    if (!truncated && !readCells(row, truncated))
        return false;
    if (row.damaged)
        return true;
    if (truncated) {
        result_.info.truncated = true;
        warn("the file ends in the middle of line " + std::to_string(lines_.lineNumber()) + "; the "
             + std::to_string(ticks_.size()) + " samples before it were kept");
        return true;
    }
    std::optional<std::uint64_t> ticks;
    if (!unwrapCounters(row, ticks))
        return false;
    holdMagAndPressure(row);
    if (!ticks || !row.hasAll(Field::AccX, Field::GyrZ))
        incompleteRows_.add(lines_.lineNumber());
    else if (!ticks_.empty() && *ticks == ticks_.back())
        repeatedRows_.add(lines_.lineNumber());
    else
        return keepSample(row, *ticks, line.size());
    return true;
}

/// Cells beyond the end of a short row count as empty. A cell that is not a number is an error,
/// except on a last line without newline, where it is where the file was cut.
bool XsensTextParser::readCells(Row& row, bool& truncated)
{
    for (std::size_t field = 0; field < kFieldCount; ++field) {
        const std::size_t column = layout_.columnOf[field];
        if (column == kNoColumn || column >= cells_.size())
            continue;
        const Cell cell = readCell(cells_[column], layout_.delimiter, row.value[field]);
        row.present[field] = cell == Cell::Number;
        if (cell != Cell::NotANumber)
            continue;
        if (!lines_.terminated()) {
            truncated = true;
            return true;
        }
        // One damaged row must not cost the rest of the file: it is skipped and named.
        damagedRows_.add(lines_.lineNumber());
        if (damageShown_.size() < kDamagedRowsShown)
            damageShown_.push_back(ReadError{result_.recording.source, lines_.lineNumber(), column + 1,
                                             "expected a number in column '" + layout_.names[column] + "', got '"
                                                 + std::string(trimmed(cells_[column])) + "'"});
        row.damaged = true;
        return true;
    }
    return true;
}

/// Both counters are followed on every row that has them, so wraps are seen even across skipped
/// rows; the time source is SampleTimeFine when the file has it.
bool XsensTextParser::unwrapCounters(const Row& row, std::optional<std::uint64_t>& ticks)
{
    for (Field field : {Field::Counter, Field::SampleTimeFine}) {
        if (!row.present[index(field)])
            continue;
        const double value = row.value[index(field)];
        const std::size_t column = layout_.columnOf[index(field)] + 1;
        const std::string& name = layout_.names[column - 1];
        if (value < 0.0 || value >= kLargestExactCounter || value != std::floor(value))
            return fail(lines_.lineNumber(), column, "expected a whole non-negative count in column '" + name + "', got "
                                                         + std::string(trimmed(cells_[column - 1])));
        WrapCounter& counter = field == Field::Counter ? packetCounter_ : sampleTimeFine_;
        const std::uint64_t previous = counter.lastRaw();
        const std::optional<std::uint64_t> unwrapped = counter.next(static_cast<std::uint64_t>(value));
        if (!unwrapped)
            return fail(lines_.lineNumber(), column, name + " goes back from " + std::to_string(previous) + " to "
                                                         + formatNumber(value) + ", which a wrap at "
                                                         + std::to_string(counter.modulus()) + " does not explain");
        if (field == Field::SampleTimeFine || !layout_.has(Field::SampleTimeFine))
            ticks = unwrapped;
    }
    return true;
}

void XsensTextParser::holdMagAndPressure(const Row& row)
{
    if (row.hasAll(Field::MagX, Field::MagZ)) {
        lastMag_ = row.vector(Field::MagX);
        sawMag_ = true;
    }
    if (row.present[index(Field::Pressure)])
        lastPressure_pa_ = toPascal(row.value[index(Field::Pressure)]);
}

/// The MTw manual gives the export's Pressure in mbar while the MTData2 packet carries Pa, and the
/// protocol notes leave the export unit open. Air pressure where people walk is 300-1100 hPa, i.e.
/// 30 000-110 000 Pa, so the first value tells which unit the file uses.
double XsensTextParser::toPascal(double pressure)
{
    if (pressureScale_ == 0.0) {
        pressureScale_ = pressure < 2000.0 ? 100.0 : 1.0;
        const double pa = pressure * pressureScale_;
        if (pa < 30000.0 || pa > 110000.0)
            warn("Pressure " + formatNumber(pressure) + " at line " + std::to_string(lines_.lineNumber())
                 + " is implausible in both Pa and hPa; read as " + (pressureScale_ == 1.0 ? "Pa" : "hPa"));
    }
    return pressure * pressureScale_;
}

bool XsensTextParser::keepSample(const Row& row, std::uint64_t ticks, std::size_t lineLength)
{
    if (ticks_.empty() && !reserveSamples(lineLength))
        return false;
    if (ticks_.size() == sampleLimit_)
        return fail(lines_.lineNumber(), 0, tooManySamplesMessage(sampleLimit_, {}, options_));
    ImuSample sample;
    sample.acc_mps2 = row.vector(Field::AccX);
    sample.gyr_radps = row.vector(Field::GyrX);
    sample.mag = lastMag_;
    sample.pressure_pa = lastPressure_pa_;
    result_.recording.samples.push_back(sample);
    ticks_.push_back(ticks);
    return true;
}

/// False, with the error, when the file clearly holds more samples than the limit: said before
/// reading on, not when the memory has run out.
bool XsensTextParser::reserveSamples(std::size_t lineLength)
{
    if (totalBytes_ <= lines_.bytesRead())
        return true;
    // Reserving too much costs address space only (pages never written stay unmapped); too little
    // makes the vector regrow by doubling, holding old and new copies at once. So: the estimate
    // plus a margin, bounded by the shortest possible row (8 bytes).
    const std::size_t remaining = totalBytes_ - lines_.bytesRead();
    if (std::string problem = checkEstimatedSamples(remaining, lineLength + 1, "row", options_); !problem.empty())
        return fail(0, 0, std::move(problem));
    const std::size_t estimate = remaining / (lineLength + 1) + 1;
    const std::size_t count = std::min({estimate + estimate / 8, remaining / kShortestRow_bytes + 1, sampleLimit_});
    result_.recording.samples.reserve(count);
    ticks_.reserve(count);
    return true;
}

bool XsensTextParser::reportProgress()
{
    if (!options_.progress || totalBytes_ == 0)
        return true;
    if (options_.progress(std::min(1.0, static_cast<double>(lines_.bytesRead()) / static_cast<double>(totalBytes_))))
        return true;
    return fail(0, 0, "reading cancelled");
}

bool XsensTextParser::finish()
{
    // Damage in at least half the rows: the file is not what its column line says.
    if (damagedRows_.count > 0 && damagedRows_.count >= ticks_.size()) {
        ReadError first = damageShown_.front();
        if (damagedRows_.count + ticks_.size() > 1)
            first.message += "; " + std::to_string(damagedRows_.count) + " of "
                             + std::to_string(damagedRows_.count + ticks_.size()) + " data rows could not be read";
        result_.error = std::move(first);
        return false;
    }
    if (ticks_.empty()) {
        if (incompleteRows_.count > 0)
            return fail(columnLine_, 0, "none of the " + std::to_string(incompleteRows_.count)
                                            + " data rows after this column line has Acc, Gyr and time values");
        return fail(columnLine_, 0, "no data rows after this column line");
    }
    if (!resolveRate())
        return false;
    assignTimes();
    warnAboutSkippedRows();
    RecordingInfo& info = result_.info;
    info.format = "xsens-text";
    info.accUnitAsRead = AccUnit::MetresPerSecond2;
    info.gyrUnitAsRead = GyrUnit::RadiansPerSecond;
    info.channels = {"acc", "gyr"};
    if (sawMag_)
        info.channels.emplace_back("mag");
    if (pressureScale_ != 0.0)
        info.channels.emplace_back("pressure");
    return true;
}

/// options.rate_hz, else the rate the metadata states, else the median SampleTimeFine step.
bool XsensTextParser::resolveRate()
{
    double& rate = result_.info.rate_hz;
    if (options_.rate_hz > 0.0) {
        rate = options_.rate_hz;
        if (statedRate_hz_ > 0.0 && std::abs(rate - statedRate_hz_) > 1e-6 * statedRate_hz_)
            warn("the rate given (" + formatNumber(rate) + " Hz) overrides the " + formatNumber(statedRate_hz_)
                 + " Hz the file states");
    } else if (statedRate_hz_ > 0.0) {
        rate = statedRate_hz_;
    } else if (const std::optional<double> fromTicks = rateFromSampleTimeFine()) {
        rate = *fromTicks;
    }
    if (rate > 0.0 || layout_.has(Field::SampleTimeFine))
        return true;
    return fail(0, 0, "the file has a PacketCounter but no SampleTimeFine and states no rate: give the sample "
                      "rate; the IPOL MTw exports use 100 Hz");
}

/// The median step is the nominal period even when some packets are lost.
std::optional<double> XsensTextParser::rateFromSampleTimeFine() const
{
    if (!layout_.has(Field::SampleTimeFine))
        return std::nullopt;
    return rateFromMedianTickStep(ticks_, kSampleTimeFineHz);
}

void XsensTextParser::assignTimes()
{
    const bool fromSampleTimeFine = layout_.has(Field::SampleTimeFine);
    const double ticksPerSecond = fromSampleTimeFine ? kSampleTimeFineHz : result_.info.rate_hz;
    assignTimesFromTicks(result_.recording.samples, ticks_, ticksPerSecond);
    result_.info.timeSource = fromSampleTimeFine ? "SampleTimeFine (10 kHz)"
                                                 : "PacketCounter at " + formatNumber(result_.info.rate_hz) + " Hz";
}

void XsensTextParser::warnAboutSkippedRows()
{
    for (const ReadError& damage : damageShown_)
        warn("line " + std::to_string(damage.line) + ", column " + std::to_string(damage.column) + " ("
             + damage.message + "): the row was skipped");
    if (damagedRows_.count > damageShown_.size())
        warn(std::to_string(damagedRows_.count - damageShown_.size()) + " more damaged row(s) were skipped");
    if (incompleteRows_.count > 0)
        warn("skipped " + std::to_string(incompleteRows_.count) + " row(s) lacking Acc, Gyr or time values (first at line "
             + std::to_string(incompleteRows_.firstLine) + ")");
    if (repeatedRows_.count > 0)
        warn("skipped " + std::to_string(repeatedRows_.count) + " row(s) repeating the previous packet's time (first at line "
             + std::to_string(repeatedRows_.firstLine) + ")");
}

ImportResult XsensTextParser::run()
{
    std::string header;
    if (readColumnLine(header) && layOut(header) && readRows())
        finish();
    return std::move(result_);
}

}  // namespace

ImportResult readXsensText(std::istream& in, const std::string& sourceName, const ImportOptions& options,
                           std::size_t totalBytes)
{
    return XsensTextParser(in, sourceName, options, totalBytes).run();
}

bool looksLikeXsensText(const std::string& firstKilobytes)
{
    std::string_view text = withoutByteOrderMark(firstKilobytes);
    while (!text.empty()) {
        const std::size_t newline = text.find('\n');
        const std::string_view line = text.substr(0, newline);
        text = newline == std::string_view::npos ? std::string_view() : text.substr(newline + 1);
        if (isBlank(line) || isMetadataLine(line))
            continue;
        std::vector<std::string_view> cells;
        splitCells(line, detectDelimiter(line), cells);
        return std::any_of(cells.begin(), cells.end(), [](std::string_view cell) {
            const std::string name = lowerCase(trimmed(cell));
            return name == "packetcounter" || name == "sampletimefine";
        });
    }
    return false;
}

}  // namespace footpath
