#pragma once

#include "Recording.h"
#include "io/DelimitedTextReader.h"
#include "io/TickClock.h"

#include <functional>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace footpath {

enum class AccUnit { Unknown, MetresPerSecond2, StandardGravity };
enum class GyrUnit { Unknown, RadiansPerSecond, DegreesPerSecond };
enum class TimeUnit { Unknown, Seconds, Milliseconds, Microseconds };

const char* unitName(AccUnit unit);   ///< "m/s^2", "g", "unknown"
const char* unitName(GyrUnit unit);   ///< "rad/s", "deg/s", "unknown"
const char* unitName(TimeUnit unit);  ///< "s", "ms", "us", "unknown"

/// The highest sample rate an import option or preset may state: above any IMU's output rate, so a
/// larger number is a typing error (a period in us, say), not a rate.
constexpr double kMaxImportRate_hz = 10000.0;

/// What the user says about a file; everything left Unknown/empty/0 is detected or read from it.
struct ImportOptions {
    std::string format;                         ///< "" detects; else one of importFormatNames()
    std::vector<std::string> columnMap;         ///< roles of a headerless text file (see DelimitedTextReader)
    std::vector<std::string> referenceColumns;  ///< header names of reference x,y,z ('-' negates)
    AccUnit accUnit = AccUnit::Unknown;         ///< override
    GyrUnit gyrUnit = GyrUnit::Unknown;         ///< override
    TimeUnit timeUnit = TimeUnit::Unknown;      ///< override for a time column without a stated unit
    double rate_hz = 0.0;                       ///< override, or the rate of a counter time base
    /// The most samples to take; a file with more is refused (io/SampleLimit.h). 0: what this
    /// computer's memory holds for the analysis, defaultSampleLimit().
    std::size_t maxSamples = 0;
    std::function<bool(double)> progress;       ///< fraction of bytes read; return false to cancel
};

/// Lost packets found in the time base.
struct GapReport {
    std::size_t count = 0;           ///< intervals longer than 1.5 nominal sample periods
    std::size_t missingSamples = 0;  ///< estimated from the nominal period
    double longest_s = 0.0;
    double longestAt_s = 0.0;        ///< time at the start of the longest gap
};

/// What `footpath-cli info` prints about a file.
struct RecordingInfo {
    std::string format;                 ///< one of importFormatNames()
    double rate_hz = 0.0;               ///< nominal rate (metadata, counters or median dt)
    std::vector<std::string> channels;  ///< "acc", "gyr", "mag", "pressure", "reference-position", "gait-events"
    AccUnit accUnitAsRead = AccUnit::Unknown;  ///< unit of the numbers in the file (after detection)
    GyrUnit gyrUnitAsRead = GyrUnit::Unknown;
    /// Unit of the file's time column; readers that convert to seconds themselves leave Seconds,
    /// Unknown asks importRecording() to find it from the sample spacing.
    TimeUnit timeUnitAsRead = TimeUnit::Seconds;
    std::string timeSource;             ///< e.g. "time column 'time_s'", "SampleTimeFine (10 kHz)"
    GapReport gaps;
    bool truncated = false;             ///< the file ended or broke before its end; what came before was kept
};

/// A reader's output before the shared finishing step: numbers as in the file (not yet scaled to
/// SI), with the units the format itself states (Unknown where it does not).
struct ImportResult {
    Recording recording;
    RecordingInfo info;
    std::optional<ReadError> error;  ///< set: nothing usable was read
    bool ok() const { return !error.has_value(); }
};

/// Detects the format (unless options.format is set), reads the file streaming, resolves units
/// (override, else what the file states, else plausibility of the data), converts to SI, reports
/// gaps, attaches reference data (columns, sidecar files, known length from the file name), and
/// adds warnings to recording.warnings. Never throws for bad input.
ImportResult importRecording(const std::string& path, const ImportOptions& options = {});
/// The same for a stream that is not a file (an embedded sample); name is used in messages and to
/// look for reference files beside it.
ImportResult importStream(std::istream& in, std::size_t size, const std::string& name,
                          const ImportOptions& options = {});

/// The names --format accepts, the importer registry's (core/methods/ImporterMethods.cpp).
std::vector<std::string> importFormatNames();


}  // namespace footpath
