#pragma once

// The rotation of the nav-frame rate to the axis right of the motion, exact and with cheap sine and
// cosine polynomials: the gait events take the sagittal axis's sign from a sum of these
// (GaitEvents.cpp, rateAgreesWithMotion). Inline: they run once a moving sample. In a header of
// their own so that tst_gaitevents checks the approximation against the exact rotation.

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace footpath {

/// sin and cos of an angle of a few turns at most, within 2e-9: Taylor polynomials on the angle
/// reduced to [-pi/4, pi/4] (the first omitted terms, (pi/4)^11/11! and (pi/4)^12/12!, bound the
/// error). A fifth of libm's cost, for a sum whose sign is all that is wanted (see
/// rateAgreesWithMotion). NaN for an angle beyond a thousand radians, which no attitude angle is.
inline void approximateSinCos(double x, double& sine, double& cosine)
{
    if (!(std::abs(x) <= 1e3)) {
        sine = cosine = std::numeric_limits<double>::quiet_NaN();
        return;
    }
    constexpr double kHalfPiHigh = 1.5707963267948966, kHalfPiLow = 6.123233995736766e-17;
    const auto quadrant = static_cast<long>(x * (2.0 / M_PI) + (x >= 0.0 ? 0.5 : -0.5));
    const double r = (x - static_cast<double>(quadrant) * kHalfPiHigh) - static_cast<double>(quadrant) * kHalfPiLow;
    const double r2 = r * r;
    const double s = r + r * r2 * (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040 + r2 * (1.0 / 362880))));
    const double c = 1.0 + r2 * (-0.5 + r2 * (1.0 / 24 + r2 * (-1.0 / 720 + r2 * (1.0 / 40320 + r2 * (-1.0 / 3628800)))));
    switch (quadrant & 3) {
    case 0: sine = s; cosine = c; break;
    case 1: sine = c; cosine = -s; break;
    case 2: sine = -s; cosine = -c; break;
    default: sine = -c; cosine = s; break;
    }
}

/// The rate about the axis to the right of the motion (v x up) from the body rate and the
/// body-to-navigation rotation C: (C w) . (v x up).
inline double rateRightOfMotion(const Eigen::Matrix3d& bodyToNav, const Eigen::Vector3d& gyr, const Eigen::Vector3d& velocity)
{
    const Eigen::Vector3d rate_n = bodyToNav * gyr;
    const Eigen::Vector3d rightOfMotion = velocity.cross(Eigen::Vector3d::UnitZ());
    return rate_n.dot(rightOfMotion);
}

/// The same with the rotation from approximateSinCos: each entry of C (sums of two products of
/// three sines or cosines) is then within 12e-9 of the exact one.
inline double approximateRateRightOfMotion(const Eigen::Vector3d& rpy, const Eigen::Vector3d& gyr, const Eigen::Vector3d& velocity)
{
    double sr, cr, sp, cp, sy, cy;
    approximateSinCos(rpy.x(), sr, cr);
    approximateSinCos(rpy.y(), sp, cp);
    approximateSinCos(rpy.z(), sy, cy);
    // The nav-frame rate's horizontal part: rows 0 and 1 of rotationFromRollPitchYaw times gyr.
    const double levelX = cp * gyr.x() + sp * (sr * gyr.y() + cr * gyr.z());
    const double levelY = cr * gyr.y() - sr * gyr.z();
    const double east = cy * levelX - sy * levelY, north = sy * levelX + cy * levelY;
    return velocity.y() * east - velocity.x() * north;
}

}  // namespace footpath
