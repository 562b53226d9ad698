#include "cli/CommandLine.h"

#include "io/Import.h"
#include "io/NearestNames.h"
#include "methods/MethodRegistry.h"
#include "nav/MethodSets.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>

namespace footpath::cli {

std::vector<std::string> splitList(const std::string& text, char separator)
{
    std::vector<std::string> items;
    std::size_t start = 0;
    for (std::size_t pos; (pos = text.find(separator, start)) != std::string::npos; start = pos + 1)
        items.push_back(text.substr(start, pos - start));
    items.push_back(text.substr(start));
    return items;
}

namespace {

const char* const kProcessSynopsis =
    R"(  footpath-cli process INPUT [import options] [--params preset.json] [--set name=value ...]
                             [--trajectory out.csv] [--steps out.csv] [--summary out.json]
                             [--summary-csv out.csv] [--parameters-csv out.csv]
)";
const char* const kReportSynopsis =
    R"(  footpath-cli report INPUT [RIGHT] --pdf out.pdf [--page-size a4|letter] [import options]
                            [--params preset.json] [--set name=value ...]
)";
const char* const kEvalSynopsis =
    R"(  footpath-cli eval INPUT... [import options] [--params preset.json] [--set name=value ...]
                          [--reference-columns x,y,z] [--closed-loop] [--length METRES]
                          [--jobs N] [--json]
)";
const char* const kCompareSynopsis =
    R"(  footpath-cli compare INPUT... [import options] [--params preset.json] [--set name=value ...]
                             [--sets "zupt;zupt,zaru;zupt,zaru,hdr;..."] [--jobs N] [--json]
)";
const char* const kTuneSynopsis =
    R"(  footpath-cli tune INPUT... --criterion closed-loop|length|reference --out preset.json
                          [--evaluations N] [--seed N] [--jobs N] [import options]
                          [--params preset.json] [--set name=value ...] [--closed-loop] [--length METRES]
                          [--reference-columns x,y,z] [--json]
)";
const char* const kGaitSynopsis =
    "  footpath-cli gait LEFT RIGHT [import options] [--params preset.json] [--set name=value ...] [--json]\n";
const char* const kInfoSynopsis = "  footpath-cli info INPUT [import options] [--json]\n";
const char* const kRecordSynopsis =
    "  footpath-cli record --port PATH [--baud N] [--rate HZ] [--duration S] --out FILE.mtb [--csv FILE.csv]\n";

const char* const kImportOptions = R"(
Import options (every format is detected from the content; these override or complete it):
  --format NAME              FORMATS
  --columns role,role,...    a file without a header: one role per column, from time_s, time_ms,
                             time_us, counter, acc_x..z, gyr_x..z, mag_x..z, pressure_pa|hpa|kpa, skip
  --acc-unit mps2|g  --gyr-unit radps|degps  --time-unit s|ms|us  --rate HZ
  --import-preset NAME|FILE  read with a saved column map and units
  --save-import-preset NAME  save the column map and units given here under NAME
)";

const char* const kParameterOptions = R"(
Parameters:
  --params preset.json       start from a parameter preset saved by the workspace (JSON)
  --set name=value           change one parameter (repeatable); the names are those of
                             --parameters-csv and of the presets, e.g. --set gyr_max_radps=1.2
)";

const char* const kProcessOutputs = R"(
Outputs (each written whole or not at all):
  --trajectory out.csv       time, position, velocity and attitude per sample
  --steps out.csv            one row per step
  --summary out.json         the figures printed on stdout, the warnings and method notes
  --summary-csv out.csv      the same figures as one CSV row
  --parameters-csv out.csv   every parameter and its value
process prints one line on stdout: samples, duration, steps, path length and end-to-start.
)";

const char* const kReferenceText = R"(
Reference data the file carries (VICON columns, gait events beside an Xsens export, a length in the
file name like rectangle_72m.TXT, a <file>.reference.json sidecar) is used by eval and compare unless
--reference-columns, --closed-loop or --length say otherwise; a leading '-' in
--reference-columns negates an axis.
)";

