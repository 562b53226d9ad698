#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Pipeline.h"
#include "nav/Parameters.h"

namespace footpath {

/// Feliz, Zalama, Garcia-Bermejo 2009 (seed 003): no Kalman filter. Fills result's per-sample
/// state from the stance flags already in result.flags. (Being written.)
bool runFelizIntegrator(const Recording& recording, const Parameters& params, const ProgressCallback& progress,
                        Result& result);

}  // namespace footpath
