#include "metrics/Evaluation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace footpath {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The ARMSE's alignment (docs/accuracy.md): the estimate must have moved this far before its heading is meaningful.
constexpr double kAlignmentDistance_m = 0.8;
// The same alignment: pyshoe's arbitrary choice when the estimate never moves that far.
constexpr std::size_t kFallbackAlignmentIndex = 300;

double horizontalDistance(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return (a.head<2>() - b.head<2>()).norm();
}

std::vector<Eigen::Vector3d> relativeToFirst(const std::vector<Eigen::Vector3d>& positions)
{
    std::vector<Eigen::Vector3d> relative;
    relative.reserve(positions.size());
    for (const Eigen::Vector3d& p : positions)
        relative.push_back(p - positions.front());
    return relative;
}

/// First sample at least kAlignmentDistance_m (horizontally) from the origin, else the fallback,
/// clamped so a short recording still has a valid index.
std::size_t findAlignmentIndex(const std::vector<Eigen::Vector3d>& estimateFromOrigin)
{
    for (std::size_t k = 0; k < estimateFromOrigin.size(); ++k) {
        if (estimateFromOrigin[k].head<2>().norm() >= kAlignmentDistance_m)
            return k;
    }
    return std::min(kFallbackAlignmentIndex, estimateFromOrigin.size() - 1);
}

/// Signed angle about z that turns the horizontal part of `from` onto that of `to`. A zero-length
/// vector has no direction, so nothing is rotated rather than rotating by an arbitrary angle.
double headingCorrection(const Eigen::Vector3d& from, const Eigen::Vector3d& to)
{
    const Eigen::Vector2d a = from.head<2>();
    const Eigen::Vector2d b = to.head<2>();
    if (a.squaredNorm() == 0.0 || b.squaredNorm() == 0.0)
        return 0.0;
    // atan2 of (cross, dot) keeps the sign for every angle, including exactly 180 degrees.
    const double cross = a.x() * b.y() - a.y() * b.x();
    return std::atan2(cross, a.dot(b));
}

void rotateAboutZ(std::vector<Eigen::Vector3d>& positions, double angle_rad)
{
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (Eigen::Vector3d& p : positions)
        p = rotation * p;
}

/// Mean over samples of the per-sample RMS difference over the first `axes` axes (pyshoe's ARMSE).
double averageRmse(const std::vector<Eigen::Vector3d>& estimate,
                   const std::vector<Eigen::Vector3d>& reference, Eigen::Index axes)
{
    double sum = 0.0;
    for (std::size_t k = 0; k < estimate.size(); ++k) {
        const double meanSquared =
            (estimate[k] - reference[k]).head(axes).squaredNorm() / static_cast<double>(axes);
        sum += std::sqrt(meanSquared);
    }
    return sum / static_cast<double>(estimate.size());
}

}  // namespace

ArmseResult computeArmse(const std::vector<Eigen::Vector3d>& estimate,
                         const std::vector<Eigen::Vector3d>& reference)
{
    // Callers batch many trials; one unusable pair should show up as NaN, not abort the batch.
    if (estimate.empty() || estimate.size() != reference.size())
        return ArmseResult{kNaN, kNaN, 0, kNaN};

    std::vector<Eigen::Vector3d> alignedEstimate = relativeToFirst(estimate);
    const std::vector<Eigen::Vector3d> referenceFromOrigin = relativeToFirst(reference);

    ArmseResult result;
    result.alignmentIndex = findAlignmentIndex(alignedEstimate);
    result.rotation_rad = headingCorrection(alignedEstimate[result.alignmentIndex],
                                            referenceFromOrigin[result.alignmentIndex]);
    rotateAboutZ(alignedEstimate, result.rotation_rad);

    result.armse2d_m = averageRmse(alignedEstimate, referenceFromOrigin, 2);
    result.armse3d_m = averageRmse(alignedEstimate, referenceFromOrigin, 3);
    return result;
}

