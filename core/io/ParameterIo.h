#pragma once

#include "nav/Parameters.h"

#include <string>
#include <vector>

namespace footpath {

/// A preset file: {"format": "footpath-parameters", "version": 1, "parameters": {"name": value, ...}}.
/// Missing names keep their current value, so a preset may set only what it changes.
std::string parametersToJson(const Parameters& params);

/// Applies the JSON text to params; returns an error naming the source and the problem, or empty.
std::string parametersFromJson(const std::string& json, const std::string& sourceName, Parameters& params);

/// The parameter names nearest to a mistyped one (at most three, best first), for "did you mean".
std::vector<std::string> nearestParameterNames(const std::string& name);
/// setParameter(), with the nearest names added to the message when the name is unknown.
std::string setParameterByName(Parameters& params, const std::string& name, const std::string& text);

std::string loadParameters(const std::string& path, Parameters& params);
std::string saveParameters(const std::string& path, const Parameters& params);

}  // namespace footpath
