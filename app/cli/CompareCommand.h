#pragma once

#include "cli/CommandLine.h"

namespace footpath::cli {

/// footpath-cli compare: every method set of --sets (or the suggested ones) on each INPUT, as a
/// table per INPUT and, for several, the mean per set; or one JSON object (--json).
int runCompare(const CommandLine& cmd);

}  // namespace footpath::cli
