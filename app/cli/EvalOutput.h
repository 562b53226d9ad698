#pragma once

#include "cli/CommandLine.h"
#include "cli/EvalRun.h"
#include "nav/Parameters.h"

#include <QJsonArray>
#include <QJsonValue>

#include <vector>

namespace footpath::cli {

/// A number for JSON, null where it is not finite (JSON has no NaN).
QJsonValue jsonNumber(double value);
/// Plausibility warnings as {kind, start_s, end_s, message} objects, as eval and compare list them.
QJsonArray warningsJson(const std::vector<PlausibilityWarning>& warnings);

/// One evaluated file as eval has always printed it: the metric table, or one JSON object (--json).
void printSingleEvaluation(const CommandLine& cmd, const Parameters& params, const RecordingEvaluation& evaluation);
/// Several files: one row per file and a summary per kind of reference, or one JSON object with
/// "recordings" and "summary" (--json). Failed files appear as error rows, in input order.
void printBatchEvaluation(const CommandLine& cmd, const Parameters& params,
                          const std::vector<RecordingEvaluation>& evaluations);

}  // namespace footpath::cli
