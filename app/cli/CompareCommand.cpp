#include "cli/CompareCommand.h"

#include "cli/CliSupport.h"
#include "cli/EvalOutput.h"
#include "cli/EvalRun.h"
#include "nav/MethodSets.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QThread>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>

namespace footpath::cli {

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

/// What a table row shows for one set: its figures on one recording, or their means over several.
struct SetFigures {
    std::string name;
    std::string error;  ///< the set failed (a mean: on every input)
    double endToStart_m = kNone;
    double endToStartPct = kNone;
    double pathLength_m = kNone;
    double heightChange_m = kNone;
    double armse2d_m = kNone;
    double stanceF1 = kNone;
    double steps = kNone;
    double warningCount = kNone;
    std::vector<PlausibilityWarning> warnings;  ///< one recording only
    std::vector<MethodNote> notes;              ///< one recording only
    std::size_t count = 0;                      ///< a mean: the inputs it averages

    bool ok() const { return error.empty(); }
};

/// A column of the comparison table and its JSON key.
struct FigureColumn {
    const char* key;
    const char* header;
    int decimals;
    int meanDecimals;  ///< counts averaged over inputs get a fraction
    double SetFigures::*member;
    bool needsReference;  ///< shown only where the recording has the reference
    bool ranked;          ///< bestComparisonRow knows which value is best
};

const std::vector<FigureColumn>& figureColumns()
{
    static const std::vector<FigureColumn> columns = {
        {"end_to_start_m", "end-start m", 3, 3, &SetFigures::endToStart_m, false, true},
        {"end_to_start_pct", "end-start %", 2, 2, &SetFigures::endToStartPct, false, true},
        {"path_length_m", "path m", 2, 2, &SetFigures::pathLength_m, false, false},
        {"height_change_m", "height m", 3, 3, &SetFigures::heightChange_m, false, false},
        {"armse_2d_m", "ARMSE2D m", 3, 3, &SetFigures::armse2d_m, true, true},
        {"stance_f1", "F1", 3, 3, &SetFigures::stanceF1, true, true},
        {"steps", "steps", 0, 1, &SetFigures::steps, false, false},
        {"warning_count", "warnings", 0, 1, &SetFigures::warningCount, false, false},
    };
    return columns;
}

/// One INPUT of compare: a row of figures per set, or why the file could not be read.
struct InputComparison {
    std::string path;
    std::string error;
    std::vector<std::string> referenceNotes;
    std::vector<SetFigures> sets;

