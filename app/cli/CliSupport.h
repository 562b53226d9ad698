#pragma once

#include "Recording.h"
#include "Result.h"
#include "cli/CommandLine.h"
#include "io/Import.h"
#include "nav/Parameters.h"

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace footpath::cli {

/// A failure the user can fix: printed as it is, exit code 2.
struct BadInput {
    std::string message;
};

/// --params then --set, validated.
Parameters loadParameterSet(const CommandLine& cmd);
/// The import options of the command line, completed by --import-preset.
ImportOptions importOptionsOf(const CommandLine& cmd);
/// Reads one file; a file with nothing usable becomes BadInput. Prints nothing, so it may run on
/// several threads at once.
ImportResult importFile(const std::string& path, const ImportOptions& options);
/// Stores options under --save-import-preset when it is given.
void saveImportPresetIfAsked(const CommandLine& cmd, const ImportOptions& options);
/// An import message with the option that does what it asks: the readers' messages say what to set
/// ("give the sample rate") without naming flags, which the GUI does not have; here they get one
/// ("give the sample rate (--rate HZ)").
std::string withFlagHints(std::string message);
/// "warning: PATH: text" on stderr for each import warning.
void printImportWarnings(const std::string& path, const std::vector<std::string>& warnings);
/// Reads INPUT with the import options (and a preset); saves the preset when asked; prints the
/// import warnings to stderr when echoWarnings is set.
ImportResult importInput(const CommandLine& cmd, bool echoWarnings = true);
/// Runs the pipeline; a problem the user caused becomes BadInput.
Result estimate(const Recording& recording, const Parameters& params);
/// Writes through writeFileAtomically when a path is given.
void writeIfAsked(const std::string& path, const std::function<void(std::ostream&)>& write);
/// "defaults" or the preset path, followed by the --set assignments.
std::string describeParameters(const CommandLine& cmd);
/// "[t0-t1 s] message" of a plausibility warning.
std::string describeWarning(const PlausibilityWarning& warning);
/// "PATH: warning: [t0-t1 s] message" on stderr for each warning.
void printPlausibilityWarnings(const std::string& path, const std::vector<PlausibilityWarning>& warnings);
/// "ZUPT+ZARU", as the method set of a results table.
std::string methodSet(const Parameters& params);

}  // namespace footpath::cli
