#pragma once

#include <string>
#include <vector>

namespace footpath::cli {

/// What the user asked for, before any file is touched.
struct CommandLine {
    std::string command;  ///< "process", "eval", "compare", "tune", "gait", "info", "report", "record" or "help"
    bool help = false;    ///< COMMAND --help: print the command's usage and options
    std::string input;                ///< the first INPUT
    std::vector<std::string> inputs;  ///< every INPUT (several only for eval, compare, tune and gait)
    // Parameters
    std::string paramsFile;
    std::vector<std::string> sets;  ///< "name=value"
    // Import
    std::string format;
    std::vector<std::string> columnMap;
    std::string importPreset;
    std::string saveImportPreset;
    std::string accUnit, gyrUnit, timeUnit;
    double rate_hz = 0.0;
    // Outputs
    std::string trajectoryOut;
    std::string stepsOut;
    std::string summaryOut;
    std::string summaryCsvOut;
    std::string parametersCsvOut;
    // Report
    std::string pdfOut;
    std::string pageSize = "a4";  ///< a4 or letter
    // Evaluation
    std::vector<std::string> referenceColumns;
    bool closedLoop = false;
    double length_m = 0.0;
    bool json = false;
    int jobs = 0;  ///< eval's, compare's and tune's parallel runs; 0: one per core
    // Comparison (compare)
    std::string methodSets;  ///< --sets "zupt;zupt,zaru"; empty: the suggested sets
    // Self-tuning (tune)
    std::string criterion;   ///< closed-loop, length or reference
    int evaluations = 200;   ///< parameter sets tried
    int seed = 1;
    // Live recording (record)
    std::string port;
    double baud = 0.0;      ///< 0: 115200 with a probe of the common rates
    double duration_s = 0.0;  ///< device seconds; 0: until Ctrl+C
    std::string outFile;  ///< --out: record's FILE.mtb, tune's preset.json
    std::string csvOut;
};

/// Parses argv; returns an error message (naming the bad option) or empty.
std::string parseCommandLine(const std::vector<std::string>& args, CommandLine& out);

/// The commands footpath-cli knows, in the order the usage lists them.
const std::vector<std::string>& commandNames();
/// Every command's synopsis and the notes: what `footpath-cli --help` prints.
std::string usageText();
/// "Usage:" and one command's synopsis; empty for an unknown command.
std::string commandSynopsis(const std::string& command);
/// One command's synopsis, options and notes: what `footpath-cli COMMAND --help` prints.
std::string commandUsageText(const std::string& command);

std::vector<std::string> splitList(const std::string& text, char separator = ',');

}  // namespace footpath::cli