const char* const kRecordText =
    R"(record talks to a live Xsens MTi (or footpath-mti-sim) on a serial port: the init sequence, then
the raw bytes to FILE.mtb and the decoded samples to FILE.csv as they arrive, flushed every second,
until --duration seconds of device time (default: until Ctrl+C). Without --baud it starts at 115200
and probes the common rates; --rate is the output rate (default 100 Hz). It prints the device and
the counters (samples, lost packets, checksum errors, resyncs).
)";

const char* const kEvalText =
    R"(eval takes any number of INPUTs, files or folders (a folder: every recording directly in it, in
name order; hidden files and *.json, *.md, *.pdf, *.png are skipped), all with the same options.
One file prints its metrics as a table (or one JSON object); several print one row per file, then
mean, median, worst and count of each metric per kind of reference (or one JSON object with
"recordings" and "summary"). --jobs N evaluates N files at once (default: one per core); the
output keeps the input order. A file that cannot be read becomes an error row, the others go on.
)";

const char* const kCompareText =
    R"(compare runs every method set of --sets on each INPUT (files or folders, as for eval): sets are
separated by ';', methods within a set by ',', from
  METHODS;
every method a set does not name is off, the other parameters come from --params and --set.
Without --sets it runs the suggested sets:
  SUGGESTED
It prints a table per INPUT, one row per set in the order given: end-to-start (m and % of the path),
path length, height change, ARMSE 2D and stance F1 where the recording has the reference, steps and
plausibility warnings, with '*' after the best value of each column that has one (the smallest
end-to-start and ARMSE, the largest F1); several INPUTs add the mean per set. With
--json one object: "sets" (one object per set, in the order given) and "best"; for several INPUTs
"inputs" (one such object per file), "sets" (the means) and "best". --jobs N runs N sets at once.
)";

const char* const kTuneText =
    R"(tune searches the detector settings and the filter noise for the values that minimise the
criterion averaged over the INPUTs (files or folders, as for eval), starting from --params and --set:
closed-loop, the end-to-start distance in % of the path of walks marked closed (--closed-loop, or a
closed walk's reference); length, the distance error in % of walks of known length (--length, or the
file name); reference, the 2D ARMSE against reference positions. A setting that adds a plausibility
warning on any INPUT is never chosen. It prints the criterion per INPUT before and after and the
parameters it changed, and saves the tuned parameters to --out (a preset for --params and the
workspace). --evaluations N parameter sets are tried (default 200), --jobs N runs at once, --seed N
makes another search. Measure a preset on recordings it was not tuned on.
)";

const char* const kGaitText =
    R"(gait takes the left and the right file of one walk (in either order: names ending in _lf/_rf,
_left/_right or _l/_r say the foot; otherwise the first is the left) and prints each foot's gait
parameters (heel strike to toe off), the double support (% of the gait cycle both feet are on the
ground, over the straight strides of both feet) and the symmetry index of stride time, stride
length, stance and swing, 100 (left - right) / mean (positive: the left larger). When both files
carry hand-labelled gait events (the IPOL MTw JSON) it adds the labels' double support beside the
detector's over the same strides. The two files' time stamps are taken as one clock: both sensors
must start together (the IPOL files' PacketCounter does); files that do not pair stride for stride
get a warning.
)";

const char* const kInfoText =
    "info prints what was read: format, samples, rate, duration, channels, units, gaps, the reference\n"
    "the file carries and the import warnings (--json: one JSON object).\n";
const char* const kReportText = "report writes the workspace's PDF report of INPUT: figures, summary, steps and "
                                "parameters; given the left and the right file of one walk, both feet (the\n"
                                "right foot's path beside the left's, double support and symmetry), as the window does.\n";
const char* const kWarningsText =
    "eval, compare and process print the plausibility warnings to stderr: FILE: warning: [t0-t1 s] message.\n";
const char* const kExitCodes = "Exit codes: 0 success, 2 bad input or options or a device problem, 1 internal error.\n";

