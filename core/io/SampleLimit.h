#pragma once

#include <cstddef>
#include <string>

namespace footpath {

struct ImportOptions;

/// Memory one sample costs from the file to every view, measured on a simulated 10-hour 100 Hz
/// walk (docs/performance.md, "Long recordings"): footpath-cli process holds about 860 bytes a sample at its
/// peak (the sample as read 88, the smoother's records about 580, the result about 200), the window
/// about 1.0 KB (what its views draw).
constexpr std::size_t kAnalysisBytesPerSample = 1200;

/// The most samples a recording may hold: what half of this computer's memory holds at
/// kAnalysisBytesPerSample (16 GB: 6.7 million samples, 18 hours at 100 Hz). A larger file is
/// refused before it is read, not after the memory has run out.
std::size_t defaultSampleLimit();

/// options.maxSamples, or defaultSampleLimit() when that is 0.
std::size_t sampleLimit(const ImportOptions& options);

/// Why a file is refused: `samples` (counted, or estimated from the file size as `estimateBasis`
/// says, e.g. "1.9 GB at 68 bytes a row") is over the limit, what the limit comes from, and what to
/// do instead.
std::string tooManySamplesMessage(std::size_t samples, const std::string& estimateBasis, const ImportOptions& options);

/// A reader's up-front check: a file whose rest (`remainingBytes`) at `bytesPerSample` (the first
/// row or message) would hold clearly more samples than the limit. The first row may be shorter
/// than the rest (zeros at rest, more digits later), so only an estimate of twice the limit
/// refuses; reading stops at the limit itself in any case, having held at most the limit's
/// samples as read (88 bytes each), before any analysis. Empty when the file may hold few enough.
std::string checkEstimatedSamples(std::size_t remainingBytes, std::size_t bytesPerSample, const char* unit,
                                  const ImportOptions& options);

}  // namespace footpath
