#pragma once

#include "nav/Parameters.h"

#include <string>

namespace footpath {

/// A preset file: {"format": "footpath-parameters", "version": 1, "parameters": {"name": value, ...}}.
/// Missing names keep their current value, so a preset may set only what it changes.
std::string parametersToJson(const Parameters& params);

/// Applies the JSON text to params; returns an error naming the source and the problem, or empty.
std::string parametersFromJson(const std::string& json, const std::string& sourceName, Parameters& params);

std::string loadParameters(const std::string& path, Parameters& params);
std::string saveParameters(const std::string& path, const Parameters& params);

}  // namespace footpath
