#include "io/Import.h"

#include "io/IpolGaitEvents.h"
#include "io/ReferenceSidecar.h"
#include "io/XsensTextReader.h"
#include "methods/MethodRegistry.h"
#include "nav/InputCheck.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

namespace footpath {

namespace {

constexpr double kStandardGravity_mps2 = 9.80665;
constexpr double kDegToRad = M_PI / 180.0;
constexpr std::size_t kDetectionBytes = 64 * 1024;

std::string formatNumber(double value, int precision = 4)
{
    std::ostringstream out;
    out.precision(precision);
    out << value;
    return out.str();
}

/// Median of up to ~20000 evenly spread values of f(sample): robust and cheap on long files.
template <typename F>
double sampledMedian(const std::vector<ImuSample>& samples, F f)
{
    if (samples.empty())
        return 0.0;
    const std::size_t stride = std::max<std::size_t>(1, samples.size() / 20000);
    std::vector<double> values;
    for (std::size_t k = 0; k < samples.size(); k += stride)
        values.push_back(f(samples[k]));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
    return values[values.size() / 2];
}

template <typename F>
double sampledQuantile(const std::vector<ImuSample>& samples, double q, F f)
{
    const std::size_t stride = std::max<std::size_t>(1, samples.size() / 20000);
    std::vector<double> values;
    for (std::size_t k = 0; k < samples.size(); k += stride)
        values.push_back(f(samples[k]));
    const auto at = static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + at, values.end());
    return values[static_cast<std::size_t>(at)];
}

bool looksBinary(const std::string& head)
{
    const auto control = std::count_if(head.begin(), head.end(), [](char ch) {
        const auto byte = static_cast<unsigned char>(ch);
        return byte == 0 || (byte < 32 && byte != '\n' && byte != '\r' && byte != '\t');
    });
    return control > 0 && static_cast<double>(control) > 0.01 * static_cast<double>(head.size());
}

/// What a container format the file is in says of itself at its start ("a MATLAB .mat file (v5)"),
/// or empty: such a file is named for what it is, not called a broken log.
std::string knownContainer(const std::string& head)
{
    const auto startsWith = [&head](std::string_view magic) { return head.compare(0, magic.size(), magic) == 0; };
    if (startsWith("MATLAB 7.3 MAT-file"))
        return "a MATLAB .mat file (v7.3, HDF5)";
    if (startsWith("MATLAB 5.0 MAT-file"))
        return "a MATLAB .mat file (v5)";
    if (startsWith("\x89HDF\r\n\x1a\n"))
        return "an HDF5 file";
    if (startsWith(std::string_view("SQLite format 3\0", 16)))
        return "an SQLite database (a ROS 2 bag?)";
    if (startsWith("PK\x03\x04"))
        return "a ZIP archive (unpack it first)";
    if (startsWith("\x1f\x8b"))
        return "a gzip-compressed file (unpack it first)";
    return {};
}

std::string whyNoBinaryFormat()
{
    return "binary content of no format Footpath knows (an Xsens .mtb log starts with the Xbus preamble 0xFA)";
}

std::string whyNoTextFormat(const std::string& head)
{
    if (!looksLikeSensorText(head))
        return "does not look like sensor data: no numeric rows (a recording has a row of numbers per sample)";
    std::istringstream in(head);
    std::string header;
    while (std::getline(in, header) && header.find_first_not_of(" \t\r") == std::string::npos) {
    }
    return "no header row: the first line has " + std::to_string(columnCount(header))
           + " numeric columns; give the column map (what each column is, e.g. time_ms,acc_x,acc_y,acc_z,"
             "gyr_x,gyr_y,gyr_z,...) or an import preset";
}

/// Which reader a file needs, from its content (the importers' recognisers, in the registry's
/// order); an error message when none fits.
const ImporterMethod* detectFormat(const std::string& head, const ImportOptions& options, std::string& error)
{
    if (head.rfind("\xFF\xFE", 0) == 0 || head.rfind("\xFE\xFF", 0) == 0) {
        error = "UTF-16 text (byte-order mark at byte 0): save the file as UTF-8 or plain ASCII";
        return nullptr;
    }
    if (const std::string container = knownContainer(head); !container.empty()) {
        error = container + ", a format Footpath does not read: export its samples as CSV (time, acc, gyr)";
        return nullptr;
    }
    const bool binary = looksBinary(head);
    if (!binary && head.find_first_not_of(" \t\r\n") == std::string::npos) {
        error = "the file is empty: expected samples";
        return nullptr;
    }
    for (const bool catchAll : {false, true})
        for (const ImporterMethod& importer : importerMethods())
            if (importer.binary == binary && importer.catchAll == catchAll && importer.recognises(head, options))
                return &importer;
    error = binary ? whyNoBinaryFormat() : whyNoTextFormat(head);
    return nullptr;
}

// ---- units ---------------------------------------------------------------------------------

double accNorm(const ImuSample& s) { return s.acc_mps2.norm(); }
double gyrNorm(const ImuSample& s) { return s.gyr_radps.norm(); }

AccUnit accUnitFromData(double medianNorm)
{
    if (medianNorm > 7.0 && medianNorm < 13.0)
        return AccUnit::MetresPerSecond2;
    if (medianNorm > 0.7 && medianNorm < 1.3)
        return AccUnit::StandardGravity;
    return AccUnit::Unknown;
}

void resolveAccUnit(ImportResult& r, const ImportOptions& options)
{
    std::vector<ImuSample>& samples = r.recording.samples;
    const double median = sampledMedian(samples, accNorm);
    const AccUnit fromData = accUnitFromData(median);
    AccUnit unit = options.accUnit != AccUnit::Unknown ? options.accUnit : r.info.accUnitAsRead;
    if (unit == AccUnit::Unknown) {
        unit = fromData;
        if (unit == AccUnit::Unknown) {
            unit = AccUnit::MetresPerSecond2;
            r.recording.warnings.push_back("cannot tell the accelerometer unit (median |a| = " + formatNumber(median)
                                           + "); assuming m/s\u00b2 - set the accelerometer unit to say");
        }
    } else if (fromData != AccUnit::Unknown && fromData != unit) {
        r.recording.warnings.push_back(std::string("the accelerometer is read as ") + unitName(unit)
                                       + " but its median |a| of " + formatNumber(median) + " looks like "
                                       + unitName(fromData) + " - check the accelerometer unit");
    }
    r.info.accUnitAsRead = unit;
    if (unit == AccUnit::StandardGravity)
        for (ImuSample& s : samples)
            s.acc_mps2 *= kStandardGravity_mps2;
}

GyrUnit gyrUnitFromData(double p99)
{
    // A walking foot turns at up to ~10 rad/s; 30 "rad/s" would be 1700 deg/s, so it is deg/s.
    if (p99 > 30.0)
        return GyrUnit::DegreesPerSecond;
    if (p99 > 0.2 && p99 < 20.0)
        return GyrUnit::RadiansPerSecond;
    return GyrUnit::Unknown;
}

void resolveGyrUnit(ImportResult& r, const ImportOptions& options)
{
    std::vector<ImuSample>& samples = r.recording.samples;
    const double p99 = sampledQuantile(samples, 0.99, gyrNorm);
    GyrUnit fromData = gyrUnitFromData(p99);
    GyrUnit unit = options.gyrUnit != GyrUnit::Unknown ? options.gyrUnit : r.info.gyrUnitAsRead;
    if (unit == GyrUnit::Unknown) {
        unit = fromData == GyrUnit::Unknown ? GyrUnit::RadiansPerSecond : fromData;
        if (fromData == GyrUnit::DegreesPerSecond)
            r.recording.warnings.push_back("angular rates up to " + formatNumber(p99)
                                           + " are read as deg/s (as rad/s they would be implausible); set the "
                                             "gyroscope unit to rad/s to override");
    } else if (unit == GyrUnit::RadiansPerSecond && fromData == GyrUnit::DegreesPerSecond) {
        r.recording.warnings.push_back("the gyroscope is read as rad/s but rates up to " + formatNumber(p99)
                                       + " look like deg/s - check the gyroscope unit");
    }
    r.info.gyrUnitAsRead = unit;
    if (unit == GyrUnit::DegreesPerSecond)
        for (ImuSample& s : samples)
            s.gyr_radps *= kDegToRad;
}

double medianStep(const std::vector<ImuSample>& samples)
{
    std::vector<double> steps;
    const std::size_t stride = std::max<std::size_t>(1, samples.size() / 20000);
    for (std::size_t k = 1; k < samples.size(); k += stride)
        steps.push_back(samples[k].time_s - samples[k - 1].time_s);
    if (steps.empty())
        return 0.0;
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
    return steps[steps.size() / 2];
}

/// A time column without a stated unit: the sample spacing tells (10 ms at 100 Hz is 0.01 in s,
/// 10 in ms, 10000 in us).
void resolveTimeUnit(ImportResult& r, const ImportOptions& options)
{
    if (r.info.timeUnitAsRead != TimeUnit::Unknown)
        return;
    TimeUnit unit = options.timeUnit;
    const double step = medianStep(r.recording.samples);
    if (unit == TimeUnit::Unknown) {
        unit = step >= 0.1 && step < 100.0   ? TimeUnit::Milliseconds
               : step >= 100.0 && step < 1e5 ? TimeUnit::Microseconds
                                              : TimeUnit::Seconds;
        r.recording.warnings.push_back("time column without a unit: a median step of " + formatNumber(step)
                                       + " is read as " + unitName(unit) + " - set the time unit to say");
    }
    const double scale = unit == TimeUnit::Milliseconds ? 1e-3 : unit == TimeUnit::Microseconds ? 1e-6 : 1.0;
    for (ImuSample& s : r.recording.samples)
        s.time_s *= scale;
    r.info.timeUnitAsRead = unit;
}

// ---- time base -----------------------------------------------------------------------------

void reportGaps(ImportResult& r)
{
    const std::vector<ImuSample>& samples = r.recording.samples;
    const double period = r.info.rate_hz > 0.0 ? 1.0 / r.info.rate_hz : medianStep(samples);
    if (r.info.rate_hz <= 0.0 && period > 0.0)
        r.info.rate_hz = 1.0 / period;
    if (!(period > 0.0))
        return;
    GapReport& gaps = r.info.gaps;
    std::size_t repeated = 0;
    for (std::size_t k = 1; k < samples.size(); ++k) {
        const double step = samples[k].time_s - samples[k - 1].time_s;
        repeated += step == 0.0;
        if (step <= 1.5 * period)
            continue;
        ++gaps.count;
        gaps.missingSamples += static_cast<std::size_t>(std::llround(step / period)) - 1;
        if (step > gaps.longest_s) {
            gaps.longest_s = step;
            gaps.longestAt_s = samples[k - 1].time_s;
        }
    }
    if (gaps.count > 0)
        r.recording.warnings.push_back(std::to_string(gaps.count) + " gap(s) in the time base, about "
                                       + std::to_string(gaps.missingSamples) + " samples lost; longest "
                                       + formatNumber(gaps.longest_s) + " s at t = " + formatNumber(gaps.longestAt_s)
                                       + " s");
    if (repeated > 0)
        r.recording.warnings.push_back(std::to_string(repeated) + " sample(s) repeat the previous timestamp");
}

void listChannels(ImportResult& r)
{
    std::vector<std::string>& channels = r.info.channels;
    channels = {"acc", "gyr"};
    if (r.recording.hasMag())
        channels.push_back("mag");
    if (r.recording.hasPressure())
        channels.push_back("pressure");
    if (!r.recording.reference.positions_m.empty())
        channels.push_back("reference-position");
    if (!r.recording.reference.swings.empty())
        channels.push_back("gait-events");
}

/// The finishing steps pass over every sample, a few tenths of a second on a ten-hour file: a cancel
/// between them is heard without waiting for all of them.
bool cancelledWhileFinishing(ImportResult& r, const std::string& path, const ImportOptions& options)
{
    if (!options.progress || options.progress(1.0))
        return false;
    r.error = ReadError{path, 0, 0, "reading cancelled"};
    return true;
}

void finishImport(ImportResult& r, const std::string& path, const ImportOptions& options)
{
    resolveTimeUnit(r, options);
    resolveAccUnit(r, options);
    resolveGyrUnit(r, options);
    if (options.rate_hz > 0.0)
        r.info.rate_hz = options.rate_hz;
    if (cancelledWhileFinishing(r, path, options))
        return;
    reportGaps(r);
    if (cancelledWhileFinishing(r, path, options))
        return;
    for (std::string& warning : describeSaturation(r.recording.samples))
        r.recording.warnings.push_back(std::move(warning));
    if (cancelledWhileFinishing(r, path, options))
        return;
    attachReferenceSidecar(path, r.recording);
    attachIpolGaitEvents(path, r.recording, r.recording.warnings);
    listChannels(r);
}

}  // namespace

