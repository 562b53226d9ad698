// libFuzzer target: the import preset JSON reader; a preset it accepts must round-trip through
// the writer and be applicable to import options.

#include "io/ImportPresets.h"

#include "FuzzInput.h"

#include <cstdlib>

using namespace footpath;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    ImportPreset preset;
    if (!importPresetFromJson(fuzz::asText(data, size), "fuzz.json", preset).empty())
        return 0;
    ImportPreset again;
    if (!importPresetFromJson(importPresetToJson(preset), "written.json", again).empty()
        || importPresetToJson(again) != importPresetToJson(preset))
        std::abort();
    ImportOptions options;
    applyImportPreset(preset, options);
    return 0;
}
