#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Parameters.h"

namespace footpath {

/// Zheng et al. 2016's motion classification, per step: the barometric height of each stance (mean pressure
/// over the stance against the first stance's), then |h_k - h_(k-1)| < motion_level_max_m is level
/// walking; otherwise a pressure variance between the two steps above motion_elevator_var_pa2 is an
/// elevator, else stairs, up or down by the sign. Fills Step::baroHeight_m and Step::motion and the
/// summary's counts; leaves everything Unknown when the recording has no pressure.
void classifyMotion(const Recording& recording, const Parameters& params, Result& result);

/// Height difference for a pressure difference from reference_pa to pressure_pa, with the chosen
/// model (the barometric formula, or Zheng et al. 2016's linear constant).
double barometricHeight(double pressure_pa, double reference_pa, const Parameters& params);

}  // namespace footpath
