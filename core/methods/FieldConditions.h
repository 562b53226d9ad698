#pragma once

// The conditions of the fields that belong to no single measurement source: the detector's and
// the filter's. A source keeps its own conditions in its file.

#include "nav/Parameters.h"

namespace footpath::conditions {

extern const FieldCondition paperDetector;          ///< detector c1c2c3
extern const FieldCondition statisticDetectors;     ///< a detector with a statistic (SHOE, ARED, ...)
extern const FieldCondition detectorAccelerometer;  ///< a statistic that reads the accelerometer
extern const FieldCondition detectorGyroscope;      ///< a statistic that reads the gyroscope
extern const FieldCondition fixedThreshold;         ///< a statistic detector with zv_adaptive off
extern const FieldCondition adaptiveThreshold;      ///< a statistic detector with zv_adaptive on
extern const FieldCondition biasStates;             ///< the 15-state filter
extern const FieldCondition zaru;                   ///< ZARU: the gyro bias states of the 15-state filter

}  // namespace footpath::conditions
