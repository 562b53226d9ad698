#pragma once

#include "cli/CommandLine.h"

namespace footpath::cli {

/// footpath-cli report: the same PDF as File > Export report, drawn offscreen.
int runReport(const CommandLine& cmd);

}  // namespace footpath::cli
