#pragma once

#include "Recording.h"
#include "Result.h"
#include "gait/GaitEvents.h"
#include "nav/Parameters.h"
#include "nav/RtsSmoother.h"

#include <functional>
#include <optional>
#include <string>

namespace footpath {

class ErrorStateEkf;
struct NavState;
class MeasurementSources;
struct SampleStanceFlags;

/// Called now and then with the fraction done (0..1); return false to cancel the run.
using ProgressCallback = std::function<bool(double fraction)>;

struct PipelineOutput {
    Result result;
    std::string error;  ///< empty on success; otherwise why nothing was estimated
};

/// The whole Guo 2015 pipeline as a pure function: stance detection, initial alignment, strapdown
/// mechanization with the EKF (ZUPT/ZARU as enabled), then the per-step table and summary.
/// Re-entrant: nothing is shared between calls, so the GUI may start a new run while an old one
/// is being cancelled. The run uses a second thread, one after the other, for the stance detector
/// (the filter follows behind it: StanceFlagsAhead) and with the smoother for its variances, unless
/// threads is One (for a caller that runs several estimates at once, AutoTune and runComparison:
/// their cores are busy already); the numbers are the same either way.
/// storage: a result nobody needs any more, whose per-sample memory the run fills again
/// (reusingMemoryOf) unless it was made for over twice as many samples; the numbers are the same
/// as with none.
/// variances: Skip leaves Result::errorStd empty when the smoother runs, for a caller that reads
/// no standard deviations (the command line, the self-tuning, the comparisons: only the window's
/// state rows draw them). They are the larger of the smoother's two backward passes: a run does
/// about a quarter less work without them (5520 -> 3998 instructions a sample on a pyshoe-vicon
/// trial), which is time where runs share the cores. The states are the same to the last bit. The
/// filter alone records its own standard deviations either way (a square root of its diagonal).
PipelineOutput runPipeline(const Recording& recording, const Parameters& params,
                           const ProgressCallback& progress = {}, RtsSmoother::Threads threads = RtsSmoother::Threads::Two,
                           Result storage = {}, RtsSmoother::Variances variances = RtsSmoother::Variances::Compute);

/// A new, empty result that owns the memory of used's per-sample vectors (time, states, standard
/// deviations, speed, stance flags, gait stance): emptied, their capacity kept. A slider's re-runs
/// fill the same memory again instead of fresh memory, which costs a page fault and the kernel's
/// zeroing of every page first touched (a 30-minute walk's result is about 37 MB, 9000 pages).
/// The paper's C1/C2/C3 detector makes its flags anew (whole-vector windows), so only the
/// statistic detectors fill the flags' memory again.
Result reusingMemoryOf(Result&& used);

/// The threads each of concurrentRuns runs at once may use: two alone, one when the runs already
/// share the cores (AutoTune, runComparison; a second thread each made tuning 11 % slower).
inline RtsSmoother::Threads threadsPerRun(std::size_t concurrentRuns)
{
    return concurrentRuns > 1 ? RtsSmoother::Threads::One : RtsSmoother::Threads::Two;
}

/// Reserves room for n samples in result's per-sample vectors (time, state, attitude, biases).
void reserveResult(Result& result, std::size_t n);

/// The smoother for a run when the parameters choose it and what it would store fits budget_bytes
/// (runPipeline: RtsSmoother::kMemoryBudget_bytes); otherwise none, the filter's estimate, with a
/// note saying why. Exposed for tests.
std::optional<RtsSmoother> smootherFor(const std::vector<ImuSample>& samples, const Parameters& params,
                                       const StanceFlags& flags, ErrorStateEkf& ekf, std::vector<MethodNote>& notes,
                                       std::size_t budget_bytes = RtsSmoother::kMemoryBudget_bytes);

/// Appends one sample's time and navigation state to result's per-sample vectors.
void recordState(Result& result, double time_s, const NavState& state);

/// Stance phases of the result as steps (stance times, mean stance position, stride) and the summary
/// figures that depend on them; samples are the recording's (their angular rate tells a swing from
/// a weight shift, appendStep). Exposed for tests; runPipeline calls it.
void fillStepsAndSummary(Result& result, const std::vector<ImuSample>& samples);

/// What runPipeline derives from the filter's (or smoother's) states and stance flags in result:
/// the steps and summary, the gait events, the motion classes and the plausibility warnings.
/// gaitRates: gaitRatesOf(recording.samples) if already computed, else computed here. Exposed for
/// the benchmark of these steps alone.
void postProcess(const Recording& recording, const Parameters& params, Result& result, GaitRates gaitRates = {});

// The pieces below are shared with StreamingEstimator, which runs them one sample at a time and so
// gives the same numbers as runPipeline.

/// The filter's work on one sample, not recorded: propagation over the time since the previous
/// sample (none for the first), then the measurement sources; index is the sample's number in the
/// result, notes where the sources write.
void advanceFilter(ErrorStateEkf& ekf, MeasurementSources& sources, const ImuSample& sample,
                   std::optional<double> previousTime_s, const SampleStanceFlags& flags, std::size_t index,
                   std::vector<MethodNote>& notes);

/// The filter's work on one sample: propagation over the time since the previous sample (none for
/// the first), the measurement sources (ZUPT/ZARU and the other methods as enabled), then the state
/// appended to result (the stance flags are the caller's to append; notes go to result.methodNotes).
void filterSample(ErrorStateEkf& ekf, MeasurementSources& sources, const ImuSample& sample,
                  std::optional<double> previousTime_s, const SampleStanceFlags& flags, Result& result);

/// Appends the stance phase of samples [first, last) of result as a step, with its stride from the
/// previous step; or, when the movement since the previous step was no stride (it moved the foot
/// less than kMinStrideDistance_m, or its highest angular rate, peakRateBefore_radps, stayed under
/// kMinSwingRate_radps), extends that step over both and lists the movement in
/// result.mergedMovements. A weight shift while standing or a moment the detector lost the stance
/// is no stride: counted as one it would add a stride of millimetres lasting seconds. Returns true
/// when it merged. Summary fields are left alone.
bool appendStep(Result& result, std::size_t first, std::size_t last, double peakRateBefore_radps);

/// A stride moves the foot at least this far (in 3D: a step up a stair may rise more than it goes) ...
constexpr double kMinStrideDistance_m = 0.1;
/// ... and turns it faster than this at some moment of its swing. A walking swing peaks at 3-20
/// rad/s, the slowest shuffles of the shared walks at 1.6 rad/s; shifting the weight while standing
/// stays under 1.1 rad/s.
constexpr double kMinSwingRate_radps = 1.0;

/// Sets every summary field but runtime_s from the samples and steps so far, with the given path
/// length (the sum of the steps' stride lengths). Constant time; result must hold a sample.
void summarize(Result& result, double pathLength_m);

}  // namespace footpath
