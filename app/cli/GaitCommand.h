#pragma once

#include "cli/CommandLine.h"

namespace footpath::cli {

/// footpath-cli gait: the two feet of one walk (core/gait/BilateralGait.h): each foot's gait
/// parameters, double support and left/right symmetry, and, when both files carry hand-labelled
/// gait events, the double support of the labels beside the detector's.
int runGait(const CommandLine& cmd);

}  // namespace footpath::cli
