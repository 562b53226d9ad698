#include "cli/TuneCommand.h"

#include "cli/CliSupport.h"
#include "cli/EvalRun.h"
#include "io/ParameterIo.h"
#include "tune/AutoTune.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include <unistd.h>

namespace footpath::cli {

namespace {

struct TuneInputs {
    std::vector<std::string> paths;
    std::vector<Recording> recordings;
};

/// Every INPUT read with the same import options; --closed-loop and --length say what the walks
/// are, as for eval (a --length without --closed-loop makes the file's own loop flag yield).
TuneInputs readInputs(const CommandLine& cmd)
{
    TuneInputs inputs;
    const ImportOptions options = importOptionsOf(cmd);
    for (const std::string& path : expandInputs(cmd.inputs)) {
        ImportResult read = importFile(path, options);
        printImportWarnings(path, read.recording.warnings);
        Reference& reference = read.recording.reference;
        reference.closedLoop = cmd.closedLoop || (cmd.length_m <= 0.0 && reference.closedLoop);
        if (cmd.length_m > 0.0)
            reference.knownLength_m = cmd.length_m;
        inputs.paths.push_back(path);
        inputs.recordings.push_back(std::move(read.recording));
    }
    return inputs;
}

const char* criterionUnit(TuneCriterion criterion)
{
    return criterion == TuneCriterion::Reference ? "m" : "%";
}

/// The fields whose values differ, as "name: before -> after".
std::vector<std::pair<std::string, std::pair<double, double>>> changedParameters(const Parameters& before,
                                                                                  const Parameters& after)
{
    std::vector<std::pair<std::string, std::pair<double, double>>> changed;
    for (const ParameterField& field : parameterFields()) {
        const double a = parameterValue(before, field), b = parameterValue(after, field);
        if (a != b)
            changed.push_back({field.name, {a, b}});
    }
    return changed;
}

void printText(const TuneInputs& inputs, const TuneOutcome& outcome, TuneCriterion criterion, const Parameters& base,
               const std::string& presetPath)
{
    const char* unit = criterionUnit(criterion);
    std::printf("criterion   %s (%s), %d evaluations%s\n\n", tuneCriterionName(criterion), unit, outcome.evaluations,
                outcome.cancelled ? " (stopped)" : "");
    std::printf("%-32s %12s %12s\n", "file", "before", "after");
    for (std::size_t i = 0; i < inputs.paths.size(); ++i) {
        const std::string name = std::filesystem::path(inputs.paths[i]).filename().string();
        if (std::isnan(outcome.basePerRecording[i]))
            std::printf("%-32s %12s %12s\n", name.c_str(), "-", "-");
        else
            std::printf("%-32s %12.4f %12.4f\n", name.c_str(), outcome.basePerRecording[i], outcome.bestPerRecording[i]);
    }
    std::printf("%-32s %12.4f %12.4f\n\n", "mean", outcome.baseScore, outcome.bestScore);
    const auto changed = changedParameters(base, outcome.best);
    if (changed.empty())
        std::printf("no setting beat the starting parameters; the preset holds them unchanged\n");
    for (const auto& [name, values] : changed)
        std::printf("%-24s %.6g -> %.6g\n", name.c_str(), values.first, values.second);
    for (const std::string& caution : outcome.cautions)
        std::printf("caution     %s: the tuned parameters change the strides, not only the figure\n", caution.c_str());
    std::printf("saved       %s\n", presetPath.c_str());
}

void printJson(const TuneInputs& inputs, const TuneOutcome& outcome, TuneCriterion criterion, const Parameters& base,
               const std::string& presetPath)
{
    QJsonArray rows;
    for (std::size_t i = 0; i < inputs.paths.size(); ++i) {
        QJsonObject row{{"recording", QString::fromStdString(inputs.paths[i])}};
        if (!std::isnan(outcome.basePerRecording[i])) {
            row["before"] = outcome.basePerRecording[i];
            row["after"] = outcome.bestPerRecording[i];
        }
        rows.append(row);
    }
    QJsonArray cautions;
    for (const std::string& caution : outcome.cautions)
        cautions.append(QString::fromStdString(caution));
    QJsonObject changed;
    for (const auto& [name, values] : changedParameters(base, outcome.best))
        changed[QString::fromStdString(name)] = QJsonArray{values.first, values.second};
    const QJsonObject json{{"criterion", tuneCriterionName(criterion)},
                           {"unit", criterionUnit(criterion)},
                           {"evaluations", outcome.evaluations},
                           {"before", outcome.baseScore},
                           {"after", outcome.bestScore},
                           {"recordings", rows},
                           {"changed", changed},
                           {"cautions", cautions},
                           {"preset", QString::fromStdString(presetPath)}};
    std::cout << QJsonDocument(json).toJson().toStdString();
}

}  // namespace

int runTune(const CommandLine& cmd)
{
    const TuneCriterion criterion = *parseTuneCriterion(cmd.criterion);  // checked by the parser
    const Parameters base = loadParameterSet(cmd);
    const TuneInputs inputs = readInputs(cmd);
    std::vector<const Recording*> recordings;
    for (const Recording& recording : inputs.recordings)
        recordings.push_back(&recording);

    TuneOptions options;
    options.criterion = criterion;
    options.evaluations = cmd.evaluations;
    options.threads = cmd.jobs;
    options.seed = static_cast<std::uint32_t>(cmd.seed);
    // A progress line for a person at a terminal, not for a log.
    const bool terminal = isatty(fileno(stderr));
    const TuneOutcome outcome = tuneParameters(recordings, base, options, [terminal](const TuneProgress& progress) {
        if (!terminal)
            return;
        std::fprintf(stderr, "\rtune: %d of %d evaluations, best %.4f", progress.evaluations, progress.budget,
                     progress.bestScore);
        std::fflush(stderr);
    });
    if (terminal)
        std::fprintf(stderr, "\n");
    if (!outcome.error.empty())
        throw BadInput{outcome.error};
    if (std::string problem = saveParameters(cmd.outFile, outcome.best); !problem.empty())
        throw BadInput{problem};
    if (cmd.json)
        printJson(inputs, outcome, criterion, base, cmd.outFile);
    else
        printText(inputs, outcome, criterion, base, cmd.outFile);
    return 0;
}

}  // namespace footpath::cli
