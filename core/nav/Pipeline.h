#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Parameters.h"

#include <functional>
#include <string>

namespace footpath {

/// Called now and then with the fraction done (0..1); return false to cancel the run.
using ProgressCallback = std::function<bool(double fraction)>;

struct PipelineOutput {
    Result result;
    std::string error;  ///< empty on success; otherwise why nothing was estimated
};

/// The whole Guo 2015 pipeline as a pure function: stance detection, initial alignment, strapdown
/// mechanization with the EKF (ZUPT/ZARU as enabled), then the per-step table and summary.
/// Re-entrant: nothing is shared between calls, so the GUI may start a new run while an old one
/// is being cancelled.
PipelineOutput runPipeline(const Recording& recording, const Parameters& params,
                           const ProgressCallback& progress = {});

/// Stance phases of the result as steps (stance times, mean stance position, stride) and the summary
/// figures that depend on them. Exposed for tests; runPipeline calls it.
void fillStepsAndSummary(Result& result);

}  // namespace footpath
