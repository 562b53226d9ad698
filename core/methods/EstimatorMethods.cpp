// The estimators, in the order of the `estimator` choice (presets store the token; append).

#include "methods/MethodRegistry.h"

#include <QtGlobal>

namespace footpath {

const std::vector<EstimatorMethod>& estimatorMethods()
{
    static const std::vector<EstimatorMethod> estimators{
        {"ekf", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Kalman filter"), "", ""},
        {"feliz", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Feliz de-drift (no filter)"), "Feliz",
         QT_TRANSLATE_NOOP("footpath::MotionLanes", "Feliz integrator")},
        {"rts", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Kalman filter + RTS smoother"), "RTS smoother", ""},
    };
    return estimators;
}

}  // namespace footpath
