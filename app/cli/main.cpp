// footpath-cli: runs the estimation pipeline on recordings in batch.
#include "cli/CliSupport.h"
#include "cli/Commands.h"
#include "cli/CompareCommand.h"
#include "cli/GaitCommand.h"
#include "cli/RecordCommand.h"
#include "cli/ReportCommand.h"
#include "cli/TuneCommand.h"
#include "nav/BulkAllocator.h"

#include <algorithm>
#include <exception>
#include <iostream>

using namespace footpath::cli;

namespace {

constexpr int kExitInternal = 1;
constexpr int kExitBadInput = 2;

/// After a mistake: the synopsis of the command (or the list of commands) and where the details
/// are, not pages of help that push the message off the screen.
std::string shortUsage(const std::string& command)
{
    const std::string synopsis = commandSynopsis(command);
    if (synopsis.empty())
        return "Commands: process, eval, compare, tune, gait, info, report, record.\n"
               "footpath-cli --help shows them all; footpath-cli COMMAND --help explains one.";
    return synopsis + "footpath-cli " + command + " --help lists its options.";
}

int dispatch(const std::vector<std::string>& args)
{
    CommandLine cmd;
    if (std::string problem = parseCommandLine(args, cmd); !problem.empty())
        throw BadInput{problem + "\n\n" + shortUsage(cmd.command)};
    if (cmd.command == "help" && args.size() > 1) {
        std::cout << commandUsageText(args[1]);  // "help process" as "process --help"
        return 0;
    }
    if (cmd.command == "help" || cmd.help) {
        std::cout << commandUsageText(cmd.command);
        return 0;
    }
    if (cmd.command == "info")
        return runInfo(cmd);
    if (cmd.command == "record")
        return runRecord(cmd);
    if (cmd.command == "report")
        return runReport(cmd);
    if (cmd.command == "compare")
        return runCompare(cmd);
    if (cmd.command == "tune")
        return runTune(cmd);
    if (cmd.command == "gait")
        return runGait(cmd);
    return cmd.command == "process" ? runProcess(cmd) : runEval(cmd);
}

}  // namespace

int main(int argc, char** argv)
{
    footpath::keepFreedMemoryForReruns();  // eval, tune and compare run the estimate many times
    try {
        return dispatch(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const BadInput& bad) {
        std::cerr << "footpath-cli: " << bad.message << "\n";
        return kExitBadInput;
    } catch (const std::exception& error) {
        std::cerr << "footpath-cli: internal error: " << error.what() << "\n";
        return kExitInternal;
    }
}
