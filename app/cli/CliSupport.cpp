#include "cli/CliSupport.h"

#include "io/ImportPresets.h"
#include "io/ParameterIo.h"
#include "io/ResultWriters.h"
#include "nav/MethodSets.h"
#include "nav/Pipeline.h"

#include <cstdio>
#include <iostream>

namespace footpath::cli {

namespace {

/// The import options as given, before a preset completes them.
ImportOptions importOptionsGiven(const CommandLine& cmd)
{
    ImportOptions options;
    options.format = cmd.format;
    options.columnMap = cmd.columnMap;
    options.referenceColumns = cmd.referenceColumns;
    options.rate_hz = cmd.rate_hz;
    if (!cmd.accUnit.empty() && !parseAccUnit(cmd.accUnit, options.accUnit))
        throw BadInput{"--acc-unit expects mps2 or g, got '" + cmd.accUnit + "'"};
    if (!cmd.gyrUnit.empty() && !parseGyrUnit(cmd.gyrUnit, options.gyrUnit))
        throw BadInput{"--gyr-unit expects radps or degps, got '" + cmd.gyrUnit + "'"};
    if (!cmd.timeUnit.empty() && !parseTimeUnit(cmd.timeUnit, options.timeUnit))
        throw BadInput{"--time-unit expects s, ms or us, got '" + cmd.timeUnit + "'"};
    return options;
}

}  // namespace

void saveImportPresetIfAsked(const CommandLine& cmd, const ImportOptions& options)
{
    if (cmd.saveImportPreset.empty())
        return;
    ImportPreset preset;
    preset.name = cmd.saveImportPreset;
    preset.format = options.format;
    preset.columnMap = options.columnMap;
    preset.accUnit = options.accUnit;
    preset.gyrUnit = options.gyrUnit;
    preset.timeUnit = options.timeUnit;
    preset.rate_hz = options.rate_hz;
    if (std::string problem = saveImportPreset(preset); !problem.empty())
        throw BadInput{problem};
    std::cerr << "saved import preset '" << preset.name << "' in " << importPresetDirectory() << "\n";
}

Parameters loadParameterSet(const CommandLine& cmd)
{
    Parameters params;
    if (!cmd.paramsFile.empty())
        if (std::string problem = loadParameters(cmd.paramsFile, params); !problem.empty())
            throw BadInput{problem};
    for (const std::string& assignment : cmd.sets) {
        const auto eq = assignment.find('=');
        if (std::string problem = setParameterByName(params, assignment.substr(0, eq), assignment.substr(eq + 1));
            !problem.empty())
            throw BadInput{"--set: " + problem};
    }
    std::string problems;
    for (const std::string& problem : params.validate())
        problems += "\n  " + problem;
    if (!problems.empty())
        throw BadInput{"invalid parameters:" + problems};
    return params;
}

ImportOptions importOptionsOf(const CommandLine& cmd)
{
    ImportOptions options = importOptionsGiven(cmd);
    if (!cmd.importPreset.empty()) {
        ImportPreset preset;
        if (std::string problem = loadImportPreset(cmd.importPreset, preset); !problem.empty())
            throw BadInput{problem};
        applyImportPreset(preset, options);
    }
    return options;
}

std::string withFlagHints(std::string message)
{
    // The phrases of core/io's messages (tst_cli_import checks that they still meet).
    static const std::pair<const char*, const char*> hints[] = {
        {"give the column map", "--columns"},
        {"set the accelerometer unit", "--acc-unit mps2|g"},
        {"check the accelerometer unit", "--acc-unit"},
        {"set the gyroscope unit to rad/s", "--gyr-unit radps"},
        {"check the gyroscope unit", "--gyr-unit"},
        {"set the time unit", "--time-unit s|ms|us"},
        {"give the sample rate", "--rate HZ"},
        {"with the sample rate given", "--rate HZ"},
    };
    for (const auto& [phrase, flag] : hints) {
        const std::size_t at = message.find(phrase);
        if (at != std::string::npos)
            message.insert(at + std::char_traits<char>::length(phrase), std::string(" (") + flag + ")");
    }
    return message;
}

ImportResult importFile(const std::string& path, const ImportOptions& options)
{
    ImportResult read = importRecording(path, options);
    if (!read.ok())
        throw BadInput{withFlagHints(read.error->text())};
    return read;
}

void printImportWarnings(const std::string& path, const std::vector<std::string>& warnings)
{
    for (const std::string& warning : warnings)
        std::cerr << "warning: " << path << ": " << withFlagHints(warning) << "\n";
}

ImportResult importInput(const CommandLine& cmd, bool echoWarnings)
{
    const ImportOptions options = importOptionsOf(cmd);
    ImportResult read = importFile(cmd.input, options);
    saveImportPresetIfAsked(cmd, options);
    if (echoWarnings)
        printImportWarnings(cmd.input, read.recording.warnings);
    return read;
}

Result estimate(const Recording& recording, const Parameters& params)
{
    // The command line writes no standard deviations (paths, steps, reports): the smoother's are not computed.
    PipelineOutput output = runPipeline(recording, params, {}, RtsSmoother::Threads::Two, {}, RtsSmoother::Variances::Skip);
    if (!output.error.empty())
        throw BadInput{recording.source + ": " + output.error};
    return std::move(output.result);
}

void writeIfAsked(const std::string& path, const std::function<void(std::ostream&)>& write)
{
    if (path.empty())
        return;
    if (std::string problem = writeFileAtomically(path, write); !problem.empty())
        throw BadInput{problem};
}

std::string describeParameters(const CommandLine& cmd)
{
    std::string text = cmd.paramsFile.empty() ? "defaults" : cmd.paramsFile;
    for (const std::string& assignment : cmd.sets)
        text += " " + assignment;
    return text;
}

std::string describeWarning(const PlausibilityWarning& warning)
{
    char span[64];
    std::snprintf(span, sizeof span, "[%.2f-%.2f s] ", warning.start_s, warning.end_s);
    return span + warning.message;
}

void printPlausibilityWarnings(const std::string& path, const std::vector<PlausibilityWarning>& warnings)
{
    for (const PlausibilityWarning& warning : warnings)
        std::cerr << path << ": warning: " << describeWarning(warning) << "\n";
}

std::string methodSet(const Parameters& params)
{
    const std::string spec = methodSetSpec(params);
    return spec.empty() ? "none" : methodSetLabel(spec);
}

}  // namespace footpath::cli