/// The lists that come from the method registry: the suggested sets, the method tokens, the formats.
std::string withRegistryLists(std::string text)
{
    const std::pair<std::string, std::string> lists[] = {
        {"SUGGESTED", suggestedMethodSetsSpec()}, {"METHODS", methodSetTokensText()}, {"FORMATS", importerNamesText()}};
    for (const auto& [placeholder, list] : lists)
        for (auto at = text.find(placeholder); at != std::string::npos; at = text.find(placeholder, at + list.size()))
            text.replace(at, placeholder.size(), list);
    return text;
}

}  // namespace

const std::vector<std::string>& commandNames()
{
    static const std::vector<std::string> names = {"process", "eval", "compare", "tune", "gait", "info", "report", "record"};
    return names;
}

std::string usageText()
{
    std::string text = std::string("Usage:\n") + kProcessSynopsis + kReportSynopsis + kEvalSynopsis + kCompareSynopsis
                       + kTuneSynopsis + kGaitSynopsis + kInfoSynopsis + kRecordSynopsis
                       + "  footpath-cli COMMAND --help   the options of one command\n" + kImportOptions
                       + kReferenceText + kRecordText + kEvalText + kCompareText + kTuneText + kGaitText + kWarningsText + kExitCodes;
    return withRegistryLists(std::move(text));
}

std::string commandSynopsis(const std::string& command)
{
    const std::map<std::string, const char*> synopses = {
        {"process", kProcessSynopsis}, {"report", kReportSynopsis}, {"eval", kEvalSynopsis},
        {"compare", kCompareSynopsis}, {"tune", kTuneSynopsis},     {"gait", kGaitSynopsis},
        {"info", kInfoSynopsis},       {"record", kRecordSynopsis}};
    const auto found = synopses.find(command);
    return found == synopses.end() ? std::string() : std::string("Usage:\n") + found->second;
}

std::string commandUsageText(const std::string& command)
{
    std::string text = "Usage:\n";
    if (command == "process")
        text += kProcessSynopsis + std::string(kParameterOptions) + kImportOptions + kProcessOutputs + kWarningsText;
    else if (command == "report")
        text += kReportSynopsis + std::string("\n") + kReportText + kParameterOptions + kImportOptions;
    else if (command == "eval")
        text += kEvalSynopsis + std::string("\n") + kEvalText + kParameterOptions + kImportOptions + kReferenceText
                + kWarningsText;
    else if (command == "compare")
        text += kCompareSynopsis + std::string("\n") + kCompareText + kParameterOptions + kImportOptions + kReferenceText
                + kWarningsText;
    else if (command == "tune")
        text += kTuneSynopsis + std::string("\n") + kTuneText + kParameterOptions + kImportOptions + kReferenceText;
    else if (command == "gait")
        text += kGaitSynopsis + std::string("\n") + kGaitText + kParameterOptions + kImportOptions + kWarningsText;
    else if (command == "info")
        text += kInfoSynopsis + std::string("\n") + kInfoText + kImportOptions;
    else if (command == "record")
        text += kRecordSynopsis + std::string("\n") + kRecordText;
    else
        return usageText();
    return withRegistryLists(text + kExitCodes);
}

