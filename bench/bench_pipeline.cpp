// Speed of the estimation pipeline (stance detector + EKF, defaults and the paper's configuration) on a 30-minute
// simulated walk at 100 Hz, offline and live, and on a real 200 Hz walk (a pyshoe-vicon trial repeated to a
// minute) beside the textbook dense-matrix implementation of the same estimator (tests/DenseReferenceFilter).
// Targets (issue 14): at least 5 million samples per second offline on real walking data, 10 times the
// dense loop; BM_SpeedRatioRealWalk gives that ratio from runs of the two side by side, which a
// machine whose speed drifts moves far less than the ratio of two benchmarks' times.
// BM_PostProcessing times the steps after the filter alone; BM_EkfPropagate, BM_EkfStanceSample and
// BM_SmootherCapture the parts of the forward pass's work a sample. Run with
// --benchmark_repetitions=5 --benchmark_report_aggregates_only=true on a busy machine.
#include "DenseReferenceFilter.h"
#include "SimulatedWalks.h"
#include "detect/StanceDetector.h"
#include "io/Import.h"
#include "nav/ErrorStateEkf.h"
#include "nav/Pipeline.h"
#include "nav/RtsSmoother.h"
#include "nav/StreamingEstimator.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <vector>

using namespace footpath;

namespace {

/// A pyshoe-vicon trial (200 Hz, 32 s of walking) played again after itself until it lasts a
/// minute; empty when the shared recordings are not there.
const Recording& realMinuteWalk()
{
    static const Recording recording = [] {
        const char* fromEnv = std::getenv("FOOTPATH_DATASETS");
        const std::filesystem::path file = std::filesystem::path(fromEnv ? fromEnv : FOOTPATH_DATASETS_DIR)
                                           / "pyshoe-vicon" / "2017-11-22-11-22-03.csv";
        Recording repeated;
        if (!std::filesystem::exists(file))
            return repeated;
        ImportResult read = importRecording(file.string());
        if (!read.ok() || read.recording.samples.size() < 2)
            return repeated;
        const std::vector<ImuSample>& trial = read.recording.samples;
        const double period_s = trial.back().time_s - trial.front().time_s
                                + (trial[1].time_s - trial[0].time_s);  // one sample step between copies
        for (double offset_s = 0.0; repeated.duration_s() < 60.0; offset_s += period_s)
            for (ImuSample sample : trial) {
                sample.time_s += offset_s;
                repeated.samples.push_back(sample);
            }
        repeated.source = file.string();
        return repeated;
    }();
    return recording;
}

/// Argument 0: the defaults (adaptive SHOE detector, 9-state filter with ZUPT, RTS smoother) as the
/// window runs them; 1: Guo 2015 as printed (C1/C2/C3, 15 states, ZUPT+ZARU, filter only); 2: the
/// defaults with the filter alone (no smoother); 3: the defaults as the command line, the
/// self-tuning and the comparisons run them, without the smoothed standard deviations (only the
/// window's state rows draw them; the dense reference computes none either).
Parameters parametersFor(const benchmark::State& state)
{
    if (state.range(0) == 1)
        return guo2015Parameters();
    Parameters params;
    if (state.range(0) == 2)
        params.estimator = static_cast<int>(EstimatorKind::Ekf);
    return params;
}

RtsSmoother::Variances variancesFor(const benchmark::State& state)
{
    return state.range(0) == 3 ? RtsSmoother::Variances::Skip : RtsSmoother::Variances::Compute;
}

void setLabel(benchmark::State& state)
{
    static const char* const names[] = {"defaults", "paper", "filter alone", "defaults, no smoothed std"};
    state.SetLabel(names[state.range(0)]);
}

/// Times estimate(recording, params) over recording with the parameters of the benchmark's argument.
template <typename Estimate>
void timeEstimates(benchmark::State& state, const Recording& recording, Estimate estimate)
{
    if (recording.samples.empty()) {
        state.SkipWithError("pyshoe-vicon/2017-11-22-11-22-03.csv is not in the shared datasets (set FOOTPATH_DATASETS)");
        return;
    }
    const Parameters params = parametersFor(state);
    for (auto _ : state)
        benchmark::DoNotOptimize(estimate(recording, params));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(recording.samples.size()));
    state.counters["samples"] = static_cast<double>(recording.samples.size());
    setLabel(state);
}

