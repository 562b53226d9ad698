#include "methods/FieldConditions.h"

#include "methods/MethodRegistry.h"

#include <QtGlobal>

namespace footpath::conditions {

// The reasons keep the parameter panel's translation context, where they were translated first.

namespace {

bool hasStatistic(const Parameters& p)
{
    return chosenDetector(p).statistic != nullptr;
}

}  // namespace

const FieldCondition paperDetector{
    "paper_detector", [](const Parameters& p) { return !hasStatistic(p); },
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: only the C1/C2/C3 detector uses it, and %1 is chosen.")};

const FieldCondition statisticDetectors{
    "statistic_detectors", hasStatistic,
    QT_TRANSLATE_NOOP("footpath::ParameterPanel",
                      "Not used: the statistic detectors (SHOE, ARED, AMVD, MBGTD) use it, and C1/C2/C3 is chosen.")};

const FieldCondition detectorAccelerometer{
    "detector_accelerometer", [](const Parameters& p) { return chosenDetector(p).readsAccelerometer; },
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: ARED looks at the gyroscope alone."),
    &statisticDetectors};

const FieldCondition detectorGyroscope{
    "detector_gyroscope", [](const Parameters& p) { return chosenDetector(p).readsGyroscope; },
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: %1 looks at the accelerometer alone."),
    &statisticDetectors};

const FieldCondition fixedThreshold{
    "fixed_threshold", [](const Parameters& p) { return !p.zv_adaptive; },
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: the threshold is adaptive (zv_adaptive is on)."),
    &statisticDetectors};

const FieldCondition adaptiveThreshold{
    "adaptive_threshold", [](const Parameters& p) { return p.zv_adaptive; },
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: the threshold is fixed (zv_adaptive is off)."),
    &statisticDetectors};

const FieldCondition biasStates{
    "bias_states", [](const Parameters& p) { return p.filterStates() == FilterStates::Fifteen; },
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: the 9-state filter has no bias states.")};

// ZARU measures the gyro bias; with the bias states held at zero it corrects nothing.
const FieldCondition zaru{
    "zaru", [](const Parameters& p) { return p.filterStates() == FilterStates::Fifteen; },
    QT_TRANSLATE_NOOP("footpath::ParameterPanel",
                      "Not used: ZARU corrects the gyro bias, which the 9-state filter does not estimate.")};

}  // namespace footpath::conditions