LoopClosure computeLoopClosure(const std::vector<Eigen::Vector3d>& positions, double pathLength_m,
                               double referenceLength_m)
{
    LoopClosure closure;
    // The reference length is the better denominator; the estimate's own length is the fallback.
    closure.lengthUsed_m = referenceLength_m > 0.0 ? referenceLength_m : pathLength_m;
    if (positions.empty()) {
        closure.dbse_m = kNaN;  // no trajectory: there is no closure error to report
        closure.dbsePct = kNaN;
        return closure;
    }
    closure.dbse_m = horizontalDistance(positions.back(), positions.front());
    closure.dbsePct = closure.lengthUsed_m == 0.0 ? 0.0 : closure.dbse_m / closure.lengthUsed_m * 100.0;
    return closure;
}

double stancePathLength(const std::vector<Step>& steps)
{
    double length = 0.0;
    for (std::size_t k = 1; k < steps.size(); ++k)
        length += horizontalDistance(steps[k].position_m, steps[k - 1].position_m);
    return length;
}

DistanceError computeDistanceError(double estimatedPathLength_m, double referenceLength_m)
{
    DistanceError error;
    error.estimated_m = estimatedPathLength_m;
    error.reference_m = referenceLength_m;
    error.error_m = std::abs(estimatedPathLength_m - referenceLength_m);
    // A percentage of a non-positive length means nothing; NaN says so instead of a made-up number.
    error.errorPct = referenceLength_m > 0.0 ? error.error_m / referenceLength_m * 100.0 : kNaN;
    return error;
}

