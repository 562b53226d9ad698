#pragma once

#include "cli/CommandLine.h"

namespace footpath::cli {

int runProcess(const CommandLine& cmd);
int runEval(const CommandLine& cmd);
int runInfo(const CommandLine& cmd);

}  // namespace footpath::cli
