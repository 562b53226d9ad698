#pragma once

#include "cli/CommandLine.h"

namespace footpath::cli {

/// footpath-cli tune: searches the detector settings and the filter noise for the values that
/// minimise a criterion over the INPUTs (core/tune/AutoTune.h), prints the criterion per INPUT
/// before and after and the changed parameters, and saves the tuned parameters to --out.
int runTune(const CommandLine& cmd);

}  // namespace footpath::cli