namespace {

/// Reference stance per sample of [first, last]: 1 outside every swing.
std::vector<std::uint8_t> referenceStance(const std::vector<SampleRange>& swings, std::size_t first, std::size_t last)
{
    std::vector<std::uint8_t> reference(last - first + 1, 1);
    for (const SampleRange& swing : swings)
        for (std::size_t k = std::max(swing.first, first); k <= std::min(swing.last, last); ++k)
            reference[k - first] = 0;
    return reference;
}

double ratio(std::size_t part, std::size_t whole)
{
    return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

}  // namespace

StanceScore scoreStanceDetection(const std::vector<std::uint8_t>& stance, const std::vector<SampleRange>& swings,
                                 const SampleRange* trialBoundaries)
{
    StanceScore score;
    if (swings.empty() || stance.empty())
        return score;
    std::size_t first = swings.front().first, last = swings.back().last;
    for (const SampleRange& swing : swings) {
        first = std::min(first, swing.first);
        last = std::max(last, swing.last);
    }
    if (trialBoundaries) {
        first = std::max(first, trialBoundaries->first);
        last = std::min(last, trialBoundaries->last);
    }
    last = std::min(last, stance.size() - 1);
    if (first > last)
        return score;
    const std::vector<std::uint8_t> reference = referenceStance(swings, first, last);
    std::size_t truePositive = 0, detected = 0, actual = 0;
    for (std::size_t k = first; k <= last; ++k) {
        const bool isStance = stance[k] != 0, isReference = reference[k - first] != 0;
        truePositive += isStance && isReference;
        detected += isStance;
        actual += isReference;
        score.detectedPhases += isStance && (k == first || !stance[k - 1]);
        score.referencePhases += isReference && (k == first || !reference[k - first - 1]);
    }
    score.samplesCompared = last - first + 1;
    score.precision = ratio(truePositive, detected);
    score.recall = ratio(truePositive, actual);
    score.f1 = score.precision + score.recall > 0.0
                   ? 2.0 * score.precision * score.recall / (score.precision + score.recall)
                   : 0.0;
    score.stepCountError = static_cast<long>(score.detectedPhases) - static_cast<long>(score.referencePhases);
    return score;
}

std::vector<Eigen::Vector3d> alignReferenceToEstimate(const std::vector<Eigen::Vector3d>& reference,
                                                      const std::vector<Eigen::Vector3d>& estimate)
{
    const ArmseResult armse = computeArmse(estimate, reference);
    if (std::isnan(armse.rotation_rad))
        return {};
    // computeArmse turns the estimate onto the reference; the overlay needs the inverse turn.
    const Eigen::Matrix3d toEstimateFrame =
        Eigen::AngleAxisd(-armse.rotation_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    std::vector<Eigen::Vector3d> aligned;
    aligned.reserve(reference.size());
    for (const Eigen::Vector3d& p : reference)
        aligned.push_back(estimate.front() + toEstimateFrame * (p - reference.front()));
    return aligned;
}

StrideCount countStrides(const Result& result, const std::vector<SampleRange>& swings,
                         const SampleRange* trialBoundaries)
{
    StrideCount count;
    if (swings.empty() || result.time_s.empty())
        return count;
    SampleRange trial{swings.front().first, swings.front().last};
    for (const SampleRange& swing : swings) {
        trial.first = std::min(trial.first, swing.first);
        trial.last = std::max(trial.last, swing.last);
    }
    if (trialBoundaries)
        trial = *trialBoundaries;
    for (const SampleRange& swing : swings)
        count.labelled += swing.first >= trial.first && swing.last <= trial.last;
    const std::size_t lastSample = result.time_s.size() - 1;
    const double from_s = result.time_s[std::min(trial.first, lastSample)];
    const double to_s = result.time_s[std::min(trial.last, lastSample)];
    for (std::size_t i = 1; i < result.steps.size(); ++i) {
        const double swing_s = 0.5 * (result.steps[i - 1].stanceEnd_s + result.steps[i].stanceStart_s);
        count.detected += swing_s >= from_s && swing_s <= to_s;
    }
    count.error = static_cast<long>(count.detected) - static_cast<long>(count.labelled);
    return count;
}

EventTimingScore scoreEventTiming(const std::vector<double>& detected_s, const std::vector<double>& reference_s,
                                  double windowStart_s, double windowEnd_s, double missTolerance_s)
{
    EventTimingScore score;
    std::vector<double> detected = detected_s;
    std::sort(detected.begin(), detected.end());
    std::vector<double> errors;
    for (double reference : reference_s) {
        if (reference < windowStart_s || reference > windowEnd_s)
            continue;
        ++score.referenceEvents;
        if (detected.empty()) {
            ++score.missed;
            continue;
        }
        const auto after = std::lower_bound(detected.begin(), detected.end(), reference);
        double nearest = std::numeric_limits<double>::infinity();
        if (after != detected.end())
            nearest = *after - reference;
        if (after != detected.begin())
            nearest = std::min(nearest, reference - *(after - 1));
        errors.push_back(nearest);
        score.missed += nearest > missTolerance_s;
    }
    if (errors.empty()) {
        score.medianError_s = score.meanError_s = score.maxError_s = kNaN;
        return score;
    }
    std::sort(errors.begin(), errors.end());
    const std::size_t half = errors.size() / 2;
    score.medianError_s = errors.size() % 2 ? errors[half] : (errors[half - 1] + errors[half]) / 2.0;
    for (double error : errors)
        score.meanError_s += error / static_cast<double>(errors.size());
    score.maxError_s = errors.back();
    return score;
}

GaitEventTiming scoreGaitEventTiming(const Result& result, const Reference& reference)
{
    const std::vector<double>& time_s = result.time_s;
    std::vector<double> detectedHeelStrikes, detectedToeOffs, referenceHeelStrikes, referenceToeOffs;
    for (const GaitEvent& event : result.gaitEvents) {
        if (event.kind == GaitEventKind::HeelStrike)
            detectedHeelStrikes.push_back(event.time_s);
        else if (event.kind == GaitEventKind::ToeOff)
            detectedToeOffs.push_back(event.time_s);
    }
    for (const SampleRange& swing : reference.swings) {
        if (swing.last >= time_s.size())
            continue;
        referenceToeOffs.push_back(time_s[swing.first]);
        referenceHeelStrikes.push_back(time_s[swing.last]);
    }
    double start_s = -std::numeric_limits<double>::infinity(), end_s = std::numeric_limits<double>::infinity();
    if (reference.hasTrialBoundaries && !time_s.empty()) {
        start_s = time_s[std::min(reference.trialBoundaries.first, time_s.size() - 1)];
        end_s = time_s[std::min(reference.trialBoundaries.last, time_s.size() - 1)];
    }
    return {scoreEventTiming(detectedHeelStrikes, referenceHeelStrikes, start_s, end_s),
            scoreEventTiming(detectedToeOffs, referenceToeOffs, start_s, end_s)};
}

}  // namespace footpath