/// runPipeline for the benchmark's argument; each call returns the last position, which the
/// benchmark keeps the compiler from dropping.
auto pipelineEstimate(const benchmark::State& state)
{
    return [variances = variancesFor(state)](const Recording& recording, const Parameters& params) {
        return runPipeline(recording, params, {}, RtsSmoother::Threads::Two, {}, variances).result.position_m.back();
    };
}

Eigen::Vector3d denseReferenceEstimate(const Recording& recording, const Parameters& params)
{
    return runDenseReference(recording, params).position_m.back();
}

void BM_Pipeline(benchmark::State& state)
{
    timeEstimates(state, thirtyMinuteWalk(), pipelineEstimate(state));
}
BENCHMARK(BM_Pipeline)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0)->Arg(0)->Arg(1)->Arg(2)->Arg(3);

/// The whole offline pipeline on real walking data.
void BM_PipelineRealWalk(benchmark::State& state)
{
    timeEstimates(state, realMinuteWalk(), pipelineEstimate(state));
}
BENCHMARK(BM_PipelineRealWalk)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0)->Arg(0)->Arg(1)->Arg(2)->Arg(3);

/// The same estimator written with dense N x N matrices (detector and alignment shared): the
/// reference for the speed ratio, on the same data and settings as BM_PipelineRealWalk.
void BM_DenseReferenceRealWalk(benchmark::State& state)
{
    timeEstimates(state, realMinuteWalk(), denseReferenceEstimate);
}
BENCHMARK(BM_DenseReferenceRealWalk)->Unit(benchmark::kMillisecond)->MinTime(1.0)->Arg(0)->Arg(1)->Arg(2);

/// Wall and process CPU time of one call, in ms.
struct RunTimes {
    double wall_ms = 0.0;
    double cpu_ms = 0.0;
};

double processCpu_ms()
{
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

template <typename Estimate>
RunTimes timeOneRun(Estimate estimate, const Recording& recording, const Parameters& params)
{
    const auto wallStart = std::chrono::steady_clock::now();
    const double cpuStart_ms = processCpu_ms();
    benchmark::DoNotOptimize(estimate(recording, params));
    return {std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wallStart).count(),
            processCpu_ms() - cpuStart_ms};
}

