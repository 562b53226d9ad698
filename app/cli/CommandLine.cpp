#include "cli/CommandLine.h"

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

std::string usageText()
{
    return R"(Usage:
  footpath-cli process INPUT [--params preset.json] [--set name=value ...]
                             [--columns role,role,...]
                             [--trajectory out.csv] [--steps out.csv] [--summary out.json]
  footpath-cli eval INPUT [--params preset.json] [--set name=value ...] [--columns role,...]
                          [--reference-columns x,y,z] [--closed-loop] [--length METRES] [--json]

INPUT is a delimited text file with a header row: time_s (or t_s, time_ms), acc_x, acc_y, acc_z
(m/s^2), gyr_x, gyr_y, gyr_z (rad/s), optional mag_x..z and pressure_pa; *_mps2 / *_radps names are
accepted. A file without a header needs --columns with one role per column: time_s, time_ms,
time_us, acc_x..z, gyr_x..z, mag_x..z, pressure_pa, skip.
--reference-columns names three header columns holding a reference position; a leading '-' negates
an axis (pyshoe-vicon: vicon_x_m,-vicon_y_m,vicon_z_m).
Exit codes: 0 success, 2 bad input or options, 1 internal error.
)";
}

namespace {

using Handler = std::function<std::string(CommandLine&, const std::string&)>;

bool parsePositive(const std::string& text, double& value)
{
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return !text.empty() && end == text.c_str() + text.size() && std::isfinite(value) && value > 0.0;
}

const std::map<std::string, Handler>& valueOptions()
{
    static const std::map<std::string, Handler> options = {
        {"--params", [](CommandLine& c, const std::string& v) { c.paramsFile = v; return std::string(); }},
        {"--set", [](CommandLine& c, const std::string& v) {
             if (v.find('=') == std::string::npos)
                 return "--set expects name=value, got '" + v + "'";
             c.sets.push_back(v);
             return std::string();
         }},
        {"--columns", [](CommandLine& c, const std::string& v) { c.columnMap = splitList(v); return std::string(); }},
        {"--trajectory", [](CommandLine& c, const std::string& v) { c.trajectoryOut = v; return std::string(); }},
        {"--steps", [](CommandLine& c, const std::string& v) { c.stepsOut = v; return std::string(); }},
        {"--summary", [](CommandLine& c, const std::string& v) { c.summaryOut = v; return std::string(); }},
        {"--reference-columns", [](CommandLine& c, const std::string& v) {
             c.referenceColumns = splitList(v);
             return c.referenceColumns.size() == 3 ? std::string()
                                                   : "--reference-columns expects three names x,y,z, got '" + v + "'";
         }},
        {"--length", [](CommandLine& c, const std::string& v) {
             return parsePositive(v, c.length_m) ? std::string() : "--length expects metres > 0, got '" + v + "'";
         }},
    };
    return options;
}

std::string checkCombination(const CommandLine& c)
{
    if (c.input.empty())
        return "missing INPUT file";
    const int references = int(!c.referenceColumns.empty()) + int(c.closedLoop) + int(c.length_m > 0.0);
    if (c.command == "process" && (references > 0 || c.json))
        return "--reference-columns, --closed-loop, --length and --json belong to eval";
    if (c.command == "eval" && (!c.trajectoryOut.empty() || !c.stepsOut.empty() || !c.summaryOut.empty()))
        return "--trajectory, --steps and --summary belong to process";
    return {};
}

}  // namespace

std::string parseCommandLine(const std::vector<std::string>& args, CommandLine& out)
{
    if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
        out.command = "help";
        return {};
    }
    out.command = args[0];
    if (out.command != "process" && out.command != "eval")
        return "unknown command '" + out.command + "'; expected process or eval";
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "--closed-loop") {
            out.closedLoop = true;
        } else if (arg == "--json") {
            out.json = true;
        } else if (const auto handler = valueOptions().find(arg); handler != valueOptions().end()) {
            if (i + 1 >= args.size())
                return arg + " expects a value";
            if (std::string problem = handler->second(out, args[++i]); !problem.empty())
                return problem;
        } else if (arg.rfind("--", 0) == 0) {
            return "unknown option '" + arg + "'";
        } else if (out.input.empty()) {
            out.input = arg;
        } else {
            return "unexpected argument '" + arg + "' (INPUT is already '" + out.input + "')";
        }
    }
    return checkCombination(out);
}

}  // namespace footpath::cli
