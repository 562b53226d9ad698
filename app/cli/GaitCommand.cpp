#include "cli/GaitCommand.h"

#include "cli/CliSupport.h"
#include "cli/EvalOutput.h"
#include "gait/BilateralGait.h"
#include "io/FootPairing.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace footpath::cli {

namespace {

struct Foot {
    Recording recording;
    Result result;
};

Foot estimateFoot(const std::string& path, const ImportOptions& options, const Parameters& params)
{
    ImportResult read = importFile(path, options);
    printImportWarnings(path, read.recording.warnings);
    Foot foot{std::move(read.recording), Result()};
    foot.result = estimate(foot.recording, params);
    printPlausibilityWarnings(path, foot.result.warnings);
    return foot;
}

QJsonObject gaitJson(const GaitSummary& gait)
{
    return {{"strides", static_cast<qint64>(gait.strides)},
            {"straight_strides", static_cast<qint64>(gait.straightStrides)},
            {"turning_strides", static_cast<qint64>(gait.turningStrides)},
            {"stride_time_s", jsonNumber(gait.strideTime_s)},
            {"stride_length_m", jsonNumber(gait.strideLength_m)},
            {"cadence_spm", jsonNumber(gait.cadence_spm)},
            {"stance_pct", jsonNumber(gait.stancePct)},
            {"swing_pct", jsonNumber(gait.swingPct)},
            {"clearance_m", jsonNumber(gait.clearance_m)}};
}

QJsonObject doubleSupportJson(const DoubleSupportSummary& support)
{
    return {{"mean_pct", jsonNumber(support.meanPct)},
            {"initial_pct", jsonNumber(support.initialPct)},
            {"terminal_pct", jsonNumber(support.terminalPct)},
            {"strides", static_cast<qint64>(support.cycles)},
            {"unpaired_strides", static_cast<qint64>(support.unpairedCycles)}};
}

QJsonObject walkJson(const FootPair& pair, const BilateralGait& walk, const std::optional<DoubleSupportCheck>& check)
{
    const GaitSymmetry& s = walk.symmetry;
    QJsonObject json{{"left", QString::fromStdString(pair.left)},
                     {"right", QString::fromStdString(pair.right)},
                     {"left_gait", gaitJson(walk.left)},
                     {"right_gait", gaitJson(walk.right)},
                     {"double_support", doubleSupportJson(walk.doubleSupport)},
                     {"symmetry_index_pct", QJsonObject{{"stride_time", jsonNumber(s.strideTimePct)},
                                                        {"stride_length", jsonNumber(s.strideLengthPct)},
                                                        {"stance", jsonNumber(s.stancePct)},
                                                        {"swing", jsonNumber(s.swingPct)}}}};
    if (check)
        json["against_labels"] = QJsonObject{{"labelled", doubleSupportJson(check->labelled)},
                                             {"detected", doubleSupportJson(check->detected)},
                                             {"matched_strides", static_cast<qint64>(check->matchedStrides)},
                                             {"matched_labelled_pct", jsonNumber(check->matchedLabelledPct)},
                                             {"matched_detected_pct", jsonNumber(check->matchedDetectedPct)}};
    QJsonArray notes;
    for (const std::string& note : pair.notes)
        notes.append(QString::fromStdString(note));
    for (const std::string& warning : walk.warnings)
        notes.append(QString::fromStdString(warning));
    json["notes"] = notes;
    return json;
}

void printFootRow(const char* name, const GaitSummary& g)
{
    std::printf("%-6s %3zu (%2zu turning)  %6.3f  %6.3f  %6.1f  %6.1f  %6.1f  %6.3f\n", name, g.strides, g.turningStrides,
                g.strideTime_s, g.strideLength_m, g.cadence_spm, g.stancePct, g.swingPct, g.clearance_m);
}

void printWalk(const FootPair& pair, const BilateralGait& walk, const std::optional<DoubleSupportCheck>& check)
{
    std::printf("left   %s\nright  %s\n\n", pair.left.c_str(), pair.right.c_str());
    std::printf("foot   strides         time s  length m  cadence  stance %%  swing %%  clearance m\n");
    printFootRow("left", walk.left);
    printFootRow("right", walk.right);
    const DoubleSupportSummary& ds = walk.doubleSupport;
    std::printf("\ndouble support  %.1f %% of the gait cycle (initial %.1f %%, terminal %.1f %%) over %zu strides",
                ds.meanPct, ds.initialPct, ds.terminalPct, ds.cycles);
    std::printf(ds.unpairedCycles > 0 ? ", %zu unpaired\n" : "\n", ds.unpairedCycles);
    const GaitSymmetry& s = walk.symmetry;
    std::printf("symmetry index  stride time %+.1f %%, stride length %+.1f %%, stance %+.1f %%, swing %+.1f %% "
                "(100 (L - R) / mean; + left larger)\n",
                s.strideTimePct, s.strideLengthPct, s.stancePct, s.swingPct);
    if (check) {
        std::printf("against labels  double support on the %zu strides both have: %.1f %% detected, %.1f %% labelled\n",
                    check->matchedStrides, check->matchedDetectedPct, check->matchedLabelledPct);
        std::printf("                over every stride of the labelled trial (turns included): %.1f %% detected over "
                    "%zu strides, %.1f %% labelled over %zu\n",
                    check->detected.meanPct, check->detected.cycles, check->labelled.meanPct, check->labelled.cycles);
    }
    for (const std::string& note : pair.notes)
        std::printf("note            %s\n", note.c_str());
    for (const std::string& warning : walk.warnings)
        std::printf("warning         %s\n", warning.c_str());
}

}  // namespace

int runGait(const CommandLine& cmd)
{
    std::string problem;
    const std::optional<FootPair> pair = pairFeet(cmd.inputs[0], cmd.inputs[1], problem);
    if (!pair)
        throw BadInput{problem};
    const Parameters params = loadParameterSet(cmd);
    const ImportOptions options = importOptionsOf(cmd);
    const Foot left = estimateFoot(pair->left, options, params);
    const Foot right = estimateFoot(pair->right, options, params);
    const BilateralGait walk = analyseBilateralGait(left.result, right.result);
    const std::optional<DoubleSupportCheck> check =
        checkDoubleSupportAgainstLabels(left.recording, left.result, right.recording, right.result);
    if (cmd.json)
        std::cout << QJsonDocument(walkJson(*pair, walk, check)).toJson(QJsonDocument::Indented).toStdString();
    else
        printWalk(*pair, walk, check);
    saveImportPresetIfAsked(cmd, options);
    return 0;
}

}  // namespace footpath::cli
