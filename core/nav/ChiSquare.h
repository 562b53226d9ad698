#pragma once

namespace footpath {

/// The value a chi-square variable with `degrees` degrees of freedom stays below with the given
/// probability (0 < probability < 1, degrees >= 1): the innovation gate's threshold on
/// y^T S^-1 y. Accurate to about 1e-9 relative (bisection on the regularised gamma function).
double chiSquareQuantile(double probability, int degrees);

/// P(X <= x) for a chi-square variable with `degrees` degrees of freedom.
double chiSquareProbability(double x, int degrees);

}  // namespace footpath
