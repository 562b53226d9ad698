#pragma once

#include "cli/CommandLine.h"

namespace footpath::cli {

/// footpath-cli record: a live session through DeviceSession without the GUI. Prints the device
/// and the counters; a device or port problem is BadInput (exit 2) with the session's words.
int runRecord(const CommandLine& cmd);

}  // namespace footpath::cli
