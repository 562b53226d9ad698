// The stance detectors, in the order of the `detector` choice (presets store the token; append).
// A new detector: its statistic in its own file (normalised by the sensor noise, as in
// detect/StatisticDetectors.h) and one line here.

#include "detect/StatisticDetectors.h"
#include "methods/MethodRegistry.h"

#include <QtGlobal>

#include <atomic>

namespace footpath {

namespace {

#define FP_LABEL(text) QT_TRANSLATE_NOOP("footpath::ParameterFields", text)

std::vector<DetectorMethod>& registry()
{
    static std::vector<DetectorMethod> detectors{
        // token     label                                    statistic       reads acc, gyr
        {"c1c2c3", FP_LABEL("C1/C2/C3 (Guo 2015)"), nullptr, true, true},
        {"shoe", FP_LABEL("SHOE (GLRT)"), shoeStatistic, true, true},
        {"ared", FP_LABEL("ARED (angular rate energy)"), aredStatistic, false, true},
        {"amvd", FP_LABEL("AMVD (acceleration variance)"), amvdStatistic, true, false},
        {"mbgtd", FP_LABEL("MBGTD (graph theoretic)"), mbgtdStatistic, true, false},
    };
    return detectors;
}

#undef FP_LABEL

}  // namespace

const std::vector<DetectorMethod>& detectorMethods()
{
    return registry();
}

const DetectorMethod& chosenDetector(const Parameters& params)
{
    const std::vector<DetectorMethod>& detectors = registry();
    const auto index = static_cast<std::size_t>(params.detector);
    return params.detector >= 0 && index < detectors.size() ? detectors[index] : detectors.front();
}

void addDetectorMethod(const DetectorMethod& method)
{
    registry().push_back(method);
    noteMethodRegistryChange();
}

namespace {
std::atomic<int> generation{0};
}  // namespace

int methodRegistryGeneration()
{
    return generation.load();
}

void noteMethodRegistryChange()
{
    ++generation;
}

}  // namespace footpath
