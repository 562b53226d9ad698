#include "nav/MotionClasses.h"

#include <cmath>

namespace footpath {

const char* motionClassName(MotionClass motion)
{
    switch (motion) {
    case MotionClass::Unknown:
        return "unknown";
    case MotionClass::Level:
        return "level";
    case MotionClass::StairsUp:
        return "stairs_up";
    case MotionClass::StairsDown:
        return "stairs_down";
    case MotionClass::ElevatorUp:
        return "elevator_up";
    case MotionClass::ElevatorDown:
        return "elevator_down";
    }
    return "unknown";
}

double barometricHeight(double pressure_pa, double reference_pa, const Parameters& params)
{
    if (params.barometerModel() == BarometerModel::Linear)
        return params.baro_linear_m_per_pa * (reference_pa - pressure_pa);
    // International barometric formula, relative to the reference pressure (ISA troposphere).
    return 44330.8 * (1.0 - std::pow(pressure_pa / reference_pa, 1.0 / 5.25588));
}

void classifyMotion(const Recording& /*recording*/, const Parameters& /*params*/, Result& /*result*/)
{
}

}  // namespace footpath
