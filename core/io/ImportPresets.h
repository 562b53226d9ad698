#pragma once

#include "io/Import.h"

#include <string>
#include <vector>

namespace footpath {

/// How to read one kind of file that does not describe itself (a headerless logger's text, say):
/// saved under a name so the next file of that kind opens with `--import-preset NAME` or a click.
struct ImportPreset {
    std::string name;
    std::string format;                  ///< empty: detect
    std::vector<std::string> columnMap;  ///< roles, as --columns
    AccUnit accUnit = AccUnit::Unknown;
    GyrUnit gyrUnit = GyrUnit::Unknown;
    TimeUnit timeUnit = TimeUnit::Unknown;
    double rate_hz = 0.0;
};

/// {"format": "footpath-import-preset", "version": 1, "name": ..., "columns": [...], "acc_unit": "g", ...}
std::string importPresetToJson(const ImportPreset& preset);
/// Returns an error naming the source and the problem, or empty.
std::string importPresetFromJson(const std::string& json, const std::string& sourceName, ImportPreset& preset);

/// Where presets live: $FOOTPATH_IMPORT_PRESETS if set, else <config dir>/footpath/import-presets.
std::string importPresetDirectory();
/// Writes <directory>/<name>.json (atomically); returns an error or empty.
std::string saveImportPreset(const ImportPreset& preset, const std::string& directory = importPresetDirectory());
/// Loads a preset by file path, or by name from the directory; returns an error or empty.
std::string loadImportPreset(const std::string& nameOrPath, ImportPreset& preset,
                             const std::string& directory = importPresetDirectory());
/// Every readable preset in the directory, by name.
std::vector<ImportPreset> listImportPresets(const std::string& directory = importPresetDirectory());

/// Fills what the options leave open from the preset (the options' own settings win).
void applyImportPreset(const ImportPreset& preset, ImportOptions& options);

/// Parses "mps2"/"g", "radps"/"degps", "s"/"ms"/"us" as the CLI and presets spell them.
bool parseAccUnit(const std::string& text, AccUnit& unit);
bool parseGyrUnit(const std::string& text, GyrUnit& unit);
bool parseTimeUnit(const std::string& text, TimeUnit& unit);

}  // namespace footpath