    bool ok() const { return error.empty(); }
};

std::vector<MethodSet> methodSetsOf(const CommandLine& cmd, const Parameters& base)
{
    const std::string specs = cmd.methodSets.empty() ? suggestedMethodSetsSpec() : cmd.methodSets;
    std::string error;
    std::vector<MethodSet> sets = parseMethodSets(specs, base, error);
    if (sets.empty())
        throw BadInput{"--sets: " + error};
    return sets;
}

SetFigures figuresOf(const ComparisonRow& row)
{
    SetFigures figures;
    figures.name = row.set.name;
    const Result& result = row.output.result;
    if (!row.output.error.empty() || result.cancelled) {
        figures.error = row.output.error.empty() ? "cancelled" : row.output.error;
        return figures;
    }
    figures.endToStart_m = row.endToStart_m;
    figures.endToStartPct = row.endToStartPct;
    figures.pathLength_m = row.pathLength_m;
    figures.heightChange_m = row.heightChange_m;
    figures.armse2d_m = row.armse2d_m;
    figures.stanceF1 = row.stanceF1;
    figures.steps = static_cast<double>(result.summary.steps);
    figures.warningCount = static_cast<double>(result.warnings.size());
    figures.warnings = result.warnings;
    figures.notes = result.methodNotes;
    figures.count = 1;
    return figures;
}

/// Reads one INPUT and runs every set on it; only the figures are kept, not the trajectories, so a
/// folder of long recordings does not pile up in memory.
InputComparison compareInput(const std::string& path, const ImportOptions& options,
                             const std::vector<MethodSet>& sets, int jobs)
{
    InputComparison comparison;
    comparison.path = path;
    try {
        const ImportResult read = importFile(path, options);
        printImportWarnings(path, read.recording.warnings);
        comparison.referenceNotes = read.recording.reference.notes;
        for (const ComparisonRow& row : runComparison(read.recording, sets, jobs))
            comparison.sets.push_back(figuresOf(row));
    } catch (const BadInput& bad) {
        comparison.error = bad.message;
    }
    return comparison;
}

/// The mean of each figure of set `index` over the inputs where the set ran and has that figure.
SetFigures meanFigures(const std::vector<InputComparison>& inputs, std::size_t index, const std::string& name)
{
    SetFigures mean;
    mean.name = name;
    for (const FigureColumn& column : figureColumns()) {
        double sum = 0.0;
        std::size_t n = 0;
        for (const InputComparison& input : inputs) {
            if (!input.ok() || !input.sets[index].ok() || !std::isfinite(input.sets[index].*column.member))
                continue;
            sum += input.sets[index].*column.member;
            ++n;
        }
        mean.*column.member = n > 0 ? sum / static_cast<double>(n) : kNone;
    }
    for (const InputComparison& input : inputs)
        mean.count += input.ok() && input.sets[index].ok() ? 1 : 0;
    if (mean.count == 0)
        mean.error = "failed on every input";
    return mean;
}

std::vector<SetFigures> summaryOf(const std::vector<InputComparison>& inputs, const std::vector<MethodSet>& sets)
{
    std::vector<SetFigures> summary;
    for (std::size_t i = 0; i < sets.size(); ++i)
        summary.push_back(meanFigures(inputs, i, sets[i].name));
    return summary;
}

/// Per ranked column, the index of the best set (columns no set has a value for are left out).
std::map<std::string, int> bestOf(const std::vector<SetFigures>& sets)
{
    std::vector<ComparisonRow> rows(sets.size());
    for (std::size_t i = 0; i < sets.size(); ++i) {
        rows[i].endToStart_m = sets[i].endToStart_m;
        rows[i].endToStartPct = sets[i].endToStartPct;
        rows[i].armse2d_m = sets[i].armse2d_m;
        rows[i].stanceF1 = sets[i].stanceF1;
        rows[i].output.error = sets[i].error;
    }
    std::map<std::string, int> best;
    for (const FigureColumn& column : figureColumns())
        if (const int index = column.ranked ? bestComparisonRow(rows, column.key) : -1; index >= 0)
            best[column.key] = index;
    return best;
}

// ---- text ----

std::vector<FigureColumn> columnsShown(const std::vector<SetFigures>& sets)
{
    std::vector<FigureColumn> shown;
    for (const FigureColumn& column : figureColumns())
        if (!column.needsReference || std::any_of(sets.begin(), sets.end(), [&](const SetFigures& s) {
                return std::isfinite(s.*column.member);
            }))
            shown.push_back(column);
    return shown;
}

int widthOf(const FigureColumn& column)
{
    return std::max(static_cast<int>(std::strlen(column.header)), 8);
}

void printCell(double value, const FigureColumn& column, int decimals, bool best)
{
    if (std::isfinite(value))
        std::printf("  %*.*f%c", widthOf(column), decimals, value, best ? '*' : ' ');
    else
        std::printf("  %*s ", widthOf(column), "-");
}

/// The sets as rows under a header, '*' after each column's best value; means adds a count column.
void printSetTable(const std::vector<SetFigures>& sets, bool means)
{
    int nameWidth = 3;  // "set"
    for (const SetFigures& set : sets)
        nameWidth = std::max(nameWidth, static_cast<int>(set.name.size()));
    const std::vector<FigureColumn> shown = columnsShown(sets);
    const std::map<std::string, int> best = bestOf(sets);
    std::printf("%-*s", nameWidth, "set");
    for (const FigureColumn& column : shown)
        std::printf("  %*s ", widthOf(column), column.header);
    std::printf(means ? "  inputs\n" : "\n");
    for (std::size_t i = 0; i < sets.size(); ++i) {
        std::printf("%-*s", nameWidth, sets[i].name.c_str());
        if (!sets[i].ok()) {
            std::printf("  error: %s\n", sets[i].error.c_str());
            continue;
        }
        for (const FigureColumn& column : shown) {
            const auto found = best.find(column.key);
            const bool isBest = found != best.end() && found->second == static_cast<int>(i);
            printCell(sets[i].*column.member, column, means ? column.meanDecimals : column.decimals, isBest);
        }
        if (means)
            std::printf("  %6zu", sets[i].count);
        std::printf("\n");
    }
}

void printInputText(const InputComparison& input)
{
    std::printf("input       %s\n", input.path.c_str());
    if (!input.ok()) {
        std::printf("error       %s\n", input.error.c_str());
        return;
    }
    for (const std::string& note : input.referenceNotes)
        std::printf("reference   %s\n", note.c_str());
    printSetTable(input.sets, false);
}

void printText(const CommandLine& cmd, const std::vector<InputComparison>& inputs,
               const std::vector<SetFigures>& summary)
{
    std::printf("parameters  %s\n", describeParameters(cmd).c_str());
    for (const InputComparison& input : inputs) {
        std::printf("\n");
        printInputText(input);
    }
    if (inputs.size() > 1) {
        const auto read = std::count_if(inputs.begin(), inputs.end(), [](const InputComparison& i) { return i.ok(); });
        std::printf("\nmean per set over %zu of %zu inputs (each figure over the inputs that have it)\n",
                    static_cast<std::size_t>(read), inputs.size());
        printSetTable(summary, true);
    }
    std::printf("*: the best of the column (smallest end-to-start and ARMSE, largest F1)\n");
}

// ---- JSON ----

QJsonArray notesJson(const std::vector<MethodNote>& notes)
{
    QJsonArray array;
    for (const MethodNote& note : notes)
        array.append(QJsonObject{{"method", QString::fromStdString(note.method)},
                                 {"start_s", note.start_s},
                                 {"end_s", note.end_s},
                                 {"message", QString::fromStdString(note.message)}});
    return array;
}

/// One set as a JSON object; a mean lists its count instead of the warnings themselves.
QJsonObject setJson(const SetFigures& set, bool mean)
{
    QJsonObject object{{"name", QString::fromStdString(set.name)}};
    if (!set.ok())
        object.insert("error", QString::fromStdString(set.error));
    for (const FigureColumn& column : figureColumns()) {
        const double value = set.*column.member;
        const bool listedSeparately = !mean && std::strcmp(column.key, "warning_count") == 0;
        if (!listedSeparately && (std::isfinite(value) || !column.needsReference))
            object.insert(QString::fromLatin1(column.key), jsonNumber(value));
    }
    if (mean) {
        object.insert("count", static_cast<qint64>(set.count));
    } else if (set.ok()) {
        object.insert("warnings", warningsJson(set.warnings));
        object.insert("method_notes", notesJson(set.notes));
    }
    return object;
}

QJsonArray setsJson(const std::vector<SetFigures>& sets, bool mean)
{
    QJsonArray array;
    for (const SetFigures& set : sets)
        array.append(setJson(set, mean));
    return array;
}

QJsonObject bestJson(const std::vector<SetFigures>& sets)
{
    QJsonObject best;
    for (const auto& [column, index] : bestOf(sets))
        best.insert(QString::fromStdString(column), QString::fromStdString(sets[static_cast<std::size_t>(index)].name));
    return best;
}

QJsonObject inputJson(const InputComparison& input)
{
    QJsonObject object{{"input", QString::fromStdString(input.path)}};
    if (!input.ok()) {
        object.insert("error", QString::fromStdString(input.error));
        return object;
    }
    QJsonArray notes;
    for (const std::string& note : input.referenceNotes)
        notes.append(QString::fromStdString(note));
    object.insert("reference", notes);
    object.insert("sets", setsJson(input.sets, false));
    object.insert("best", bestJson(input.sets));
    return object;
}

/// One input: its object. Several: "inputs", and the means as "sets" (also under "summary").
void printJson(const CommandLine& cmd, const std::vector<InputComparison>& inputs,
               const std::vector<SetFigures>& summary, bool single)
{
    QJsonObject root;
    if (single) {
        root = inputJson(inputs.front());
    } else {
        QJsonArray list;
        for (const InputComparison& input : inputs)
            list.append(inputJson(input));
        const QJsonArray means = setsJson(summary, true);
        root = QJsonObject{{"inputs", list}, {"summary", QJsonObject{{"sets", means}}}, {"sets", means},
                           {"best", bestJson(summary)}};
    }
    root.insert("parameters", QString::fromStdString(describeParameters(cmd)));
    std::cout << QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString();
}

// ---- run ----

void printWarnings(const std::vector<InputComparison>& inputs)
{
    for (const InputComparison& input : inputs)
        for (const SetFigures& set : input.sets)
            printPlausibilityWarnings(input.path + " [" + set.name + "]", set.warnings);
}

/// 0 when every input was read and every set ran; else BadInput saying what failed (exit code 2).
int reportFailures(const std::vector<InputComparison>& inputs)
{
    std::string failed;
    std::size_t count = 0;
    for (const InputComparison& input : inputs) {
        for (const SetFigures& set : input.sets)
            if (!set.ok())
                failed += (count++ ? ", " : "") + input.path + " [" + set.name + "]";
        if (!input.ok())
            failed += (count++ ? ", " : "") + input.path;
    }
    if (count == 0)
        return 0;
    throw BadInput{"could not compare " + failed};
}

}  // namespace

