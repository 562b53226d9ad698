// footpath-cli: runs the estimation pipeline on a recording in batch.
#include "cli/CommandLine.h"
#include "io/DelimitedTextReader.h"
#include "io/ParameterIo.h"
#include "io/ResultWriters.h"
#include "metrics/Evaluation.h"
#include "nav/Pipeline.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <sstream>

using namespace footpath;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitInternal = 1;
constexpr int kExitBadInput = 2;

/// A failure the user can fix: printed as it is, exit code 2.
struct BadInput {
    std::string message;
};

Parameters loadParameterSet(const cli::CommandLine& cmd)
{
    Parameters params;
    if (!cmd.paramsFile.empty())
        if (std::string problem = loadParameters(cmd.paramsFile, params); !problem.empty())
            throw BadInput{problem};
    for (const std::string& assignment : cmd.sets) {
        const auto eq = assignment.find('=');
        if (std::string problem = setParameter(params, assignment.substr(0, eq), assignment.substr(eq + 1));
            !problem.empty())
            throw BadInput{"--set: " + problem};
    }
    std::string problems;
    for (const std::string& problem : params.validate())
        problems += "\n  " + problem;
    if (!problems.empty())
        throw BadInput{"invalid parameters:" + problems};
    return params;
}

Recording loadRecording(const cli::CommandLine& cmd)
{
    TextReadOptions options;
    options.columnMap = cmd.columnMap;
    options.referenceColumns = cmd.referenceColumns;
    TextReadResult read = readDelimitedText(cmd.input, options);
    if (!read.ok())
        throw BadInput{read.error->text()};
    for (const std::string& warning : read.recording.warnings)
        std::cerr << "warning: " << warning << "\n";
    return std::move(read.recording);
}

Result estimate(const Recording& recording, const Parameters& params)
{
    PipelineOutput output = runPipeline(recording, params);
    if (!output.error.empty())
        throw BadInput{recording.source + ": " + output.error};
    return std::move(output.result);
}

void writeIfAsked(const std::string& path, const std::function<void(std::ostream&)>& write)
{
    if (path.empty())
        return;
    if (std::string problem = writeFileAtomically(path, write); !problem.empty())
        throw BadInput{problem};
}

int runProcess(const cli::CommandLine& cmd)
{
    const Parameters params = loadParameterSet(cmd);
    const Recording recording = loadRecording(cmd);
    const Result result = estimate(recording, params);
    writeIfAsked(cmd.trajectoryOut, [&](std::ostream& out) { writeTrajectoryCsv(out, result); });
    writeIfAsked(cmd.stepsOut, [&](std::ostream& out) { writeStepsCsv(out, result); });
    writeIfAsked(cmd.summaryOut, [&](std::ostream& out) { out << summaryToJson(result.summary); });
    const Summary& s = result.summary;
    std::printf("%s: %zu samples, %.2f s, %zu steps, path %.3f m, end-to-start %.3f m (%.2f %%), %.3f s\n",
                recording.source.c_str(), s.samples, s.duration_s, s.steps, s.pathLength_m, s.endToStart_m,
                s.endToStartPct, s.runtime_s);
    return kExitOk;
}

struct Metric {
    std::string key;
    std::string label;
    double value;
};

std::vector<Metric> computeMetrics(const cli::CommandLine& cmd, const Recording& recording, const Result& result)
{
    std::vector<Metric> metrics;
    const double pathLength = result.summary.pathLength_m;
    metrics.push_back({"path_length_m", "path length (m)", pathLength});
    if (!recording.reference.positions_m.empty()) {
        const ArmseResult armse = computeArmse(result.position_m, recording.reference.positions_m);
        metrics.push_back({"armse_2d_m", "ARMSE 2D (m)", armse.armse2d_m});
        metrics.push_back({"armse_3d_m", "ARMSE 3D (m)", armse.armse3d_m});
    }
    if (cmd.closedLoop || !recording.reference.positions_m.empty()) {
        const LoopClosure closure = computeLoopClosure(result.position_m, pathLength, cmd.length_m);
        metrics.push_back({"dbse_m", "end-to-start DBSE (m)", closure.dbse_m});
        metrics.push_back({"dbse_pct", "end-to-start DBSE (% of length)", closure.dbsePct});
    }
    if (cmd.length_m > 0.0) {
        const DistanceError distance = computeDistanceError(pathLength, cmd.length_m);
        metrics.push_back({"reference_length_m", "reference length (m)", distance.reference_m});
        metrics.push_back({"distance_error_m", "distance error (m)", distance.error_m});
        metrics.push_back({"distance_error_pct", "distance error (%)", distance.errorPct});
    }
    metrics.push_back({"steps", "steps", static_cast<double>(result.summary.steps)});
    return metrics;
}

std::string jsonString(const std::string& text)
{
    std::string out = "\"";
    for (char ch : text) {
        if (ch == '"' || ch == '\\')
            out += '\\';
        out += ch;
    }
    return out + "\"";
}

std::string describeParameters(const cli::CommandLine& cmd)
{
    std::string text = cmd.paramsFile.empty() ? "defaults" : cmd.paramsFile;
    for (const std::string& assignment : cmd.sets)
        text += " " + assignment;
    return text;
}

std::string methodSet(const Parameters& params)
{
    std::string text = params.use_zupt ? "ZUPT" : "";
    if (params.use_zaru)
        text += text.empty() ? "ZARU" : "+ZARU";
    return text.empty() ? "none" : text;
}

void printMetrics(const cli::CommandLine& cmd, const Parameters& params, const std::vector<Metric>& metrics)
{
    std::ostringstream out;
    out.precision(6);
    if (cmd.json) {
        out << "{\"recording\": " << jsonString(cmd.input) << ", \"parameters\": " << jsonString(describeParameters(cmd))
            << ", \"methods\": " << jsonString(methodSet(params));
        for (const Metric& metric : metrics)
            out << ", " << jsonString(metric.key) << ": " << (std::isfinite(metric.value) ? metric.value : 0.0);
        out << "}\n";
    } else {
        out << "recording   " << cmd.input << "\nparameters  " << describeParameters(cmd) << "\nmethods     "
            << methodSet(params) << "\n";
        for (const Metric& metric : metrics) {
            char line[128];
            std::snprintf(line, sizeof line, "%-34s %12.4f\n", metric.label.c_str(), metric.value);
            out << line;
        }
    }
    std::cout << out.str();
}

int runEval(const cli::CommandLine& cmd)
{
    const Parameters params = loadParameterSet(cmd);
    const Recording recording = loadRecording(cmd);
    const Result result = estimate(recording, params);
    printMetrics(cmd, params, computeMetrics(cmd, recording, result));
    return kExitOk;
}

int dispatch(const std::vector<std::string>& args)
{
    cli::CommandLine cmd;
    if (std::string problem = cli::parseCommandLine(args, cmd); !problem.empty())
        throw BadInput{problem + "\n\n" + cli::usageText()};
    if (cmd.command == "help") {
        std::cout << cli::usageText();
        return kExitOk;
    }
    return cmd.command == "process" ? runProcess(cmd) : runEval(cmd);
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        return dispatch(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const BadInput& bad) {
        std::cerr << "footpath-cli: " << bad.message << "\n";
        return kExitBadInput;
    } catch (const std::exception& error) {
        std::cerr << "footpath-cli: internal error: " << error.what() << "\n";
        return kExitInternal;
    }
}
