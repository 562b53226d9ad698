#pragma once

#include "Recording.h"
#include "Result.h"
#include "metrics/GaitStatistics.h"

#include <Eigen/Core>

#include <vector>

namespace footpath {

/// Everything the views and the report derive from one estimate, computed once per result (off the
/// GUI thread, by the pipeline runner) and read by all of them: the walk's and the gait's figures,
/// the scores against the recording's reference (docs/accuracy.md's metrics), the reference moved
/// into the estimate's frame for drawing, and the distributions the summary charts and the PDF show.
struct ResultEvaluation {
    GaitStatistics statistics;
    /// The reference positions aligned to the estimate as the ARMSE aligns them; empty when the
    /// recording has none (or they do not match the estimate sample for sample).
    std::vector<Eigen::Vector3d> alignedReference;
    Histogram strideLengths;    ///< of statistics.strideLengths_m, bins of at least kStrideLengthBin_m
    Histogram stanceDurations;  ///< of statistics.stanceDurations_s, bins of at least kStanceDurationBin_s
};

/// Finer bins would only show estimation noise (a centimetre of stride, a sample period of stance).
constexpr double kStrideLengthBin_m = 0.01;
constexpr double kStanceDurationBin_s = 0.01;

/// recording may be null (no reference figures); it must be the recording result was estimated from.
ResultEvaluation evaluate(const Result& result, const Recording* recording);

}  // namespace footpath
