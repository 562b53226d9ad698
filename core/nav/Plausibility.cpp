#include "nav/Plausibility.h"

#include "nav/Alignment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace footpath {

const char* warningKindName(PlausibilityWarning::Kind kind)
{
    using K = PlausibilityWarning::Kind;
    switch (kind) {
    case K::NoInitialRest:
        return "no_initial_rest";
    case K::LongSwing:
        return "long_swing";
    case K::StrideLength:
        return "stride_length";
    case K::StrideDuration:
        return "stride_duration";
    case K::StanceRatio:
        return "stance_ratio";
    case K::ImplausibleSpeed:
        return "implausible_speed";
    case K::FewStances:
        return "few_stances";
    case K::BarometerGap:
        return "barometer_gap";
    }
    return "unknown";
}

namespace {

using Kind = PlausibilityWarning::Kind;

template <typename... Args>
std::string format(const char* pattern, Args... args)
{
    char text[512];
    std::snprintf(text, sizeof text, pattern, args...);
    return text;
}

/// Half-open runs [first, last) of samples where predicate(k) holds.
template <typename Predicate>
std::vector<std::pair<std::size_t, std::size_t>> runsWhere(std::size_t n, Predicate predicate)
{
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    for (std::size_t k = 0; k < n;) {
        if (!predicate(k)) {
            ++k;
            continue;
        }
        std::size_t end = k;
        while (end < n && predicate(end))
            ++end;
        runs.emplace_back(k, end);
        k = end;
    }
    return runs;
}

/// The forward filter's speed: a smoother spreads a runaway over the recording, which must not
/// hide it.
double speedAt(const Result& result, std::size_t k)
{
    return result.forwardSpeed_mps.empty() ? result.velocity_mps[k].norm() : result.forwardSpeed_mps[k];
}

double peakSpeed(const Result& result, std::size_t first, std::size_t last)
{
    double peak = 0.0;
    for (std::size_t k = first; k < last; ++k)
        peak = std::max(peak, speedAt(result, k));
    return peak;
}

/// Why the detector did not call the quietest moment of [first, last) a stance.
std::string whatBlockedStance(const Result& result, std::size_t first, std::size_t last, const Parameters& params)
{
    const StanceFlags& flags = result.flags;
    std::size_t quietest = first;
    for (std::size_t k = first; k < last; ++k)
        if (flags.logStatistic[k] - flags.logThreshold[k] < flags.logStatistic[quietest] - flags.logThreshold[quietest])
            quietest = k;
    const double at = result.time_s[quietest];
    if (params.detectorKind() != DetectorKind::PaperC1C2C3) {
        if (flags.logStatistic[quietest] < flags.logThreshold[quietest])  // dropped by the duration rule
            return format("at its quietest (t = %.2f s) the detector statistic (10^%.1f) fell below its threshold "
                          "(10^%.1f) for less than the minimum stance of %.3f s",
                          at, flags.logStatistic[quietest], flags.logThreshold[quietest], params.zv_min_stance_s);
        return format("at its quietest (t = %.2f s) the detector statistic was 10^%.1f, above its threshold 10^%.1f",
                      at, flags.logStatistic[quietest], flags.logThreshold[quietest]);
    }
    std::string failed;
    const auto note = [&](bool ok, const char* what) {
        if (!ok)
            failed += (failed.empty() ? "" : ", ") + std::string(what);
    };
    note(flags.c1[quietest], "C1 (|a| outside its band)");
    note(flags.c2[quietest], "C2 (std of |a| above its bound)");
    note(flags.c3[quietest], "C3 (|w| above its bound)");
    if (failed.empty())
        failed = "the median filter";
    return format("at its quietest (t = %.2f s) it was blocked by %s", at, failed.c_str());
}

void checkInitialRest(const Result& result, const Parameters& params, const PlausibilityLimits& limits,
                      std::vector<PlausibilityWarning>& out)
{
    // Where runFilter started: after a mid-walk start it waited for the first stance.
    const std::size_t start = std::min(alignmentStart(result.flags.stance), result.time_s.size() - 1);
    const double held_s = result.time_s[start] - result.time_s.front();
    if (held_s > limits.maxQuietHold_s) {
        // Feliz's integrator runs from the first sample; only its attitude waits for the stance.
        const std::string what =
            params.estimatorKind() == EstimatorKind::Feliz
                ? format("Roll and pitch were aligned at that first stance; the %.2f s before it are integrated from "
                         "an assumed rest, so the start of the path is uncertain.",
                         held_s)
                : format("The path starts at that first stance, where roll and pitch were aligned, instead of "
                         "assuming rest at the first sample; the %.2f s before it are held at the start position "
                         "and not estimated.",
                         held_s);
        out.push_back({Kind::NoInitialRest, result.time_s.front(), result.time_s[start],
                       format("The recording starts mid-walk (no stance until t = %.2f s). ", result.time_s[start])
                           + what});
        return;
    }
    const double end = result.time_s.front() + params.alignment_s;
    std::size_t count = 0, atRest = 0;
    for (std::size_t k = 0; k < result.time_s.size() && result.time_s[k] <= end; ++k, ++count)
        atRest += result.flags.stance[k];
    const double share = count > 0 ? static_cast<double>(atRest) / static_cast<double>(count) : 0.0;
    if (share >= limits.minInitialRestShare)
        return;
    const std::string message =
        result.steps.empty()
            ? format("The recording has no stance at all: roll and pitch were aligned on the first %.2f s of a "
                     "moving foot, so the path may tilt and drift.",
                     params.alignment_s)
            : format("The recording does not start at rest: only %.0f %% of the first %.2f s are stance. Roll and "
                     "pitch were aligned on the first stance samples alone, so the initial attitude is less certain "
                     "and the path may tilt.",
                     100.0 * share, params.alignment_s);
    out.push_back({Kind::NoInitialRest, result.time_s.front(), end, message});
}

void checkSwings(const Result& result, const Parameters& params, const PlausibilityLimits& limits,
                 std::vector<PlausibilityWarning>& out)
{
    const std::vector<std::uint8_t>& stance = result.flags.stance;
    for (const auto& [first, last] : runsWhere(stance.size(), [&](std::size_t k) { return !stance[k]; })) {
        const double duration = result.time_s[last - 1] - result.time_s[first];
        if (duration <= limits.maxSwing_s || peakSpeed(result, first, last) < limits.movingSpeed_mps)
            continue;
        out.push_back({Kind::LongSwing, result.time_s[first], result.time_s[last - 1],
                       format("No stance for %.1f s while moving: a stance was probably missed, and the path drifts "
                              "without the zero-velocity updates; %s.",
                              duration, whatBlockedStance(result, first, last, params).c_str())});
    }
}

/// Steps are numbered from 1 wherever a user sees them (the step table, the steps CSV, the report):
/// a warning names the step its stride leads to by that number.
std::size_t stepNumber(std::size_t stepIndex)
{
    return stepIndex + 1;
}

void checkStrides(const Result& result, const PlausibilityLimits& limits, std::vector<PlausibilityWarning>& out)
{
    for (std::size_t i = 1; i < result.steps.size(); ++i) {
        const Step& previous = result.steps[i - 1];
        const Step& step = result.steps[i];
        if (step.strideLength_m > limits.maxStrideLength_m)
            out.push_back({Kind::StrideLength, previous.stanceEnd_s, step.stanceStart_s,
                           format("The stride to step %zu is %.2f m long; human strides stay under %.1f m, so the "
                                  "stance between was missed or the filter drifted.",
                                  stepNumber(i), step.strideLength_m, limits.maxStrideLength_m)});
        else if (step.strideDuration_s < limits.minStrideDuration_s && step.strideLength_m > limits.minStrideLength_m)
            out.push_back({Kind::StrideDuration, previous.stanceStart_s, step.stanceStart_s,
                           format("The stride to step %zu took only %.2f s for %.2f m; a human stride takes at least "
                                  "%.1f s, so a stance was probably found in the middle of a swing.",
                                  stepNumber(i), step.strideDuration_s, step.strideLength_m, limits.minStrideDuration_s)});
    }
}

void checkSpeed(const Result& result, const PlausibilityLimits& limits, std::vector<PlausibilityWarning>& out)
{
    const auto tooFast = [&](std::size_t k) { return speedAt(result, k) > limits.maxFootSpeed_mps; };
    for (const auto& [first, last] : runsWhere(result.time_s.size(), tooFast))
        out.push_back({Kind::ImplausibleSpeed, result.time_s[first], result.time_s[last - 1],
                       format("The estimated foot speed reaches %.1f m/s, faster than a foot moves (under %.0f m/s): "
                              "the filter ran away here and the path is not to be trusted.",
                              peakSpeed(result, first, last), limits.maxFootSpeed_mps)});
}

void checkStanceShare(const Result& result, const PlausibilityLimits& limits, std::vector<PlausibilityWarning>& out)
{
    // From the first to the last moment the foot moves: standing before and after is no gait.
    const auto moving = [&](const Eigen::Vector3d& v) { return v.norm() > limits.movingSpeed_mps; };
    const auto firstMoving = std::find_if(result.velocity_mps.begin(), result.velocity_mps.end(), moving);
    if (firstMoving == result.velocity_mps.end())
        return;
    const auto lastMoving = std::find_if(result.velocity_mps.rbegin(), result.velocity_mps.rend(), moving);
    const auto first = static_cast<std::size_t>(firstMoving - result.velocity_mps.begin());
    const auto last = static_cast<std::size_t>(result.velocity_mps.rend() - lastMoving);  // one past
    const double span = result.time_s[last - 1] - result.time_s[first];
    if (span < 5.0)
        return;  // too short a walk to judge a share
    double stanceTime = 0.0;
    for (std::size_t k = first + 1; k < last; ++k)
        if (result.flags.stance[k])
            stanceTime += result.time_s[k] - result.time_s[k - 1];
    const double share = stanceTime / span;
    if (share < limits.minStanceShare || share > limits.maxStanceShare)
        out.push_back({Kind::StanceRatio, result.time_s[first], result.time_s[last - 1],
                       format("The foot is at rest %.0f %% of the time while walking; gait keeps it still 15-60 %% "
                              "of the time, so stances are %s.",
                              100.0 * share, share < limits.minStanceShare ? "being missed" : "found where the foot moves")});
}

constexpr double kNeverMovedRestShare = 0.95;

void checkStanceCount(const Result& result, std::vector<PlausibilityWarning>& out)
{
    const double duration = result.summary.duration_s;
    if (duration < 10.0 || result.steps.size() >= 3)
        return;
    const std::vector<std::uint8_t>& stance = result.flags.stance;
    const double restShare = static_cast<double>(std::count(stance.begin(), stance.end(), 1))
                             / static_cast<double>(stance.size());
    // Few stances because the foot never left the ground is a different problem from a detector
    // that misses them: say which one it is.
    if (restShare > kNeverMovedRestShare) {
        out.push_back({Kind::FewStances, result.time_s.front(), result.time_s.back(),
                       format("The foot is at rest for %.0f %% of the %.0f s: the sensor hardly moved, so there is "
                              "no walk to estimate.",
                              100.0 * restShare, duration)});
        return;
    }
    out.push_back({Kind::FewStances, result.time_s.front(), result.time_s.back(),
                   format("Only %zu stance phases in %.0f s: the detector does not find the foot at rest, so the "
                          "path is integrated without corrections.",
                          result.steps.size(), duration)});
}

/// x rounded to tenths, with no negative zero ("+0.0 m", not "-0.0 m", for a height that did not change).
double tenths(double x)
{
    return std::round(10.0 * x) / 10.0 + 0.0;
}

/// With pressure in the recording but the barometer not fused (use_baro off), each stance's height
/// since the first stance against the barometer's (Step::baroHeight_m). The inertial height alone
/// drifts by metres over a few minutes of 100 Hz walking and cannot see an elevator ride; the
/// pressure drifts only with the weather, over hours. Two thirds of a floor apart, the heights and
/// any floor read from them are not to be trusted, and fusing the barometer is the remedy.
void checkHeightAgainstBarometer(const Result& result, const Parameters& params, const PlausibilityLimits& limits,
                                 std::vector<PlausibilityWarning>& out)
{
    const std::vector<Step>& steps = result.steps;
    if (params.use_baro || steps.size() < 2 || !std::isfinite(steps.front().baroHeight_m))
        return;
    // baroHeight_m is already the height since the first stance (MotionClasses); the path's is not.
    const auto heightSinceFirst = [&](const Step& step) { return step.position_m.z() - steps.front().position_m.z(); };
    std::size_t firstApart = steps.size(), lastApart = 0, widest = 0;
    double widestGap_m = 0.0;
    for (std::size_t i = 1; i < steps.size(); ++i) {
        const double gap_m = heightSinceFirst(steps[i]) - steps[i].baroHeight_m;
        if (!(std::abs(gap_m) > limits.maxBarometerGap_m))  // a NaN (a stance without pressure) is no finding
            continue;
        firstApart = std::min(firstApart, i);
        lastApart = i;
        if (std::abs(gap_m) > widestGap_m) {
            widest = i;
            widestGap_m = std::abs(gap_m);
        }
    }
    if (firstApart == steps.size())
        return;
    const Step& worst = steps[widest];
    out.push_back({Kind::BarometerGap, steps[firstApart].stanceStart_s, steps[lastApart].stanceEnd_s,
                   format("The stance heights and the barometer disagree by %.1f m at %.0f s (height since the first "
                          "stance: %+.1f m on the path, %+.1f m from the pressure): the inertial height drifts and "
                          "does not see an elevator ride, so heights and floors are not to be trusted. The "
                          "barometric height (use_baro) holds them to the pressure.",
                          widestGap_m, worst.stanceStart_s, tenths(heightSinceFirst(worst)), tenths(worst.baroHeight_m))});
}

}  // namespace

std::vector<PlausibilityWarning> checkPlausibility(const Result& result, const Parameters& params,
                                                   const PlausibilityLimits& limits)
{
    std::vector<PlausibilityWarning> warnings;
    if (result.time_s.empty() || result.flags.stance.size() != result.time_s.size())
        return warnings;
    checkInitialRest(result, params, limits, warnings);
    checkSwings(result, params, limits, warnings);
    checkStrides(result, limits, warnings);
    checkSpeed(result, limits, warnings);
    checkStanceShare(result, limits, warnings);
    checkStanceCount(result, warnings);
    checkHeightAgainstBarometer(result, params, limits, warnings);
    std::stable_sort(warnings.begin(), warnings.end(),
                     [](const PlausibilityWarning& a, const PlausibilityWarning& b) { return a.start_s < b.start_s; });
    return warnings;
}

}  // namespace footpath
