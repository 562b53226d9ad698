#include "metrics/GaitStatistics.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>

namespace footpath {

namespace {

double mean(const std::vector<double>& values)
{
    return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double median(std::vector<double> values)
{
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    if (values.size() % 2 == 1)
        return *middle;
    return (*middle + *std::max_element(values.begin(), middle)) / 2.0;
}

/// Linear interpolation between the closest ranks (sorted must not be empty).
double quantile(const std::vector<double>& sorted, double fraction)
{
    const double position = fraction * static_cast<double>(sorted.size() - 1);
    const auto below = static_cast<std::size_t>(std::floor(position));
    const std::size_t above = std::min(below + 1, sorted.size() - 1);
    return sorted[below] + (position - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

double sampleStd(const std::vector<double>& values, double average)
{
    if (values.size() < 2)
        return 0.0;
    double sum = 0.0;
    for (double value : values)
        sum += (value - average) * (value - average);
    return std::sqrt(sum / static_cast<double>(values.size() - 1));
}

void collectPerStepSeries(const Result& result, GaitStatistics& stats)
{
    for (std::size_t k = 0; k < result.steps.size(); ++k) {
        const Step& step = result.steps[k];
        stats.stanceDurations_s.push_back(step.stanceEnd_s - step.stanceStart_s);
        if (k > 0) {  // the first stance ends no stride
            stats.strideLengths_m.push_back(step.strideLength_m);
            stats.strideDurations_s.push_back(step.strideDuration_s);
        }
    }
}

/// The same evaluations footpath-cli eval reports, from core's one implementation.
void addReferenceEvaluation(const Result& result, const Recording& recording, GaitStatistics& stats)
{
    const Reference& reference = recording.reference;
    // A result of another recording (or a partial one) would be compared sample by sample with
    // the wrong reference, or index past it.
    if (result.position_m.empty() || result.position_m.size() != recording.samples.size())
        return;
    if (reference.positions_m.size() == result.position_m.size())
        stats.armse = computeArmse(result.position_m, reference.positions_m);
    if (reference.closedLoop)
        stats.loopClosure = computeLoopClosure(result.position_m, result.summary.pathLength_m, reference.knownLength_m);
    if (reference.knownLength_m > 0.0)
        stats.distanceError = computeDistanceError(result.summary.pathLength_m, reference.knownLength_m);
    if (reference.swings.empty() || result.flags.stance.size() != recording.samples.size())
        return;
    const SampleRange* trial = reference.hasTrialBoundaries ? &reference.trialBoundaries : nullptr;
    stats.stanceScore = scoreStanceDetection(result.flags.stance, reference.swings, trial);
    stats.strideCount = countStrides(result, reference.swings, trial);
    if (result.gaitStance.size() == recording.samples.size())
        stats.gaitStanceScore = scoreStanceDetection(result.gaitStance, reference.swings, trial);
}

/// The smallest 1, 2, 2.5 or 5 times a power of ten that is at least width.
double niceWidthAtLeast(double width)
{
    const double power = std::pow(10.0, std::floor(std::log10(width)));
    for (double mantissa : {1.0, 2.0, 2.5, 5.0})
        if (mantissa * power >= width * (1.0 - 1e-9))
            return mantissa * power;
    return 10.0 * power;
}

}  // namespace

GaitStatistics computeGaitStatistics(const Result& result, const Recording* recording)
{
    GaitStatistics stats;
    const Summary& summary = result.summary;
    stats.duration_s = summary.duration_s;
    stats.pathLength_m = summary.pathLength_m;
    stats.endToStart_m = summary.endToStart_m;
    stats.endToStartPct = summary.endToStartPct;
    collectPerStepSeries(result, stats);
    stats.stancePhases = stats.stanceDurations_s.size();
    stats.strides = stats.strideLengths_m.size();
    if (!stats.stanceDurations_s.empty())
        stats.meanStanceDuration_s = mean(stats.stanceDurations_s);
    if (!stats.strideLengths_m.empty()) {
        stats.meanStrideLength_m = mean(stats.strideLengths_m);
        stats.strideLengthStd_m = sampleStd(stats.strideLengths_m, stats.meanStrideLength_m);
        stats.meanStrideDuration_s = mean(stats.strideDurations_s);
        stats.medianStrideDuration_s = median(stats.strideDurations_s);
        if (stats.medianStrideDuration_s > 0.0) {
            stats.strideRate_perMin = 60.0 / stats.medianStrideDuration_s;
            stats.cadence_stepsPerMin = cadenceOf(stats.medianStrideDuration_s);
        }
    }
    if (recording)
        addReferenceEvaluation(result, *recording, stats);
    return stats;
}

int Histogram::total() const
{
    return below + above + std::accumulate(counts.begin(), counts.end(), 0);
}

Histogram makeHistogram(const std::vector<double>& values, double minimumBinWidth)
{
    std::vector<double> sorted;
    std::copy_if(values.begin(), values.end(), std::back_inserter(sorted), [](double v) { return std::isfinite(v); });
    Histogram histogram;
    if (sorted.empty())
        return histogram;
    std::sort(sorted.begin(), sorted.end());
    const double spread = 3.0 * (quantile(sorted, 0.75) - quantile(sorted, 0.25));
    const auto inside = [&](double v) { return v >= quantile(sorted, 0.25) - spread && v <= quantile(sorted, 0.75) + spread; };
    const double low = *std::find_if(sorted.begin(), sorted.end(), inside);
    const double high = *std::find_if(sorted.rbegin(), sorted.rend(), inside);
    const double targetBins = std::clamp(std::ceil(std::sqrt(static_cast<double>(sorted.size()))), 5.0, 10.0);
    const double width = high > low ? niceWidthAtLeast((high - low) / targetBins) : 0.0;
    histogram.binWidth = std::max(minimumBinWidth, width);
    if (!(histogram.binWidth > 0.0))
        histogram.binWidth = 1.0;  // all values equal and no minimum given
    histogram.firstEdge = std::floor(low / histogram.binWidth) * histogram.binWidth;
    // The tolerance keeps a value on an edge in the bin above it despite rounding
    // (floor(1.4 / 0.01) * 0.01 is a hair above 1.4).
    const auto binOf = [&histogram](double value) {
        return static_cast<long>(std::floor((value - histogram.firstEdge) / histogram.binWidth + 1e-9));
    };
    histogram.counts.assign(static_cast<std::size_t>(binOf(high)) + 1, 0);
    for (double value : sorted) {
        const long bin = binOf(value);
        if (bin < 0)
            ++histogram.below;
        else if (bin >= static_cast<long>(histogram.counts.size()))
            ++histogram.above;
        else
            ++histogram.counts[static_cast<std::size_t>(bin)];
    }
    return histogram;
}

}  // namespace footpath
