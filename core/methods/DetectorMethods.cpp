// The stance detectors, in the order of the `detector` choice (presets store the token; append).
// A new detector: its statistic in its own file (normalised by the sensor noise, as in
// detect/StatisticDetectors.h) and one line here.

#include "detect/StatisticDetectors.h"
#include "methods/MethodRegistry.h"

#include <QtGlobal>

#include <atomic>

namespace footpath {

namespace {

std::vector<DetectorMethod>& registry()
{
    // token, label, statistic, reads the accelerometer, reads the gyroscope
    static std::vector<DetectorMethod> detectors{
        {"c1c2c3", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C1/C2/C3 (Guo 2015)"), nullptr, true, true},
        {"shoe", QT_TRANSLATE_NOOP("footpath::ParameterFields", "SHOE (GLRT)"), shoeStatistic, true, true},
        {"ared", QT_TRANSLATE_NOOP("footpath::ParameterFields", "ARED (angular rate energy)"), aredStatistic, false,
         true},
        {"amvd", QT_TRANSLATE_NOOP("footpath::ParameterFields", "AMVD (acceleration variance)"), amvdStatistic, true,
         false},
        {"mbgtd", QT_TRANSLATE_NOOP("footpath::ParameterFields", "MBGTD (graph theoretic)"), mbgtdStatistic, true,
         false},
    };
    return detectors;
}


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
