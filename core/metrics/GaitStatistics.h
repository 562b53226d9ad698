#pragma once

#include "Recording.h"
#include "Result.h"
#include "metrics/Evaluation.h"

#include <limits>
#include <optional>
#include <vector>

namespace footpath {

/// The figures the summary panel and the PDF report show, computed once from a result (and the
/// recording's reference, when it has one). Figures that need at least one stride are NaN without.
///
/// A stride is one cycle of the instrumented foot (one stance phase to the next; Summary::steps
/// counts them). Cadence follows the clinical convention of counting both feet: two steps per
/// stride, so cadence_stepsPerMin = 2 * strideRate_perMin. Both come from the median stride
/// duration: the first stride also holds the standing still before the walk (and a pause holds
/// its wait), which would slow a mean-based cadence by 10 % on a 15-stride walk.
struct GaitStatistics {
    static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

    std::size_t stancePhases = 0;
    std::size_t strides = 0;
    double duration_s = 0.0;
    double pathLength_m = 0.0;
    double strideRate_perMin = kNone;      ///< 60 / median stride duration
    double cadence_stepsPerMin = kNone;    ///< both feet: 120 / median stride duration
    double meanStrideLength_m = kNone;
    double strideLengthStd_m = kNone;      ///< sample standard deviation (n - 1); 0 for one stride
    double meanStrideDuration_s = kNone;
    double medianStrideDuration_s = kNone;
    double meanStanceDuration_s = kNone;
    double endToStart_m = 0.0;
    double endToStartPct = 0.0;

    std::vector<double> strideLengths_m;   ///< one per stride, in step order
    std::vector<double> strideDurations_s; ///< one per stride, in step order
    std::vector<double> stanceDurations_s; ///< one per stance phase, in step order

    // Against the recording's reference; empty where it has none (the metrics of docs/accuracy.md).
    std::optional<ArmseResult> armse;           ///< reference position at every sample
    std::optional<LoopClosure> loopClosure;     ///< walk ends where it started
    std::optional<DistanceError> distanceError; ///< known walked length
    std::optional<StanceScore> gaitStanceScore; ///< hand-labelled gait events: heel strike to toe off
    std::optional<StanceScore> stanceScore;     ///< the same labels: the foot at rest (ZUPT flag)
    std::optional<StrideCount> strideCount;     ///< strides against the labelled swings
};

/// recording may be null; it must be the recording result was estimated from (its reference is
/// only used when its sample count matches the result's).
GaitStatistics computeGaitStatistics(const Result& result, const Recording* recording = nullptr);

/// Equal-width bins, edges on multiples of the width, plus one bin each for values below and above
/// them. The regular bins cover the values inside Tukey's far-out fences (quartiles -/+ 3 IQR), so
/// the standing still at the start and end of a walk, or a turn, does not stretch the bins over
/// the whole range and squeeze the walking strides into one. The width is a 1-2-2.5-5 number
/// giving about sqrt(n) bins (5 to 10) over that range, never narrower than minimumBinWidth (the
/// resolution worth showing: a centimetre of stride, a sample period of stance). Non-finite values
/// are left out.
struct Histogram {
    double firstEdge = 0.0;
    double binWidth = 0.0;
    std::vector<int> counts;  ///< regular bins; empty when there are no values
    int below = 0;            ///< values below firstEdge
    int above = 0;            ///< values at or above lastEdge()

    double lastEdge() const { return firstEdge + static_cast<double>(counts.size()) * binWidth; }
    double binCentre(std::size_t bin) const { return firstEdge + (static_cast<double>(bin) + 0.5) * binWidth; }
    int total() const;
};
Histogram makeHistogram(const std::vector<double>& values, double minimumBinWidth);

}  // namespace footpath
