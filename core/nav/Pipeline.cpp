#include "nav/Pipeline.h"

#include "detect/StanceDetector.h"
#include "detect/StanceFlagsAhead.h"
#include "gait/GaitEvents.h"
#include "metrics/Evaluation.h"
#include "nav/Alignment.h"
#include "nav/Attitude.h"
#include "nav/ErrorStateEkf.h"
#include "nav/FelizIntegrator.h"
#include "nav/InputCheck.h"
#include "nav/MeasurementSources.h"
#include "nav/MotionClasses.h"
#include "nav/Plausibility.h"
#include "nav/RtsSmoother.h"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <utility>

namespace footpath {

namespace {

constexpr std::size_t kProgressInterval = 8192;

std::string checkInput(const Recording& recording, const Parameters& params)
{
    std::ostringstream out;
    for (const std::string& problem : params.validate())
        out << problem << "\n";
    if (recording.samples.size() < 2)
        out << "the recording has " << recording.samples.size() << " samples; at least 2 are needed\n";
    if (const std::string damage = describeUnusableSamples(recording.samples); !damage.empty())
        out << damage << "\n";
    std::string text = out.str();
    if (!text.empty())
        text.pop_back();
    return text;
}

}  // namespace

Result reusingMemoryOf(Result&& used)
{
    Result empty;
    const auto take = [](auto& into, auto& from) {
        from.clear();
        into.swap(from);
    };
    take(empty.time_s, used.time_s);
    take(empty.position_m, used.position_m);
    take(empty.velocity_mps, used.velocity_mps);
    take(empty.rollPitchYaw_rad, used.rollPitchYaw_rad);
    take(empty.gyroBias_radps, used.gyroBias_radps);
    take(empty.accBias_mps2, used.accBias_mps2);
    take(empty.errorStd, used.errorStd);
    take(empty.forwardSpeed_mps, used.forwardSpeed_mps);
    take(empty.flags.c1, used.flags.c1);
    take(empty.flags.c2, used.flags.c2);
    take(empty.flags.c3, used.flags.c3);
    take(empty.flags.c, used.flags.c);
    take(empty.flags.stance, used.flags.stance);
    take(empty.gaitStance, used.gaitStance);
    take(empty.flags.logStatistic, used.flags.logStatistic);
    take(empty.flags.logThreshold, used.flags.logThreshold);
    return empty;
}

void reserveResult(Result& result, std::size_t n)
{
    result.time_s.reserve(n);
    result.position_m.reserve(n);
    result.velocity_mps.reserve(n);
    result.rollPitchYaw_rad.reserve(n);
    result.gyroBias_radps.reserve(n);
    result.accBias_mps2.reserve(n);
}

namespace {

/// The per-sample vectors but the attitude angles. The smoother's forward pass records only these:
/// the backward pass writes every sample's attitude and standard deviations.
void recordStateButAttitude(Result& result, double time_s, const NavState& state)
{
    result.time_s.push_back(time_s);
    result.position_m.push_back(state.position_m);
    result.velocity_mps.push_back(state.velocity_mps);
    result.gyroBias_radps.push_back(state.gyroBias_radps);
    result.accBias_mps2.push_back(state.accBias_mps2);
}

}  // namespace

void recordState(Result& result, double time_s, const NavState& state)
{
    recordStateButAttitude(result, time_s, state);
    result.rollPitchYaw_rad.push_back(rollPitchYaw(state.bodyToNav));
}

namespace {

/// smootherFor, with room for the updates of stanceSamples stance samples (a bound will do: the
/// room is reserved, not touched).
std::optional<RtsSmoother> smootherWithRoomFor(const std::vector<ImuSample>& samples, const Parameters& params,
                                               std::size_t stanceSamples, ErrorStateEkf& ekf,
                                               std::vector<MethodNote>& notes, std::size_t budget_bytes)
{
    std::optional<RtsSmoother> smoother;
    if (params.estimatorKind() != EstimatorKind::Smoother)
        return smoother;
    smoother.emplace(params, ekf);
    const std::size_t needed = smoother->projectedBytes(samples.size(), stanceSamples);
    if (needed <= budget_bytes) {
        smoother->reserve(samples.size(), stanceSamples);
        return smoother;
    }
    smoother.reset();
    ekf.setRecordUpdates(false);
    std::ostringstream message;
    message.precision(2);
    message << std::fixed << "not applied: smoothing this recording would store " << static_cast<double>(needed) / double(1 << 30)
            << " GiB, more than the " << static_cast<double>(budget_bytes) / double(1 << 30)
            << " GiB a run may use; the path is the filter's (a shorter recording is smoothed)";
    notes.push_back(MethodNote{"rts", samples.front().time_s, samples.back().time_s, message.str()});
    return smoother;
}

/// The smoother for a run whose stance flags may still be being decided: room for every sample
/// to be a stance sample while that fits the budget, otherwise smootherFor on the final flags (so
/// the decision is smootherFor's either way). Flags already final give the exact room: the bound
/// made the self-tuning's many short runs (one thread each) 15 % slower (bench_tune 4.5 -> 5.4 s).
std::optional<RtsSmoother> smootherAhead(const std::vector<ImuSample>& samples, const Parameters& params,
                                         StanceFlagsAhead& ahead, const StanceFlags& flags, ErrorStateEkf& ekf,
                                         std::vector<MethodNote>& notes)
{
    if (ahead.allDecided())
        return smootherFor(samples, params, flags, ekf, notes);
    std::vector<MethodNote> boundNotes;  // a bound that does not fit says nothing about the run
    std::optional<RtsSmoother> smoother = smootherWithRoomFor(samples, params, samples.size(), ekf, boundNotes,
                                                              RtsSmoother::kMemoryBudget_bytes);
    if (smoother || params.estimatorKind() != EstimatorKind::Smoother)
        return smoother;
    ahead.waitForAll();
    return smootherFor(samples, params, flags, ekf, notes);
}

}  // namespace

std::optional<RtsSmoother> smootherFor(const std::vector<ImuSample>& samples, const Parameters& params,
                                       const StanceFlags& flags, ErrorStateEkf& ekf, std::vector<MethodNote>& notes,
                                       std::size_t budget_bytes)
{
    const auto stanceSamples = static_cast<std::size_t>(std::count(flags.stance.begin(), flags.stance.end(), 1));
    return smootherWithRoomFor(samples, params, stanceSamples, ekf, notes, budget_bytes);
}

namespace {

/// Runs the filter over every sample, then the smoother's backward pass when it is chosen, and
/// afterStates once the states are final (with the smoother, while its variances are still being
/// computed on another thread: afterStates must not touch errorStd); returns false if the callback
/// cancelled.
bool runFilter(const Recording& recording, const Parameters& params, StanceFlagsAhead& ahead,
               const ProgressCallback& progress, Result& result, const std::function<void()>& afterStates,
               RtsSmoother::Threads threads, RtsSmoother::Variances variances)
{
    const std::vector<ImuSample>& samples = recording.samples;
    const StanceFlags& flags = result.flags;
    // After a mid-walk start, the first stance.
    const std::size_t start = waitForAlignmentFlags(ahead, samples, flags.stance, params.alignment_s);
    const AlignmentResult alignment = alignInitialAttitude(samples, flags.stance, params);
    ErrorStateEkf ekf(params, alignment.bodyToNav);
    MeasurementSources sources(params);
    std::optional<RtsSmoother> smoother = smootherAhead(samples, params, ahead, flags, ekf, result.methodNotes);
    // The forward pass is most of the work without the smoother, about half with it.
    const double forwardShare = smoother ? 0.5 : 1.0;
    reserveResult(result, samples.size());
    if (!smoother)
        result.errorStd.reserve(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
        ahead.waitFor(k + 1);
        const ImuSample& sample = samples[k];
        const std::optional<double> previousTime_s =
            k > start ? std::optional<double>(samples[k - 1].time_s) : std::nullopt;
        if (smoother) {  // samples before the start: the filter stands still, as holdAtStart records
            if (k >= start)
                advanceFilter(ekf, sources, sample, previousTime_s, flagsAt(flags, k), k, result.methodNotes);
            recordStateButAttitude(result, sample.time_s, ekf.state());
            smoother->capture(ekf);
        } else if (k < start) {
            holdAtStart(ekf, sample.time_s, result);
        } else {
            filterSample(ekf, sources, sample, previousTime_s, flagsAt(flags, k), result);
        }
        if (progress && k % kProgressInterval == 0
            && !progress(forwardShare * static_cast<double>(k) / static_cast<double>(samples.size())))
            return false;
    }
    sources.finish(samples.back().time_s, result.methodNotes);
    if (!smoother) {
        afterStates();
        return true;
    }
    result.forwardSpeed_mps.reserve(samples.size());
    for (const Eigen::Vector3d& velocity : result.velocity_mps)
        result.forwardSpeed_mps.push_back(static_cast<float>(velocity.norm()));
    result.rollPitchYaw_rad.resize(samples.size());
    if (variances == RtsSmoother::Variances::Compute)
        result.errorStd.resize(samples.size());
    return smoother->smooth(
        result, [&](double fraction) { return !progress || progress(forwardShare + (1.0 - forwardShare) * fraction); },
        afterStates, threads, variances);
}

double horizontalDistance(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return (a - b).head<2>().norm();
}

Step makeStep(const Result& result, std::size_t first, std::size_t last)
{
    Step step;
    step.stanceStart_s = result.time_s[first];
    step.stanceEnd_s = result.time_s[last - 1];
    for (std::size_t k = first; k < last; ++k)
        step.position_m += result.position_m[k];
    step.position_m /= static_cast<double>(last - first);
    return step;
}

}  // namespace

void advanceFilter(ErrorStateEkf& ekf, MeasurementSources& sources, const ImuSample& sample,
                   std::optional<double> previousTime_s, const SampleStanceFlags& flags, std::size_t index,
                   std::vector<MethodNote>& notes)
{
    if (previousTime_s)
        ekf.propagate(sample.acc_mps2, sample.gyr_radps, sample.time_s - *previousTime_s);
    sources.apply(ekf, SourceContext{sample, index, flags, notes});
}

void filterSample(ErrorStateEkf& ekf, MeasurementSources& sources, const ImuSample& sample,
                  std::optional<double> previousTime_s, const SampleStanceFlags& flags, Result& result)
{
    advanceFilter(ekf, sources, sample, previousTime_s, flags, result.time_s.size(), result.methodNotes);
    recordState(result, sample.time_s, ekf.state());
    result.errorStd.push_back(ekf.covariance().diagonal().cwiseMax(0.0).cwiseSqrt().cast<float>());
}

bool appendStep(Result& result, std::size_t first, std::size_t last, double peakRateBefore_radps)
{
    Step step = makeStep(result, first, last);
    bool merged = false;
    if (!result.steps.empty()) {
        const Step& previous = result.steps.back();
        const double moved_m = (step.position_m - previous.position_m).norm();  // a stair step may rise more than it goes
        if (moved_m < kMinStrideDistance_m || peakRateBefore_radps < kMinSwingRate_radps) {
            result.mergedMovements.push_back({previous.stanceEnd_s, step.stanceStart_s, moved_m, peakRateBefore_radps});
            first = static_cast<std::size_t>(
                std::lower_bound(result.time_s.begin(), result.time_s.end(), previous.stanceStart_s) - result.time_s.begin());
            result.steps.pop_back();
            merged = true;
            step = makeStep(result, first, last);
        }
    }
    if (!result.steps.empty()) {
        const Step& previous = result.steps.back();
        step.strideLength_m = horizontalDistance(step.position_m, previous.position_m);
        step.strideDuration_s = step.stanceStart_s - previous.stanceStart_s;
    }
    result.steps.push_back(step);
    return merged;
}

void summarize(Result& result, double pathLength_m)
{
    Summary& summary = result.summary;
    summary.samples = result.time_s.size();
    summary.duration_s = result.time_s.empty() ? 0.0 : result.time_s.back() - result.time_s.front();
    summary.stancePhases = result.steps.size();
    summary.steps = result.steps.empty() ? 0 : result.steps.size() - 1;
    summary.pathLength_m = pathLength_m;
    const LoopClosure closure = computeLoopClosure(result.position_m, summary.pathLength_m);
    summary.endToStart_m = closure.dbse_m;
    summary.endToStartPct = closure.dbsePct;
}

void fillStepsAndSummary(Result& result, const std::vector<ImuSample>& samples)
{
    const std::vector<std::uint8_t>& stance = result.flags.stance;
    result.steps.clear();
    result.mergedMovements.clear();
    double peakRate_radps = 0.0;  // of the samples since the last stance phase
    for (std::size_t k = 0; k < stance.size();) {
        if (!stance[k]) {
            if (k < samples.size())
                peakRate_radps = std::max(peakRate_radps, samples[k].gyr_radps.norm());
            ++k;
            continue;
        }
        std::size_t end = k;
        while (end < stance.size() && stance[end])
            ++end;
        appendStep(result, k, end, peakRate_radps);
        peakRate_radps = 0.0;
        k = end;
    }
    summarize(result, stancePathLength(result.steps));
}

void postProcess(const Recording& recording, const Parameters& params, Result& result, GaitRates gaitRates)
{
    fillStepsAndSummary(result, recording.samples);
    detectGaitEvents(recording, std::move(gaitRates), result);
    classifyMotion(recording, params, result);
    result.warnings = checkPlausibility(result, params);
}

PipelineOutput runPipeline(const Recording& recording, const Parameters& params, const ProgressCallback& progress,
                           RtsSmoother::Threads threads, Result storage, RtsSmoother::Variances variances)
{
    PipelineOutput output;
    // A used result over twice this run's size (a long walk's before a short one) is let go:
    // refilled, its memory would stay held for nothing.
    if (storage.time_s.capacity() <= 2 * recording.samples.size())
        output.result = reusingMemoryOf(std::move(storage));
    output.error = checkInput(recording, params);
    if (!output.error.empty())
        return output;
    const auto start = std::chrono::steady_clock::now();
    Result& result = output.result;
    bool completed = false;
    GaitRates gaitRates;  // the gait detection's rates: the samples alone decide them
    {
        // With a second thread the filter runs behind the detector, which may write result.flags
        // until this scope ends (a cancelled run): output is returned only after that. Then that
        // thread, idle while the filter runs, computes the gait rates.
        StanceFlagsAhead ahead(recording.samples, params, result.flags,
                               threads == RtsSmoother::Threads::Two ? StanceFlagsAhead::Mode::Concurrent
                                                                    : StanceFlagsAhead::Mode::First,
                               [&] { gaitRates = gaitRatesOf(recording.samples); });
        // postProcess reads no standard deviations, so it overlaps the smoother's variances (runFilter).
        const auto finishStates = [&] {
            ahead.waitForAfterFlags();
            postProcess(recording, params, result, std::move(gaitRates));
        };
        if (params.estimatorKind() == EstimatorKind::Feliz) {
            ahead.waitForAll();
            completed = runFelizIntegrator(recording, params, progress, result);
            if (completed)
                finishStates();
        } else {
            completed = runFilter(recording, params, ahead, progress, result, finishStates, threads, variances);
        }
    }
    if (!completed) {
        result.cancelled = true;
        return output;
    }
    result.summary.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (progress)
        progress(1.0);
    return output;
}

}  // namespace footpath
