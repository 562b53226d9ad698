#include "cli/Commands.h"

#include "cli/CliSupport.h"
#include "cli/EvalOutput.h"
#include "cli/EvalRun.h"
#include "io/ResultWriters.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QThread>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace footpath::cli {

namespace {

QJsonArray toJsonArray(const std::vector<std::string>& items)
{
    QJsonArray array;
    for (const std::string& item : items)
        array.append(QString::fromStdString(item));
    return array;
}

std::string joined(const std::vector<std::string>& items, const char* separator = ", ")
{
    std::string text;
    for (const std::string& item : items)
        text += (text.empty() ? "" : separator) + item;
    return text;
}

QJsonObject infoJson(const ImportResult& read)
{
    const RecordingInfo& info = read.info;
    const Recording& recording = read.recording;
    const GapReport& gaps = info.gaps;
    QJsonObject reference{{"positions", !recording.reference.positions_m.empty()},
                          {"gait_event_swings", static_cast<qint64>(recording.reference.swings.size())},
                          {"closed_loop", recording.reference.closedLoop},
                          {"known_length_m", recording.reference.knownLength_m},
                          {"notes", toJsonArray(recording.reference.notes)}};
    return QJsonObject{
        {"file", QString::fromStdString(recording.source)},
        {"format", QString::fromStdString(info.format)},
        {"samples", static_cast<qint64>(recording.samples.size())},
        {"rate_hz", info.rate_hz},
        {"duration_s", recording.duration_s()},
        {"channels", toJsonArray(info.channels)},
        {"units", QJsonObject{{"acc", unitName(info.accUnitAsRead)},
                              {"gyr", unitName(info.gyrUnitAsRead)},
                              {"time", unitName(info.timeUnitAsRead)}}},
        {"time_source", QString::fromStdString(info.timeSource)},
        {"gaps", QJsonObject{{"count", static_cast<qint64>(gaps.count)},
                             {"missing_samples", static_cast<qint64>(gaps.missingSamples)},
                             {"longest_s", gaps.longest_s},
                             {"longest_at_s", gaps.longestAt_s}}},
        {"truncated", info.truncated},
        {"reference", reference},
        {"warnings", toJsonArray(recording.warnings)},
    };
}

void printInfoTable(const ImportResult& read)
{
    const RecordingInfo& info = read.info;
    const Recording& recording = read.recording;
    std::printf("file        %s\nformat      %s\nsamples     %zu\nrate        %.6g Hz\nduration    %.3f s\n",
                recording.source.c_str(), info.format.c_str(), recording.samples.size(), info.rate_hz,
                recording.duration_s());
    std::printf("time        %s\nchannels    %s\nunits       acc %s, gyr %s (as read; converted to SI)\n",
                info.timeSource.c_str(), joined(info.channels).c_str(), unitName(info.accUnitAsRead),
                unitName(info.gyrUnitAsRead));
    std::printf("gaps        %zu (about %zu samples lost), longest %.4g s at t = %.4g s\n", info.gaps.count,
                info.gaps.missingSamples, info.gaps.longest_s, info.gaps.longestAt_s);
    if (info.truncated)
        std::printf("truncated   yes: the samples before the damage were kept\n");
    for (const std::string& note : recording.reference.notes)
        std::printf("reference   %s\n", note.c_str());
    for (const std::string& warning : recording.warnings)
        std::printf("warning     %s\n", withFlagHints(warning).c_str());
}

EvalSetup evalSetupOf(const CommandLine& cmd)
{
    EvalSetup setup;
    setup.params = loadParameterSet(cmd);
    setup.import = importOptionsOf(cmd);
    setup.closedLoop = cmd.closedLoop;
    setup.length_m = cmd.length_m;
    return setup;
}

/// On stderr, file by file in input order, whatever order the threads finished in.
void printEvalWarnings(const std::vector<RecordingEvaluation>& evaluations)
{
    for (const RecordingEvaluation& evaluation : evaluations) {
        printImportWarnings(evaluation.path, evaluation.importWarnings);
        printPlausibilityWarnings(evaluation.path, evaluation.warnings);
    }
}

/// 0 when every file was evaluated; else BadInput naming the files that were not (exit code 2).
int reportFailures(const std::vector<RecordingEvaluation>& evaluations)
{
    std::vector<std::string> failed;
    for (const RecordingEvaluation& evaluation : evaluations)
        if (!evaluation.ok())
            failed.push_back(evaluation.path);
    if (failed.empty())
        return 0;
    throw BadInput{std::to_string(failed.size()) + " of " + std::to_string(evaluations.size())
                   + " recordings could not be evaluated: " + joined(failed)};
}

}  // namespace

int runProcess(const CommandLine& cmd)
{
    const Parameters params = loadParameterSet(cmd);
    const ImportResult read = importInput(cmd);
    const Result result = estimate(read.recording, params);
    writeIfAsked(cmd.trajectoryOut, [&](std::ostream& out) { writeTrajectoryCsv(out, result); });
    writeIfAsked(cmd.stepsOut, [&](std::ostream& out) { writeStepsCsv(out, result); });
    printPlausibilityWarnings(cmd.input, result.warnings);
    writeIfAsked(cmd.summaryOut, [&](std::ostream& out) {
        out << summaryToJson(result);
    });
    writeIfAsked(cmd.summaryCsvOut, [&](std::ostream& out) { writeSummaryCsv(out, result); });
    writeIfAsked(cmd.parametersCsvOut, [&](std::ostream& out) { writeParametersCsv(out, params); });
    const Summary& s = result.summary;
    std::printf("%s: %zu samples, %.2f s, %zu steps, path %.3f m, end-to-start %.3f m (%.2f %%), %.3f s\n",
                cmd.input.c_str(), s.samples, s.duration_s, s.steps, s.pathLength_m, s.endToStart_m, s.endToStartPct,
                s.runtime_s);
    return 0;
}

int runEval(const CommandLine& cmd)
{
    const EvalSetup setup = evalSetupOf(cmd);
    const std::vector<std::string> paths = expandInputs(cmd.inputs);
    const int jobs = cmd.jobs > 0 ? cmd.jobs : QThread::idealThreadCount();
    const std::vector<RecordingEvaluation> evaluations = evaluateAll(setup, paths, jobs);
    printEvalWarnings(evaluations);
    const bool single = cmd.inputs.size() == 1 && !isFolder(cmd.inputs.front());
    if (single && !evaluations.front().ok())
        throw BadInput{evaluations.front().error};  // as before: the message alone, nothing on stdout
    if (single)
        printSingleEvaluation(cmd, setup.params, evaluations.front());
    else
        printBatchEvaluation(cmd, setup.params, evaluations);
    if (std::any_of(evaluations.begin(), evaluations.end(), [](const RecordingEvaluation& e) { return e.ok(); }))
        saveImportPresetIfAsked(cmd, setup.import);
    std::cout.flush();
    return reportFailures(evaluations);
}

int runInfo(const CommandLine& cmd)
{
    const ImportResult read = importInput(cmd, false);  // the table lists the warnings itself
    if (cmd.json)
        std::cout << QJsonDocument(infoJson(read)).toJson(QJsonDocument::Indented).toStdString();
    else
        printInfoTable(read);
    return 0;
}

}  // namespace footpath::cli
