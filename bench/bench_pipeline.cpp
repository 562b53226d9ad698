// Speed of the estimation pipeline (stance detector + EKF, defaults and the paper's configuration) on a 30-minute
// simulated walk at 100 Hz, offline and live. Target (foundation issue): at least 2 million samples
// per second.
#include "detect/StanceDetector.h"
#include "nav/ErrorStateEkf.h"
#include "nav/Pipeline.h"
#include "nav/StreamingEstimator.h"
#include "sim/WalkSimulator.h"

#include <benchmark/benchmark.h>

using namespace footpath;

namespace {

/// Laps of a 40 x 25 m rectangle until the walk lasts 30 minutes, with MTi-class sensor errors.
const Recording& thirtyMinuteWalk()
{
    static const Recording recording = [] {
        WalkSimulatorConfig config;
        config.accNoiseStd_mps2 = 0.01;
        config.gyrNoiseStd_radps = 0.0015;
        config.accBias_mps2 = Eigen::Vector3d(0.0075, -0.005, 0.01);
        config.gyrBias_radps = Eigen::Vector3d(0.0016, -0.0012, 0.002);
        std::vector<Eigen::Vector3d> path{Eigen::Vector3d::Zero()};
        const std::vector<Eigen::Vector3d> lap = closedRectanglePath(40.0, 25.0);
        for (int i = 0; i < 20; ++i)  // about 93 s per lap
            path.insert(path.end(), lap.begin() + 1, lap.end());
        SimulatedWalk walk = simulateWalk(path, config);
        walk.recording.samples.resize(std::min<std::size_t>(walk.recording.samples.size(), 30 * 60 * 100));
        return walk.recording;
    }();
    return recording;
}

/// Argument 0: the defaults (adaptive SHOE detector, 9-state filter); 1: Guo 2015 as printed
/// (C1/C2/C3, 15 states, ZUPT+ZARU).
Parameters parametersFor(const benchmark::State& state)
{
    return state.range(0) == 0 ? Parameters() : guo2015Parameters();
}

void BM_Pipeline(benchmark::State& state)
{
    const Recording& recording = thirtyMinuteWalk();
    const Parameters params = parametersFor(state);
    for (auto _ : state) {
        PipelineOutput output = runPipeline(recording, params);
        benchmark::DoNotOptimize(output.result.position_m.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(recording.samples.size()));
    state.counters["samples"] = static_cast<double>(recording.samples.size());
}
BENCHMARK(BM_Pipeline)->Unit(benchmark::kMillisecond)->MinTime(2.0)->Arg(0)->Arg(1);

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

}  // namespace

BENCHMARK_MAIN();
