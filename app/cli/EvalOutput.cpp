#include "cli/EvalOutput.h"

#include "cli/CliSupport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

namespace footpath::cli {

namespace {

/// Which end of a metric's range is bad: errors grow, detection scores shrink.
enum class Worst { Largest, Smallest, FarthestFromZero };

/// A metric as a column of the batch table and, when it has a group, a line of the summary.
struct Column {
    const char* key;
    const char* header;  ///< short, for the table
    const char* label;   ///< as in the single-file table, for the summary
    int decimals;
    const char* group;   ///< kind of reference it needs; nullptr: not summarised
    Worst worst;
};

const std::vector<Column>& columns()
{
    static const std::vector<Column> list = {
        {"armse_2d_m", "ARMSE2D m", "ARMSE 2D (m)", 3, "positions", Worst::Largest},
        {"armse_3d_m", "ARMSE3D m", "ARMSE 3D (m)", 3, "positions", Worst::Largest},
        {"dbse_m", "DBSE m", "end-to-start DBSE (m)", 3, "closed loop", Worst::Largest},
        {"dbse_pct", "DBSE %", "end-to-start DBSE (% of length)", 2, "closed loop", Worst::Largest},
        {"distance_error_pct", "dist err %", "distance error (%)", 2, "known length", Worst::Largest},
        {"gait_stance_precision", "gait P", "gait stance precision", 3, "gait events", Worst::Smallest},
        {"gait_stance_recall", "gait R", "gait stance recall", 3, "gait events", Worst::Smallest},
        {"gait_stance_f1", "gait F1", "gait stance F1", 3, "gait events", Worst::Smallest},
        {"stride_count_error", "strides +-", "strides - labelled swings", 0, "gait events", Worst::FarthestFromZero},
        {"stance_precision", "rest P", "at rest (ZUPT) precision", 3, "gait events", Worst::Smallest},
        {"stance_recall", "rest R", "at rest (ZUPT) recall", 3, "gait events", Worst::Smallest},
        {"stance_f1", "rest F1", "at rest (ZUPT) F1", 3, "gait events", Worst::Smallest},
        {"heel_strike_error_ms", "HS ms", "heel strike error (ms, median)", 1, "gait events", Worst::Largest},
        {"toe_off_error_ms", "TO ms", "toe off error (ms, median)", 1, "gait events", Worst::Largest},
        {"steps", "steps", "steps", 0, nullptr, Worst::Largest},
        {"warning_count", "warnings", "plausibility warnings", 0, "plausibility checks", Worst::Largest},
    };
    return list;
}

const std::vector<const char*>& summaryGroups()
{
    static const std::vector<const char*> groups = {"positions", "closed loop", "known length", "gait events",
                                                    "plausibility checks"};
    return groups;
}

struct Statistics {
    double mean = 0.0;
    double median = 0.0;
    double worst = 0.0;
    std::size_t count = 0;
};

/// Over the files that have the metric; a non-finite value (nothing to divide by) is left out.
Statistics statisticsOf(const std::vector<RecordingEvaluation>& evaluations, const Column& column)
{
    std::vector<double> values;
    for (const RecordingEvaluation& evaluation : evaluations)
        if (const Metric* metric = evaluation.find(column.key); metric && std::isfinite(metric->value))
            values.push_back(metric->value);
    Statistics stats;
    stats.count = values.size();
    if (values.empty())
        return stats;
    std::sort(values.begin(), values.end());
    const std::size_t half = values.size() / 2;
    stats.median = values.size() % 2 ? values[half] : (values[half - 1] + values[half]) / 2.0;
    for (double value : values)
        stats.mean += value / static_cast<double>(values.size());
    if (column.worst == Worst::FarthestFromZero)
        stats.worst = std::abs(values.back()) >= std::abs(values.front()) ? values.back() : values.front();
    else
        stats.worst = column.worst == Worst::Largest ? values.back() : values.front();
    return stats;
}

QJsonObject recordingJson(const CommandLine& cmd, const Parameters& params, const RecordingEvaluation& evaluation)
{
    QJsonObject object{{"recording", QString::fromStdString(evaluation.path)},
                       {"parameters", QString::fromStdString(describeParameters(cmd))},
                       {"methods", QString::fromStdString(methodSet(params))}};
    if (!evaluation.ok()) {
        object.insert("error", QString::fromStdString(evaluation.error));
        return object;
    }
    for (const Metric& metric : evaluation.metrics)
        object.insert(QString::fromStdString(metric.key),
                      metric.isCount ? QJsonValue(static_cast<qint64>(metric.value)) : jsonNumber(metric.value));
    object.insert("warnings", warningsJson(evaluation.warnings));
    return object;
}

QJsonObject summaryJson(const std::vector<RecordingEvaluation>& evaluations)
{
    QJsonObject summary;
    for (const Column& column : columns()) {
        if (!column.group)
            continue;
        const Statistics stats = statisticsOf(evaluations, column);
        const bool any = stats.count > 0;
        summary.insert(QString::fromLatin1(column.key),
                       QJsonObject{{"mean", any ? jsonNumber(stats.mean) : QJsonValue()},
                                   {"median", any ? jsonNumber(stats.median) : QJsonValue()},
                                   {"worst", any ? jsonNumber(stats.worst) : QJsonValue()},
                                   {"count", static_cast<qint64>(stats.count)}});
    }
    return summary;
}

void printBatchJson(const CommandLine& cmd, const Parameters& params,
                    const std::vector<RecordingEvaluation>& evaluations)
{
    QJsonArray recordings;
    for (const RecordingEvaluation& evaluation : evaluations)
        recordings.append(recordingJson(cmd, params, evaluation));
    const QJsonObject root{{"parameters", QString::fromStdString(describeParameters(cmd))},
                           {"methods", QString::fromStdString(methodSet(params))},
                           {"recordings", recordings},
                           {"summary", summaryJson(evaluations)}};
    std::cout << QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString();
}

/// The file names, or the paths where two files of the batch share a name.
std::vector<std::string> displayNames(const std::vector<RecordingEvaluation>& evaluations)
{
    std::map<std::string, int> uses;
    std::vector<std::string> names;
    for (const RecordingEvaluation& evaluation : evaluations)
        names.push_back(std::filesystem::path(evaluation.path).filename().string());
    for (const std::string& name : names)
        ++uses[name];
    for (std::size_t i = 0; i < names.size(); ++i)
        if (uses[names[i]] > 1)
            names[i] = evaluations[i].path;
    return names;
}

/// The columns at least one evaluated file has a value for.
std::vector<Column> columnsPresent(const std::vector<RecordingEvaluation>& evaluations)
{
    std::vector<Column> present;
    for (const Column& column : columns())
        if (std::any_of(evaluations.begin(), evaluations.end(),
                        [&](const RecordingEvaluation& e) { return e.find(column.key) != nullptr; }))
            present.push_back(column);
    return present;
}

int widthOf(const Column& column)
{
    return std::max(static_cast<int>(std::strlen(column.header)), 9);
}

void printTableHeader(const std::vector<Column>& shown, int nameWidth)
{
    std::printf("%-*s", nameWidth, "file");
    for (const Column& column : shown)
        std::printf("  %*s", widthOf(column), column.header);
    std::printf("\n");
}

void printRow(const RecordingEvaluation& evaluation, const std::string& name, const std::vector<Column>& shown,
              int nameWidth)
{
    std::printf("%-*s", nameWidth, name.c_str());
    if (!evaluation.ok()) {
        std::printf("  error: %s\n", evaluation.error.c_str());
        return;
    }
    for (const Column& column : shown) {
        if (const Metric* metric = evaluation.find(column.key))
            std::printf("  %*.*f", widthOf(column), column.decimals, metric->value);
        else
            std::printf("  %*s", widthOf(column), "-");
    }
    std::printf("\n");
}

void printTable(const std::vector<RecordingEvaluation>& evaluations)
{
    const std::vector<std::string> names = displayNames(evaluations);
    int nameWidth = 4;  // "file"
    for (const std::string& name : names)
        nameWidth = std::max(nameWidth, static_cast<int>(name.size()));
    const std::vector<Column> shown = columnsPresent(evaluations);
    printTableHeader(shown, nameWidth);
    for (std::size_t i = 0; i < evaluations.size(); ++i)
        printRow(evaluations[i], names[i], shown, nameWidth);
}

void printSummaryGroup(const std::vector<RecordingEvaluation>& evaluations, const char* group)
{
    bool headed = false;
    for (const Column& column : columns()) {
        if (!column.group || std::strcmp(column.group, group) != 0)
            continue;
        const Statistics stats = statisticsOf(evaluations, column);
        if (stats.count == 0)
            continue;
        if (!headed)
            std::printf("%s\n", group);
        headed = true;
        std::printf("  %-34s %10.4f %10.4f %10.4f %6zu\n", column.label, stats.mean, stats.median, stats.worst,
                    stats.count);
    }
}

void printCounts(const std::vector<RecordingEvaluation>& evaluations)
{
    const auto failed = std::count_if(evaluations.begin(), evaluations.end(),
                                      [](const RecordingEvaluation& e) { return !e.ok(); });
    const auto warned = std::count_if(evaluations.begin(), evaluations.end(),
                                      [](const RecordingEvaluation& e) { return !e.warnings.empty(); });
    std::printf("%zu recordings: %zu evaluated, %zu failed, %zu with plausibility warnings\n", evaluations.size(),
                evaluations.size() - static_cast<std::size_t>(failed), static_cast<std::size_t>(failed),
                static_cast<std::size_t>(warned));
}

void printBatchText(const CommandLine& cmd, const Parameters& params,
                    const std::vector<RecordingEvaluation>& evaluations)
{
    std::printf("parameters  %s\nmethods     %s\n\n", describeParameters(cmd).c_str(), methodSet(params).c_str());
    printTable(evaluations);
    std::printf("\n%-36s %10s %10s %10s %6s\n", "summary", "mean", "median", "worst", "count");
    for (const char* group : summaryGroups())
        printSummaryGroup(evaluations, group);
    std::printf("worst: the largest error or warning count, the smallest precision, recall or F1\n");
    printCounts(evaluations);
}

}  // namespace

QJsonValue jsonNumber(double value)
{
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue();  // JSON has no NaN
}

QJsonArray warningsJson(const std::vector<PlausibilityWarning>& warnings)
{
    QJsonArray array;
    for (const PlausibilityWarning& warning : warnings)
        array.append(QJsonObject{{"kind", QString::fromLatin1(warningKindName(warning.kind))},
                                 {"start_s", warning.start_s},
                                 {"end_s", warning.end_s},
                                 {"message", QString::fromStdString(warning.message)}});
    return array;
}

void printSingleEvaluation(const CommandLine& cmd, const Parameters& params, const RecordingEvaluation& evaluation)
{
    if (cmd.json) {
        std::cout << QJsonDocument(recordingJson(cmd, params, evaluation)).toJson(QJsonDocument::Compact).toStdString()
                  << "\n";
        return;
    }
    std::cout << "recording   " << evaluation.path << "\nparameters  " << describeParameters(cmd)
              << "\nmethods     " << methodSet(params) << "\n";
    for (const std::string& note : evaluation.referenceNotes)
        std::cout << "reference   " << note << "\n";
    for (const Metric& metric : evaluation.metrics) {
        char line[128];
        if (metric.isCount)
            std::snprintf(line, sizeof line, "%-34s %7.0f\n", metric.label.c_str(), metric.value);
        else
            std::snprintf(line, sizeof line, "%-34s %12.4f\n", metric.label.c_str(), metric.value);
        std::cout << line;
    }
}

void printBatchEvaluation(const CommandLine& cmd, const Parameters& params,
                          const std::vector<RecordingEvaluation>& evaluations)
{
    if (cmd.json)
        printBatchJson(cmd, params, evaluations);
    else
        printBatchText(cmd, params, evaluations);
}

}  // namespace footpath::cli
