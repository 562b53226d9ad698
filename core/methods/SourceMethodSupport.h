#pragma once

// The pieces a source's registry entry is written with: a switch in the parameters turns the
// source on, and the source is built from the parameters when it is on.

#include "methods/MethodRegistry.h"
#include "nav/MeasurementSources.h"

#include <memory>

namespace footpath::methods {

template <bool Parameters::*Switch>
bool switchIsOn(const Parameters& params)
{
    return params.*Switch;
}

template <bool Parameters::*Switch>
void setSwitch(Parameters& params, bool on)
{
    params.*Switch = on;
}

template <class Source, bool Parameters::*Switch>
std::unique_ptr<MeasurementSource> makeWhenOn(const Parameters& params)
{
    if (!(params.*Switch))
        return nullptr;
    return std::make_unique<Source>(params);
}

}  // namespace footpath::methods
