// footpath-cli: runs the estimation pipeline on recordings in batch.
#include "cli/CliSupport.h"
#include "cli/Commands.h"
#include "cli/CompareCommand.h"
#include "cli/RecordCommand.h"
#include "cli/ReportCommand.h"

#include <exception>
#include <iostream>

using namespace footpath::cli;

namespace {

constexpr int kExitInternal = 1;
constexpr int kExitBadInput = 2;

int dispatch(const std::vector<std::string>& args)
{
    CommandLine cmd;
    if (std::string problem = parseCommandLine(args, cmd); !problem.empty())
        throw BadInput{problem + "\n\n" + usageText()};
    if (cmd.command == "help") {
        std::cout << usageText();
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
    return cmd.command == "process" ? runProcess(cmd) : runEval(cmd);
}

}  // namespace

int main(int argc, char** argv)
{
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
