#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Pipeline.h"
#include "nav/Parameters.h"

namespace footpath {

/// Feliz, Zalama and Garcia-Bermejo 2009: dead reckoning without a Kalman filter.
///
/// Attitude: the initial alignment, then the integrated gyro (the EKF's Pade step), re-levelled
/// from the accelerometer at every stance. Velocity: C f - g integrated and held at zero during
/// stance; the velocity a swing reaches at the next stance start is the drift of that swing and is
/// removed linearly in time over the swing (their Fig. 8), so the velocity is exactly zero at every
/// stance. Position: the de-drifted velocity integrated (trapezoid).
///
/// Offline only: a swing's correction needs the stance that ends it. A final swing that no stance
/// ends is left as integrated (and noted in result.methodNotes).
///
/// Fills result's per-sample vectors (time, position, velocity, roll/pitch/yaw; the bias vectors
/// hold zeros) from the stance flags already in result.flags. Returns false if progress cancelled.
bool runFelizIntegrator(const Recording& recording, const Parameters& params, const ProgressCallback& progress,
                        Result& result);

}  // namespace footpath
