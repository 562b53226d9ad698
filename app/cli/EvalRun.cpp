#include "cli/EvalRun.h"

#include "cli/CliSupport.h"
#include "metrics/Evaluation.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>
#include <stdexcept>
#include <thread>

namespace footpath::cli {

namespace {

namespace fs = std::filesystem;

/// The reference to evaluate against: the command line's, else what the recording carries.
struct EvaluationReference {
    bool closedLoop = false;
    double length_m = 0.0;
};

EvaluationReference referenceFor(const EvalSetup& setup, const Recording& recording)
{
    EvaluationReference reference;
    // A --length without --closed-loop says what the walk is, so the file's own loop flag yields.
    reference.closedLoop = setup.closedLoop || (setup.length_m <= 0.0 && recording.reference.closedLoop);
    reference.length_m = setup.length_m > 0.0 ? setup.length_m : recording.reference.knownLength_m;
    return reference;
}

void addTrajectoryMetrics(std::vector<Metric>& metrics, const Recording& recording, const Result& result,
                          const EvaluationReference& ref)
{
    const double pathLength = result.summary.pathLength_m;
    if (!recording.reference.positions_m.empty()) {
        const ArmseResult armse = computeArmse(result.position_m, recording.reference.positions_m);
        metrics.push_back({"armse_2d_m", "ARMSE 2D (m)", armse.armse2d_m});
        metrics.push_back({"armse_3d_m", "ARMSE 3D (m)", armse.armse3d_m});
    }
    if (ref.closedLoop) {
        const LoopClosure closure = computeLoopClosure(result.position_m, pathLength, ref.length_m);
        metrics.push_back({"dbse_m", "end-to-start DBSE (m)", closure.dbse_m});
        metrics.push_back({"dbse_pct", "end-to-start DBSE (% of length)", closure.dbsePct});
    }
    if (ref.length_m > 0.0) {
        const DistanceError distance = computeDistanceError(pathLength, ref.length_m);
        metrics.push_back({"reference_length_m", "reference length (m)", distance.reference_m});
        metrics.push_back({"distance_error_m", "distance error (m)", distance.error_m});
        metrics.push_back({"distance_error_pct", "distance error (%)", distance.errorPct});
    }
}

void addStanceMetrics(std::vector<Metric>& metrics, const Recording& recording, const Result& result)
{
    const Reference& r = recording.reference;
    if (r.swings.empty())
        return;
    const SampleRange* trial = r.hasTrialBoundaries ? &r.trialBoundaries : nullptr;
    // The gait events' stance (heel strike to toe off) is what a gait lab labels; the ZUPT flag
    // marks only the part of it where the foot is at rest, so its recall is low by design.
    const StanceScore gaitStance = scoreStanceDetection(result.gaitStance, r.swings, trial);
    metrics.push_back({"gait_stance_precision", "gait stance precision", gaitStance.precision});
    metrics.push_back({"gait_stance_recall", "gait stance recall", gaitStance.recall});
    metrics.push_back({"gait_stance_f1", "gait stance F1", gaitStance.f1});
    const StrideCount strides = countStrides(result, r.swings, trial);
    metrics.push_back({"stride_count_error", "strides - labelled swings",
                       static_cast<double>(strides.error), true});
    const StanceScore stance = scoreStanceDetection(result.flags.stance, r.swings, trial);
    metrics.push_back({"stance_precision", "at rest (ZUPT) precision", stance.precision});
    metrics.push_back({"stance_recall", "at rest (ZUPT) recall", stance.recall});
    metrics.push_back({"stance_f1", "at rest (ZUPT) F1", stance.f1});
    const GaitEventTiming timing = scoreGaitEventTiming(result, r);
    metrics.push_back({"heel_strike_error_ms", "heel strike error (ms, median)",
                       1000.0 * timing.heelStrike.medianError_s});
    metrics.push_back({"toe_off_error_ms", "toe off error (ms, median)", 1000.0 * timing.toeOff.medianError_s});
}

/// Every metric the recording's reference allows, in the order of the single-file table.
std::vector<Metric> computeMetrics(const Recording& recording, const Result& result, const EvaluationReference& ref)
{
    std::vector<Metric> metrics{{"path_length_m", "path length (m)", result.summary.pathLength_m}};
    addTrajectoryMetrics(metrics, recording, result, ref);
    addStanceMetrics(metrics, recording, result);
    metrics.push_back({"steps", "steps", static_cast<double>(result.summary.steps), true});
    return metrics;
}

/// Fills evaluation step by step, so the import warnings survive an estimation that fails.
void measure(const EvalSetup& setup, RecordingEvaluation& evaluation)
{
    const ImportResult read = importFile(evaluation.path, setup.import);
    const Recording& recording = read.recording;
    evaluation.importWarnings = recording.warnings;
    evaluation.referenceNotes = recording.reference.notes;
    Result result = estimate(recording, setup.params);
    evaluation.metrics = computeMetrics(recording, result, referenceFor(setup, recording));
    evaluation.metrics.push_back(
        {"warning_count", "plausibility warnings", static_cast<double>(result.warnings.size()), true});
    evaluation.warnings = std::move(result.warnings);
}

/// One file's evaluation; a bad file is an error entry, a bug is kept in internalError for the
/// caller to rethrow once every thread has stopped.
RecordingEvaluation evaluateRecording(const EvalSetup& setup, const std::string& path, std::string& internalError)
{
    RecordingEvaluation evaluation;
    evaluation.path = path;
    try {
        measure(setup, evaluation);
    } catch (const BadInput& bad) {
        evaluation.error = bad.message;
    } catch (const std::exception& error) {
        internalError = path + ": " + error.what();
    }
    return evaluation;
}

std::string lowercase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return text;
}

/// Metadata beside the recordings: sidecars and gait-event files are read with their recording by
/// the importer, and documents or pictures are not recordings at all.
bool isRecordingFile(const fs::directory_entry& entry)
{
    const std::string name = entry.path().filename().string();
    const std::string extension = lowercase(entry.path().extension().string());
    std::error_code unreadable;  // a dangling link is no recording either
    return entry.is_regular_file(unreadable) && name.front() != '.' && extension != ".json" && extension != ".md"
           && extension != ".pdf" && extension != ".png";
}

std::vector<std::string> recordingsIn(const std::string& folder)
{
    std::error_code error;
    std::vector<fs::path> files;
    for (fs::directory_iterator it(folder, error); !error && it != fs::directory_iterator(); it.increment(error))
        if (isRecordingFile(*it))
            files.push_back(it->path());
    if (error)
        throw BadInput{folder + ": cannot list the folder: " + error.message()};
    // Byte order of the names, not the locale's collation, so every machine lists them alike.
    std::sort(files.begin(), files.end(),
              [](const fs::path& a, const fs::path& b) { return a.filename().string() < b.filename().string(); });
    std::vector<std::string> paths;
    for (const fs::path& file : files)
        paths.push_back(file.string());
    return paths;
}

/// Joins the threads however the scope is left, so a failed thread start cannot abort the process.
struct JoinOnExit {
    std::vector<std::thread>& threads;
    ~JoinOnExit()
    {
        for (std::thread& thread : threads)
            if (thread.joinable())
                thread.join();
    }
};

}  // namespace

