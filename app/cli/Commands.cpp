#include "cli/Commands.h"

#include "cli/CliSupport.h"
#include "io/ResultWriters.h"
#include "metrics/Evaluation.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace footpath::cli {

namespace {

struct Metric {
    std::string key;
    std::string label;
    double value;
};

/// The reference to evaluate against: the command line's, else what the recording carries.
struct EvaluationReference {
    bool closedLoop = false;
    double length_m = 0.0;
};

EvaluationReference referenceFor(const CommandLine& cmd, const Recording& recording)
{
    EvaluationReference reference;
    reference.closedLoop = cmd.closedLoop || (!cmd.closedLoop && cmd.length_m <= 0.0 && recording.reference.closedLoop);
    reference.length_m = cmd.length_m > 0.0 ? cmd.length_m : recording.reference.knownLength_m;
    return reference;
}

std::vector<Metric> computeMetrics(const Recording& recording, const Result& result, const EvaluationReference& ref)
{
    std::vector<Metric> metrics;
    const double pathLength = result.summary.pathLength_m;
    metrics.push_back({"path_length_m", "path length (m)", pathLength});
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
    if (!recording.reference.swings.empty()) {
        const Reference& r = recording.reference;
        const StanceScore stance = scoreStanceDetection(result.flags.stance, r.swings,
                                                        r.hasTrialBoundaries ? &r.trialBoundaries : nullptr);
        metrics.push_back({"stance_precision", "stance precision", stance.precision});
        metrics.push_back({"stance_recall", "stance recall", stance.recall});
        metrics.push_back({"stance_f1", "stance F1", stance.f1});
        metrics.push_back({"stance_phase_count_error", "stance phases detected - labelled",
                           static_cast<double>(stance.stepCountError)});
    }
    metrics.push_back({"steps", "steps", static_cast<double>(result.summary.steps)});
    return metrics;
}

void printMetrics(const CommandLine& cmd, const Parameters& params, const Recording& recording,
                  const std::vector<Metric>& metrics)
{
    if (cmd.json) {
        QJsonObject root{{"recording", QString::fromStdString(cmd.input)},
                         {"parameters", QString::fromStdString(describeParameters(cmd))},
                         {"methods", QString::fromStdString(methodSet(params))}};
        for (const Metric& metric : metrics)
            root.insert(QString::fromStdString(metric.key), std::isfinite(metric.value) ? QJsonValue(metric.value)
                                                                                        : QJsonValue());
        std::cout << QJsonDocument(root).toJson(QJsonDocument::Compact).toStdString() << "\n";
        return;
    }
    std::cout << "recording   " << cmd.input << "\nparameters  " << describeParameters(cmd) << "\nmethods     "
              << methodSet(params) << "\n";
    for (const std::string& note : recording.reference.notes)
        std::cout << "reference   " << note << "\n";
    for (const Metric& metric : metrics) {
        char line[128];
        std::snprintf(line, sizeof line, "%-34s %12.4f\n", metric.label.c_str(), metric.value);
        std::cout << line;
    }
}

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
        std::printf("warning     %s\n", warning.c_str());
}

}  // namespace

int runProcess(const CommandLine& cmd)
{
    const Parameters params = loadParameterSet(cmd);
    const ImportResult read = importInput(cmd);
    const Result result = estimate(read.recording, params);
    writeIfAsked(cmd.trajectoryOut, [&](std::ostream& out) { writeTrajectoryCsv(out, result); });
    writeIfAsked(cmd.stepsOut, [&](std::ostream& out) { writeStepsCsv(out, result); });
    writeIfAsked(cmd.summaryOut, [&](std::ostream& out) { out << summaryToJson(result.summary); });
    writeIfAsked(cmd.summaryCsvOut, [&](std::ostream& out) { writeSummaryCsv(out, result.summary); });
    writeIfAsked(cmd.parametersCsvOut, [&](std::ostream& out) { writeParametersCsv(out, params); });
    const Summary& s = result.summary;
    std::printf("%s: %zu samples, %.2f s, %zu steps, path %.3f m, end-to-start %.3f m (%.2f %%), %.3f s\n",
                cmd.input.c_str(), s.samples, s.duration_s, s.steps, s.pathLength_m, s.endToStart_m, s.endToStartPct,
                s.runtime_s);
    return 0;
}

int runEval(const CommandLine& cmd)
{
    const Parameters params = loadParameterSet(cmd);
    const ImportResult read = importInput(cmd);
    const Result result = estimate(read.recording, params);
    const EvaluationReference reference = referenceFor(cmd, read.recording);
    printMetrics(cmd, params, read.recording, computeMetrics(read.recording, result, reference));
    return 0;
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
