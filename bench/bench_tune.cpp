// Self-tuning speed: the case, 200 evaluations over the 12 pyshoe-vicon trials on 2 cores
// (under a minute). Needs the shared recordings (FOOTPATH_DATASETS or ../shared/datasets); says so
// and skips without them.
#include "io/Import.h"
#include "tune/AutoTune.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>

using namespace footpath;

namespace {

std::vector<Recording> pyshoeTrials()
{
    const char* fromEnv = std::getenv("FOOTPATH_DATASETS");
    const std::filesystem::path folder = std::filesystem::path(fromEnv ? fromEnv : FOOTPATH_DATASETS_DIR) / "pyshoe-vicon";
    std::vector<Recording> recordings;
    std::error_code missing;
    for (const auto& entry : std::filesystem::directory_iterator(folder, missing))
        if (entry.path().extension() == ".csv") {
            ImportResult read = importRecording(entry.path().string(), ImportOptions());
            if (read.ok())
                recordings.push_back(std::move(read.recording));
        }
    return recordings;
}

void BM_TunePyshoeTrials(benchmark::State& state)
{
    static const std::vector<Recording> trials = pyshoeTrials();
    if (trials.empty()) {
        state.SkipWithError("the shared pyshoe-vicon recordings are not there (set FOOTPATH_DATASETS)");
        return;
    }
    std::vector<const Recording*> pointers;
    for (const Recording& trial : trials)
        pointers.push_back(&trial);
    TuneOptions options;
    options.criterion = TuneCriterion::Reference;
    options.evaluations = static_cast<int>(state.range(0));
    options.threads = 2;
    TuneOutcome outcome;
    for (auto _ : state)
        benchmark::DoNotOptimize(outcome = tuneParameters(pointers, Parameters(), options));
    state.counters["trials"] = static_cast<double>(trials.size());
    state.counters["evaluations"] = outcome.evaluations;
    state.counters["armse_before_m"] = outcome.baseScore;
    state.counters["armse_after_m"] = outcome.bestScore;
}

}  // namespace

BENCHMARK(BM_TunePyshoeTrials)->Arg(200)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

// main: BenchmarkMain.cpp