int runCompare(const CommandLine& cmd)
{
    const Parameters base = loadParameterSet(cmd);
    const std::vector<MethodSet> sets = methodSetsOf(cmd, base);  // a bad token stops before any file is read
    const ImportOptions options = importOptionsOf(cmd);
    const std::vector<std::string> paths = expandInputs(cmd.inputs);
    const int jobs = cmd.jobs > 0 ? cmd.jobs : QThread::idealThreadCount();
    std::vector<InputComparison> inputs;
    for (const std::string& path : paths)
        inputs.push_back(compareInput(path, options, sets, jobs));
    const bool single = cmd.inputs.size() == 1 && !isFolder(cmd.inputs.front());
    if (single && !inputs.front().ok())
        throw BadInput{inputs.front().error};  // as eval: the message alone, nothing on stdout
    printWarnings(inputs);
    const std::vector<SetFigures> summary = summaryOf(inputs, sets);
    if (cmd.json)
        printJson(cmd, inputs, summary, single);
    else
        printText(cmd, inputs, summary);
    if (std::any_of(inputs.begin(), inputs.end(), [](const InputComparison& i) { return i.ok(); }))
        saveImportPresetIfAsked(cmd, options);
    std::cout.flush();
    return reportFailures(inputs);
}

}  // namespace footpath::cli
