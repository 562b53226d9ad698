#pragma once

#include "nav/Parameters.h"

#include <cmath>

namespace footpath {

/// Sets a field from the number the GUI passes around (flags as 0/1, choices as their index): the
/// inverse of parameterValue().
inline void setParameterValue(Parameters& params, const ParameterField& field, double value)
{
    switch (field.kind) {
    case ParameterField::Kind::Real:
        params.*field.real = value;
        return;
    case ParameterField::Kind::Flag:
        params.*field.flag = value != 0.0;
        return;
    case ParameterField::Kind::Choice:
        params.*field.choice = static_cast<int>(std::lround(value));
        return;
    }
}

}  // namespace footpath
