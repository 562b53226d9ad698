// The measurement sources, in the order the parameter table lists them. A new source: its
// MeasurementSource and its registry entry in nav/sources/ (as HeadingDriftReduction.cpp), its
// fields in nav/Parameters.h, and one line here.

#include "methods/MethodRegistry.h"
#include "nav/sources/BarometricHeight.h"
#include "nav/sources/HeadingDriftReduction.h"
#include "nav/sources/MagneticHeading.h"
#include "nav/sources/PositionErrorReduction.h"
#include "nav/sources/ZeroNavigationAcceleration.h"
#include "nav/sources/ZeroVelocity.h"

#include <cstring>

namespace footpath {

namespace {

std::vector<SourceMethod>& registry()
{
    static std::vector<SourceMethod> sources{
        zeroVelocityMethod(),
        zeroAngularRateMethod(),
        headingDriftReductionMethod(),
        positionErrorReductionMethod(),
        zeroNavigationAccelerationMethod(),
        barometricHeightMethod(),
        magneticHeadingMethod(),
    };
    return sources;
}

}  // namespace

const std::vector<SourceMethod>& sourceMethods()
{
    return registry();
}

const SourceMethod* findSourceMethod(const std::string& token)
{
    for (const SourceMethod& method : registry())
        if (token == method.token)
            return &method;
    return nullptr;
}

void addSourceMethod(const SourceMethod& method)
{
    registry().push_back(method);
    noteMethodRegistryChange();
}

std::vector<std::string> methodSetTokens()
{
    std::vector<std::string> tokens;
    for (const SourceMethod& method : sourceMethods())
        tokens.emplace_back(method.token);
    for (const EstimatorMethod& estimator : estimatorMethods())
        if (*estimator.setLabel)
            tokens.emplace_back(estimator.token);
    tokens.emplace_back("9state");
    tokens.emplace_back("15state");
    return tokens;
}

std::string methodSetTokensText()
{
    std::string text;
    for (const std::string& token : methodSetTokens())
        text += (text.empty() ? "" : ", ") + token;
    return text;
}

}  // namespace footpath