namespace {

using Handler = std::function<std::string(CommandLine&, const std::string&)>;

bool parsePositive(const std::string& text, double& value)
{
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return !text.empty() && end == text.c_str() + text.size() && std::isfinite(value) && value > 0.0;
}

Handler storeText(std::string CommandLine::*member)
{
    return [member](CommandLine& c, const std::string& v) {
        c.*member = v;
        return std::string();
    };
}

Handler storeList(std::vector<std::string> CommandLine::*member)
{
    return [member](CommandLine& c, const std::string& v) {
        c.*member = splitList(v);
        return std::string();
    };
}

Handler storeJobs()
{
    return [](CommandLine& c, const std::string& v) {
        double jobs = 0.0;
        const bool whole = parsePositive(v, jobs) && jobs == std::floor(jobs) && jobs <= 1024.0;
        c.jobs = whole ? static_cast<int>(jobs) : 0;
        return whole ? std::string() : "--jobs expects a whole number of parallel runs from 1 to 1024, got '" + v + "'";
    };
}

Handler storeWhole(int CommandLine::*member, const std::string& option, double maximum)
{
    return [member, option, maximum](CommandLine& c, const std::string& v) {
        double value = 0.0;
        const bool whole = parsePositive(v, value) && value == std::floor(value) && value <= maximum;
        c.*member = whole ? static_cast<int>(value) : 0;
        return whole ? std::string()
                     : option + " expects a whole number from 1 to " + std::to_string(static_cast<long>(maximum))
                           + ", got '" + v + "'";
    };
}

Handler storePositive(double CommandLine::*member, const std::string& option, const char* what)
{
    return [member, option, what](CommandLine& c, const std::string& v) {
        return parsePositive(v, c.*member) ? std::string() : option + " expects " + what + " > 0, got '" + v + "'";
    };
}

const std::map<std::string, Handler>& valueOptions()
{
    static const std::map<std::string, Handler> options = {
        {"--params", storeText(&CommandLine::paramsFile)},
        {"--set", [](CommandLine& c, const std::string& v) {
             if (v.find('=') == std::string::npos)
                 return "--set expects name=value, got '" + v + "'";
             c.sets.push_back(v);
             return std::string();
         }},
        {"--format", storeText(&CommandLine::format)},
        {"--columns", storeList(&CommandLine::columnMap)},
        {"--import-preset", storeText(&CommandLine::importPreset)},
        {"--save-import-preset", storeText(&CommandLine::saveImportPreset)},
        {"--acc-unit", storeText(&CommandLine::accUnit)},
        {"--gyr-unit", storeText(&CommandLine::gyrUnit)},
        {"--time-unit", storeText(&CommandLine::timeUnit)},
        {"--rate", [](CommandLine& c, const std::string& v) {
             // The bound of an import preset's rate_hz: a larger number is a typing error.
             if (parsePositive(v, c.rate_hz) && c.rate_hz <= kMaxImportRate_hz)
                 return std::string();
             return "--rate expects a rate in Hz > 0 and up to " + std::to_string(static_cast<int>(kMaxImportRate_hz))
                    + ", got '" + v + "'";
         }},
        {"--trajectory", storeText(&CommandLine::trajectoryOut)},
        {"--steps", storeText(&CommandLine::stepsOut)},
        {"--summary", storeText(&CommandLine::summaryOut)},
        {"--summary-csv", storeText(&CommandLine::summaryCsvOut)},
        {"--parameters-csv", storeText(&CommandLine::parametersCsvOut)},
        {"--pdf", storeText(&CommandLine::pdfOut)},
        {"--page-size", [](CommandLine& c, const std::string& v) {
             c.pageSize = v;
             return v == "a4" || v == "letter" ? std::string() : "--page-size expects a4 or letter, got '" + v + "'";
         }},
        {"--reference-columns", [](CommandLine& c, const std::string& v) {
             c.referenceColumns = splitList(v);
             return c.referenceColumns.size() == 3 ? std::string()
                                                   : "--reference-columns expects three names x,y,z, got '" + v + "'";
         }},
        {"--length", storePositive(&CommandLine::length_m, "--length", "metres")},
        {"--jobs", storeJobs()},
        {"--sets", storeText(&CommandLine::methodSets)},
        {"--criterion", storeText(&CommandLine::criterion)},
        {"--evaluations", storeWhole(&CommandLine::evaluations, "--evaluations", 1e6)},
        {"--seed", storeWhole(&CommandLine::seed, "--seed", 1e9)},
        {"--port", storeText(&CommandLine::port)},
        {"--baud", storePositive(&CommandLine::baud, "--baud", "a baud rate")},
        {"--duration", storePositive(&CommandLine::duration_s, "--duration", "seconds")},
        {"--out", storeText(&CommandLine::outFile)},
        {"--csv", storeText(&CommandLine::csvOut)},
    };
    return options;
}

bool isHelpOption(const std::string& arg)
{
    return arg == "--help" || arg == "-h";
}

std::vector<std::string> optionNames()
{
    std::vector<std::string> names = {"--closed-loop", "--json", "--help"};
    for (const auto& [name, handler] : valueOptions())
        names.push_back(name);
    return names;
}

/// Reads args[i] (and its value, moving i past it) into out; an error message or empty.
std::string parseArgument(const std::vector<std::string>& args, std::size_t& i, CommandLine& out)
{
    const std::string& arg = args[i];
    if (arg == "--closed-loop") {
        out.closedLoop = true;
    } else if (arg == "--json") {
        out.json = true;
    } else if (const auto handler = valueOptions().find(arg); handler != valueOptions().end()) {
        if (i + 1 >= args.size())
            return arg + " expects a value";
        return handler->second(out, args[++i]);
    } else if (arg.rfind("-", 0) == 0 && arg.size() > 1) {
        return "unknown option '" + arg + "'" + didYouMean(arg, optionNames());
    } else if (out.input.empty() || out.command == "eval" || out.command == "compare" || out.command == "tune"
               || out.command == "gait" || (out.command == "report" && out.inputs.size() == 1)) {
        if (out.input.empty())
            out.input = arg;
        out.inputs.push_back(arg);
    } else {
        return "unexpected argument '" + arg + "' (INPUT is already '" + out.input + "')";
    }
    return {};
}

std::string checkRecordCombination(const CommandLine& c)
{
    if (!c.input.empty())
        return "record reads a serial port, not a file: pass it with --port (got '" + c.input + "')";
    if (c.port.empty())
        return "record needs --port PATH (e.g. /dev/ttyUSB0, or the emulator's /tmp/ttyMTi0)";
    if (c.outFile.empty())
        return "record needs --out FILE.mtb";
    const bool otherOptions = !c.paramsFile.empty() || !c.sets.empty() || !c.format.empty() || !c.columnMap.empty()
                              || !c.importPreset.empty() || !c.saveImportPreset.empty() || !c.accUnit.empty()
                              || !c.gyrUnit.empty() || !c.timeUnit.empty() || !c.trajectoryOut.empty()
                              || !c.stepsOut.empty() || !c.summaryOut.empty() || !c.referenceColumns.empty()
                              || c.closedLoop || c.length_m > 0.0 || c.json || c.jobs > 0 || !c.methodSets.empty();
    if (otherOptions)
        return "record takes only --port, --baud, --rate, --duration, --out and --csv";
    if (c.baud > 0.0 && c.baud != std::floor(c.baud))
        return "--baud expects a whole number, got " + std::to_string(c.baud);
    if (c.rate_hz > 0.0 && (c.rate_hz != std::floor(c.rate_hz) || c.rate_hz > 2000.0))
        return "record's --rate expects a whole number of Hz up to 2000";
    return {};
}

std::string checkTuneCombination(const CommandLine& c)
{
    if (c.input.empty())
        return "missing INPUT: the recordings to tune on";
    if (c.criterion != "closed-loop" && c.criterion != "length" && c.criterion != "reference")
        return c.criterion.empty() ? "tune needs --criterion closed-loop, length or reference"
                                   : "--criterion expects closed-loop, length or reference, got '" + c.criterion + "'";
    if (c.outFile.empty())
        return "tune needs --out preset.json, where the tuned parameters go";
    if (!c.port.empty() || c.baud > 0.0 || c.duration_s > 0.0 || !c.csvOut.empty())
        return "--port, --baud, --duration and --csv belong to record";
    if (!c.methodSets.empty())
        return "--sets belongs to compare";
    const bool outputs = !c.trajectoryOut.empty() || !c.stepsOut.empty() || !c.summaryOut.empty()
                         || !c.summaryCsvOut.empty() || !c.parametersCsvOut.empty() || !c.pdfOut.empty();
    return outputs ? "tune writes only the preset (--out)" : std::string();
}

std::string checkGaitCombination(const CommandLine& c)
{
    if (c.inputs.size() != 2)
        return "gait takes two files, the left and the right foot of one walk (got "
               + std::to_string(c.inputs.size()) + ")";
    const bool others = !c.port.empty() || c.baud > 0.0 || c.duration_s > 0.0 || !c.outFile.empty() || !c.csvOut.empty()
                        || !c.trajectoryOut.empty() || !c.stepsOut.empty() || !c.summaryOut.empty()
                        || !c.summaryCsvOut.empty() || !c.parametersCsvOut.empty() || !c.pdfOut.empty()
                        || !c.referenceColumns.empty() || c.closedLoop || c.length_m > 0.0 || c.jobs > 0
                        || !c.methodSets.empty() || !c.criterion.empty();
    return others ? "gait takes the import options, --params, --set and --json" : std::string();
}

std::string checkCombination(const CommandLine& c)
{
    if (c.command == "gait")
        return checkGaitCombination(c);
    const bool recordOptions = !c.port.empty() || c.baud > 0.0 || c.duration_s > 0.0 || !c.outFile.empty()
                               || !c.csvOut.empty();
    if (c.command == "record")
        return checkRecordCombination(c);
    if (c.command == "tune")
        return checkTuneCombination(c);
    if (recordOptions)
        return "--port, --baud, --duration, --out and --csv belong to record";
    if (!c.criterion.empty() || c.evaluations != CommandLine().evaluations || c.seed != CommandLine().seed)
        return "--criterion, --evaluations and --seed belong to tune";
    if (c.input.empty())
        return "missing INPUT file";
    const bool evaluation = c.closedLoop || c.length_m > 0.0;
    const bool several = c.command == "eval" || c.command == "compare";
    const bool outputs = !c.trajectoryOut.empty() || !c.stepsOut.empty() || !c.summaryOut.empty()
                         || !c.summaryCsvOut.empty() || !c.parametersCsvOut.empty();
    const bool estimation = !c.paramsFile.empty() || !c.sets.empty();
    if (c.command != "eval" && evaluation)
        return "--closed-loop and --length belong to eval and tune";
    if (!several && !c.referenceColumns.empty())
        return "--reference-columns belongs to eval, compare and tune";
    if (!several && c.jobs > 0)
        return "--jobs belongs to eval, compare and tune";
    if (c.command != "compare" && !c.methodSets.empty())
        return "--sets belongs to compare";
    if ((c.command == "process" || c.command == "report") && c.json)
        return "--json belongs to eval, compare and info";
    if (c.command != "process" && outputs)
        return "--trajectory, --steps, --summary, --summary-csv and --parameters-csv belong to process";
    if (c.command == "report" && c.pdfOut.empty())
        return "report needs --pdf OUT.pdf";
    if (c.command != "report" && !c.pdfOut.empty())
        return "--pdf belongs to report";
    if (c.command == "info" && estimation)
        return "--params and --set belong to process, report, eval and compare";
    return {};
}

}  // namespace

std::string parseCommandLine(const std::vector<std::string>& args, CommandLine& out)
{
    if (args.empty())
        return "no command given";
    if (isHelpOption(args[0]) || args[0] == "help") {
        out.command = "help";
        return {};
    }
    out.command = args[0];
    const std::vector<std::string>& known = commandNames();
    if (std::find(known.begin(), known.end(), out.command) == known.end())
        return "unknown command '" + out.command + "'" + didYouMean(out.command, known)
               + " (expected process, eval, compare, tune, gait, info, report or record)";
    // Asking for a command's help always works, whatever else the line holds.
    if (std::any_of(args.begin() + 1, args.end(), isHelpOption)) {
        out.help = true;
        return {};
    }
    for (std::size_t i = 1; i < args.size(); ++i)
        if (std::string problem = parseArgument(args, i, out); !problem.empty())
            return problem;
    return checkCombination(out);
}

}  // namespace footpath::cli