double median(std::vector<double> values)
{
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

/// The speed ratio itself, robust to a machine whose speed drifts (a shared VM's moved by half
/// between benchmarks a minute apart): each iteration runs the pipeline and the dense loop back to
/// back on the real walk, and the counters are medians over the iterations of each one's time and
/// of the pair's ratio. The ratio is given twice: by wall time (the pipeline's second thread
/// counts in its favour) and by the process's CPU time (the work alone).
void BM_SpeedRatioRealWalk(benchmark::State& state)
{
    const Recording& recording = realMinuteWalk();
    if (recording.samples.empty()) {
        state.SkipWithError("pyshoe-vicon/2017-11-22-11-22-03.csv is not in the shared datasets (set FOOTPATH_DATASETS)");
        return;
    }
    const Parameters params = parametersFor(state);
    const auto estimate = pipelineEstimate(state);
    std::vector<double> pipelineWall_ms, pipelineCpu_ms, denseWall_ms, wallRatio, cpuRatio;
    for (auto _ : state) {
        const RunTimes pipeline = timeOneRun(estimate, recording, params);
        const RunTimes dense = timeOneRun(denseReferenceEstimate, recording, params);
        state.SetIterationTime(1e-3 * (pipeline.wall_ms + dense.wall_ms));
        pipelineWall_ms.push_back(pipeline.wall_ms);
        pipelineCpu_ms.push_back(pipeline.cpu_ms);
        denseWall_ms.push_back(dense.wall_ms);
        wallRatio.push_back(dense.wall_ms / pipeline.wall_ms);
        cpuRatio.push_back(dense.cpu_ms / pipeline.cpu_ms);
    }
    state.counters["pipeline_ms"] = median(pipelineWall_ms);
    state.counters["pipeline_cpu_ms"] = median(pipelineCpu_ms);
    state.counters["dense_ms"] = median(denseWall_ms);
    state.counters["ratio_wall"] = median(wallRatio);
    state.counters["ratio_cpu"] = median(cpuRatio);
    state.counters["samples"] = static_cast<double>(recording.samples.size());
    setLabel(state);
}
BENCHMARK(BM_SpeedRatioRealWalk)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(21)->Arg(0)->Arg(1)->Arg(2)->Arg(3);

/// An ecg-xmu walk with a barometer (100 Hz, 2.5 minutes: stairs and an elevator), for the motion
/// classes; empty when the shared recordings are not there.
const Recording& realWalkWithPressure()
{
    static const Recording recording = [] {
        const char* fromEnv = std::getenv("FOOTPATH_DATASETS");
        const std::filesystem::path file =
            std::filesystem::path(fromEnv ? fromEnv : FOOTPATH_DATASETS_DIR) / "ecg-xmu" / "Height.txt";
        ImportOptions options;
        options.columnMap = {"time_ms", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "pressure_pa",
                             "skip",    "skip",  "skip"};
        ImportResult read = std::filesystem::exists(file) ? importRecording(file.string(), options) : ImportResult{};
        return read.ok() ? read.recording : Recording{};
    }();
    return recording;
}

/// What runPipeline does after the filter and smoother (steps, gait events, motion classes,
/// plausibility warnings), timed alone on the filter's output. Argument 0: the pyshoe-vicon
/// minute (no barometer); 1: the ecg-xmu walk with pressure.
void BM_PostProcessing(benchmark::State& state)
{
    const Recording& recording = state.range(0) == 0 ? realMinuteWalk() : realWalkWithPressure();
    if (recording.samples.empty()) {
        state.SkipWithError("the shared datasets are not there (set FOOTPATH_DATASETS)");
        return;
    }
    const Parameters params;
    Result result = runPipeline(recording, params).result;
    for (auto _ : state) {
        postProcess(recording, params, result);  // each step replaces what it wrote before
        benchmark::DoNotOptimize(result.gaitEvents.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(recording.samples.size()));
    state.counters["samples"] = static_cast<double>(recording.samples.size());
    state.SetLabel(state.range(0) == 0 ? "pyshoe-vicon walk" : "ecg-xmu walk with pressure");
}
BENCHMARK(BM_PostProcessing)->Unit(benchmark::kMicrosecond)->MinTime(1.0)->Arg(0)->Arg(1);

/// The same walk through the live estimator, pushed sample by sample as a device delivers it.
void BM_StreamingEstimator(benchmark::State& state)
{
    const Recording& recording = thirtyMinuteWalk();
    const Parameters params;
    for (auto _ : state) {
        StreamingEstimator estimator(params);
        for (const ImuSample& sample : recording.samples)
            estimator.push(sample);
        estimator.finish();
        benchmark::DoNotOptimize(estimator.result().position_m.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(recording.samples.size()));
    state.counters["samples"] = static_cast<double>(recording.samples.size());
}
BENCHMARK(BM_StreamingEstimator)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_StanceDetector(benchmark::State& state)
{
    const Recording& recording = thirtyMinuteWalk();
    const Parameters params = parametersFor(state);
    for (auto _ : state) {
        StanceFlags flags = detectStance(recording.samples, params);
        benchmark::DoNotOptimize(flags.stance.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(recording.samples.size()));
    setLabel(state);
}
BENCHMARK(BM_StanceDetector)->Unit(benchmark::kMillisecond)->Arg(0)->Arg(1);

/// One propagation: strapdown plus the structured covariance propagation.
void BM_EkfPropagate(benchmark::State& state)
{
    ErrorStateEkf ekf(Parameters(), Eigen::Matrix3d::Identity());
    const Eigen::Vector3d acc(1.0, -0.5, 9.9), gyr(0.3, 2.0, -0.1);
    for (auto _ : state) {
        ekf.propagate(acc, gyr, 0.01);
        benchmark::DoNotOptimize(ekf.covariance().data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EkfPropagate);

/// The dense triple product the structured propagation replaces, for comparison.
void BM_DenseCovariancePropagation(benchmark::State& state)
{
    ErrorStateEkf ekf(Parameters(), Eigen::Matrix3d::Identity());
    const ErrorStateEkf::Matrix15 phi = ekf.transitionMatrix(Eigen::Vector3d(1.0, -0.5, 9.9), 0.01);
    ErrorStateEkf::Matrix15 p = ErrorStateEkf::Matrix15::Identity();
    for (auto _ : state) {
        p = phi * p * phi.transpose();
        p *= 0.5;  // keeps the values finite over millions of iterations
        benchmark::DoNotOptimize(p.data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_DenseCovariancePropagation);

void BM_EkfZuptZaruUpdate(benchmark::State& state)
{
    ErrorStateEkf ekf(Parameters(), Eigen::Matrix3d::Identity());
    const Eigen::Vector3d gyr(0.001, -0.002, 0.0005);
    for (auto _ : state) {
        ekf.updateZeroVelocityAndRate(gyr);
        benchmark::DoNotOptimize(ekf.covariance().data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EkfZuptZaruUpdate);

/// A stance sample of the defaults (9 states): a propagation, then a ZUPT, as the forward pass
/// makes them (BM_EkfPropagate alone is the propagation's share, so the difference is the
/// update's). Argument 1: the update recorded for the smoother (ErrorStateEkf::setRecordUpdates),
/// as an offline run does; 0: not, as the live filter does.
void BM_EkfStanceSample(benchmark::State& state)
{
    ErrorStateEkf ekf(Parameters(), Eigen::Matrix3d::Identity());
    ekf.setRecordUpdates(state.range(0) == 1);
    const Eigen::Vector3d acc(0.05, -0.02, 9.81), gyr(0.001, -0.002, 0.0005);
    for (auto _ : state) {
        ekf.propagate(acc, gyr, 0.01);
        ekf.updateZeroVelocity();
        benchmark::DoNotOptimize(ekf.covariance().data());
    }
    state.SetItemsProcessed(state.iterations());
    state.SetLabel(state.range(0) == 1 ? "update recorded" : "not recorded");
}
BENCHMARK(BM_EkfStanceSample)->Arg(0)->Arg(1);

/// What the smoother stores of a sample with a ZUPT (the defaults): the packed covariance, the
/// attitude, the propagation and the update, into fresh records as a run writes them. With
/// BM_EkfStanceSample/1, the forward pass's work on a stance sample but recording the result.
void BM_SmootherCapture(benchmark::State& state)
{
    constexpr std::size_t kSamples = 4096;  // a new smoother each batch, so memory stays bounded
    const Parameters params;
    ErrorStateEkf ekf(params, Eigen::Matrix3d::Identity());
    for (auto _ : state) {
        RtsSmoother smoother(params, ekf);
        smoother.reserve(kSamples, kSamples);
        ekf.propagate(Eigen::Vector3d(0.1, 0.0, 9.81), Eigen::Vector3d(0.01, 0.0, 0.0), 0.01);
        ekf.updateZeroVelocity();
        for (std::size_t k = 0; k < kSamples; ++k)
            smoother.capture(ekf);
        benchmark::DoNotOptimize(&smoother);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kSamples));
}
BENCHMARK(BM_SmootherCapture);

}  // namespace

// main: BenchmarkMain.cpp
