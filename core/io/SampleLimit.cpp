#include "io/SampleLimit.h"

#include "io/Import.h"

#include <cstdio>

#if __has_include(<unistd.h>)
#include <unistd.h>
#endif

namespace footpath {

namespace {

constexpr std::size_t kAssumedMemory_bytes = std::size_t(8) << 30;  // where the system does not say

std::size_t physicalMemory_bytes()
{
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGESIZE)
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageSize = sysconf(_SC_PAGESIZE);
    if (pages > 0 && pageSize > 0)
        return static_cast<std::size_t>(pages) * static_cast<std::size_t>(pageSize);
#endif
    return kAssumedMemory_bytes;
}

/// "31.2 million", "950000": counts a reader can take in at a glance.
std::string count(std::size_t n)
{
    if (n < 1000000)
        return std::to_string(n);
    char text[32];
    std::snprintf(text, sizeof text, "%.1f million", static_cast<double>(n) / 1e6);
    return text;
}

std::string byteCount(std::size_t bytes)
{
    char text[32];
    if (bytes >= 1000000000)
        std::snprintf(text, sizeof text, "%.1f GB", static_cast<double>(bytes) / 1e9);
    else if (bytes >= 1000000)
        std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
    else
        std::snprintf(text, sizeof text, "%zu bytes", bytes);
    return text;
}

/// How long a recording of that many samples lasts at 100 Hz, in the unit that reads best.
std::string durationAt100Hz(std::size_t samples)
{
    const double seconds = static_cast<double>(samples) / 100.0;
    char text[48];
    if (seconds < 120.0)
        std::snprintf(text, sizeof text, "%.0f s at 100 Hz", seconds);
    else if (seconds < 7200.0)
        std::snprintf(text, sizeof text, "%.0f minutes at 100 Hz", seconds / 60.0);
    else
        std::snprintf(text, sizeof text, "%.0f hours at 100 Hz", seconds / 3600.0);
    return text;
}

}  // namespace

std::size_t defaultSampleLimit()
{
    return physicalMemory_bytes() / 2 / kAnalysisBytesPerSample;
}

std::size_t sampleLimit(const ImportOptions& options)
{
    return options.maxSamples > 0 ? options.maxSamples : defaultSampleLimit();
}

std::string tooManySamplesMessage(std::size_t samples, const std::string& estimateBasis, const ImportOptions& options)
{
    const std::size_t limit = sampleLimit(options);
    const std::string most = count(limit) + " samples (" + durationAt100Hz(limit) + ") a recording may hold";
    std::string text = estimateBasis.empty()
                           ? "the file holds more than the " + most
                           : "the file holds about " + count(samples) + " samples (" + estimateBasis
                                 + "), more than the " + most;
    if (options.maxSamples == 0)
        text += ": analysing a sample takes about " + std::to_string(kAnalysisBytesPerSample)
                + " bytes of memory, and half of this computer's " + byteCount(physicalMemory_bytes())
                + " holds that many";
    return text + "; split the file into shorter recordings";
}

std::string checkEstimatedSamples(std::size_t remainingBytes, std::size_t bytesPerSample, const char* unit,
                                  const ImportOptions& options)
{
    if (bytesPerSample == 0)
        return {};
    const std::size_t estimate = remainingBytes / bytesPerSample;
    const std::size_t limit = sampleLimit(options);
    if (estimate / 2 <= limit)
        return {};
    return tooManySamplesMessage(estimate, byteCount(remainingBytes) + " at " + std::to_string(bytesPerSample)
                                               + " bytes a " + unit,
                                 options);
}

}  // namespace footpath