const Metric* RecordingEvaluation::find(const std::string& key) const
{
    const auto found = std::find_if(metrics.begin(), metrics.end(), [&](const Metric& m) { return m.key == key; });
    return found == metrics.end() ? nullptr : &*found;
}

bool isFolder(const std::string& path)
{
    std::error_code ignored;
    return fs::is_directory(path, ignored);
}

std::vector<std::string> expandInputs(const std::vector<std::string>& inputs)
{
    for (const std::string& input : inputs) {
        std::error_code ignored;
        if (!fs::exists(input, ignored))
            throw BadInput{input + ": no such file or folder"};
    }
    std::vector<std::string> paths;
    for (const std::string& input : inputs) {
        const std::vector<std::string> files = isFolder(input) ? recordingsIn(input) : std::vector{input};
        paths.insert(paths.end(), files.begin(), files.end());
    }
    if (paths.empty())
        throw BadInput{inputs.front() + (inputs.size() > 1 ? " and the other folders hold" : " holds")
                       + " no recording"};
    return paths;
}

std::vector<RecordingEvaluation> evaluateAll(const EvalSetup& setup, const std::vector<std::string>& paths, int jobs)
{
    std::vector<RecordingEvaluation> evaluations(paths.size());
    std::vector<std::string> internalErrors(paths.size());
    std::atomic<std::size_t> next{0};
    // Each thread takes the next file not yet taken, so a long recording does not hold up others.
    const auto work = [&] {
        for (std::size_t i = next++; i < paths.size(); i = next++)
            evaluations[i] = evaluateRecording(setup, paths[i], internalErrors[i]);
    };
    {
        std::vector<std::thread> helpers;
        const JoinOnExit joinHelpers{helpers};
        const std::size_t threads = std::min(paths.size(), static_cast<std::size_t>(std::max(jobs, 1)));
        for (std::size_t t = 1; t < threads; ++t)
            helpers.emplace_back(work);
        work();  // this thread takes its share too
    }
    for (const std::string& error : internalErrors)
        if (!error.empty())
            throw std::runtime_error(error);
    return evaluations;
}

}  // namespace footpath::cli
