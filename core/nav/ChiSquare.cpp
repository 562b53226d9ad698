#include "nav/ChiSquare.h"

#include <cmath>

namespace footpath {

namespace {

/// The regularised lower incomplete gamma function P(a, x), by its series (Abramowitz and Stegun
/// 6.5.29) below a + 1 and by the continued fraction of Q = 1 - P above (Numerical Recipes'
/// Lentz form), where the series would need many terms.
double lowerGammaSeries(double a, double x)
{
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n < 1000 && std::abs(term) > std::abs(sum) * 1e-16; ++n) {
        term *= x / (a + n);
        sum += term;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

double upperGammaFraction(double a, double x)
{
    constexpr double kTiny = 1e-300;
    double b = x + 1.0 - a;
    double c = 1.0 / kTiny;
    double d = 1.0 / b;
    double h = d;
    for (int i = 1; i < 1000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        d = std::abs(d) < kTiny ? kTiny : d;
        c = b + an / c;
        c = std::abs(c) < kTiny ? kTiny : c;
        d = 1.0 / d;
        const double step = d * c;
        h *= step;
        if (std::abs(step - 1.0) < 1e-16)
            break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

double regularisedLowerGamma(double a, double x)
{
    if (x <= 0.0)
        return 0.0;
    return x < a + 1.0 ? lowerGammaSeries(a, x) : 1.0 - upperGammaFraction(a, x);
}

}  // namespace

double chiSquareProbability(double x, int degrees)
{
    return regularisedLowerGamma(0.5 * degrees, 0.5 * x);
}

double chiSquareQuantile(double probability, int degrees)
{
    double low = 0.0;
    double high = 1.0;
    while (chiSquareProbability(high, degrees) < probability)
        high *= 2.0;
    for (int i = 0; i < 200 && high - low > 1e-12 * high; ++i) {
        const double middle = 0.5 * (low + high);
        (chiSquareProbability(middle, degrees) < probability ? low : high) = middle;
    }
    return 0.5 * (low + high);
}

}  // namespace footpath
