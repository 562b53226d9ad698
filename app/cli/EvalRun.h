#pragma once

#include "Result.h"
#include "cli/CommandLine.h"
#include "io/Import.h"
#include "nav/Parameters.h"

#include <string>
#include <vector>

namespace footpath::cli {

/// One accuracy figure (docs/accuracy.md, "The metrics") for one recording.
struct Metric {
    std::string key;    ///< JSON name, e.g. "armse_2d_m"
    std::string label;  ///< the single-file table's row label
    double value;
    bool isCount = false;  ///< a number of things: printed without decimals
};

/// What eval found for one input file: its metrics, or why it could not be evaluated.
struct RecordingEvaluation {
    std::string path;
    std::string error;  ///< empty when the file was evaluated
    std::vector<Metric> metrics;
    std::vector<std::string> referenceNotes;
    std::vector<std::string> importWarnings;
    std::vector<PlausibilityWarning> warnings;

    bool ok() const { return error.empty(); }
    /// The metric called key, or nullptr when this file has no such figure.
    const Metric* find(const std::string& key) const;
};

/// What every file of one eval run shares.
struct EvalSetup {
    ImportOptions import;
    Parameters params;
    bool closedLoop = false;  ///< --closed-loop
    double length_m = 0.0;    ///< --length, 0 when not given
};

/// True when path names a folder (eval then reads the recordings in it).
bool isFolder(const std::string& path);
/// The files to evaluate: each file as given, each folder's recordings in name order. A path that
/// does not exist, or inputs that name no recording at all, are BadInput.
std::vector<std::string> expandInputs(const std::vector<std::string>& inputs);
/// Evaluates every path with up to `jobs` threads; the results keep the order of paths. A file that
/// cannot be read or estimated becomes an error entry; anything else is rethrown here.
std::vector<RecordingEvaluation> evaluateAll(const EvalSetup& setup, const std::vector<std::string>& paths,
                                             int jobs);

}  // namespace footpath::cli