const char* unitName(AccUnit unit)
{
    return unit == AccUnit::MetresPerSecond2 ? "m/s^2" : unit == AccUnit::StandardGravity ? "g" : "unknown";
}

const char* unitName(GyrUnit unit)
{
    return unit == GyrUnit::RadiansPerSecond ? "rad/s" : unit == GyrUnit::DegreesPerSecond ? "deg/s" : "unknown";
}

const char* unitName(TimeUnit unit)
{
    switch (unit) {
    case TimeUnit::Seconds: return "s";
    case TimeUnit::Milliseconds: return "ms";
    case TimeUnit::Microseconds: return "us";
    default: return "unknown";
    }
}

std::vector<std::string> importFormatNames()
{
    std::vector<std::string> names;
    for (const ImporterMethod& importer : importerMethods())
        names.emplace_back(importer.name);
    return names;
}

ImportResult importStream(std::istream& in, std::size_t size, const std::string& name, const ImportOptions& options)
{
    ImportResult failed;
    failed.recording.source = name;
    std::string head(std::min(size, kDetectionBytes), '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
    in.clear();
    in.seekg(0);

    const ImporterMethod* importer = nullptr;
    std::string problem;
    if (!options.format.empty()) {
        importer = findImporter(options.format);
        problem = "unknown format '" + options.format + "'; expected one of " + importerNamesText();
    } else {
        importer = detectFormat(head, options, problem);
    }
    if (!importer) {
        failed.error = ReadError{name, 0, 0, problem};
        return failed;
    }
    ImportResult result = importer->read(in, name, options, size);
    result.info.format = importer->name;
    if (result.ok())
        finishImport(result, name, options);
    return result;
}

ImportResult importRecording(const std::string& path, const ImportOptions& options)
{
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored)) {  // an ifstream opens a folder and reads nothing
        ImportResult failed;
        failed.recording.source = path;
        failed.error = ReadError{path, 0, 0, "is a directory, not a recording file"};
        return failed;
    }
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) {
        ImportResult failed;
        failed.recording.source = path;
        failed.error = ReadError{path, 0, 0, "cannot open the file for reading"};
        return failed;
    }
    const auto size = static_cast<std::size_t>(std::max<std::streamoff>(0, in.tellg()));
    in.seekg(0);
    return importStream(in, size, path, options);
}

}  // namespace footpath
