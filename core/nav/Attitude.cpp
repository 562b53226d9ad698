#include "nav/Attitude.h"

#include <algorithm>
#include <cmath>

namespace footpath {

Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d s;
    s << 0.0, -v.z(), v.y(),
         v.z(), 0.0, -v.x(),
         -v.y(), v.x(), 0.0;
    return s;
}

Eigen::Matrix3d padeRotation(const Eigen::Vector3d& theta)
{
    // With A = S(theta): (2I + A)(2I - A)^-1 = I + 4/(4 + |theta|^2) (A + A^2/2), because A and
    // (2I - A) commute and A^3 = -|theta|^2 A. This avoids a 3x3 solve on every sample.
    const Eigen::Matrix3d a = skew(theta);
    const double scale = 4.0 / (4.0 + theta.squaredNorm());
    return Eigen::Matrix3d::Identity() + scale * (a + 0.5 * a * a);
}

Eigen::Matrix3d rotationFromRollPitchYaw(double roll, double pitch, double yaw)
{
    const double cr = std::cos(roll), sr = std::sin(roll);
    const double cp = std::cos(pitch), sp = std::sin(pitch);
    const double cy = std::cos(yaw), sy = std::sin(yaw);
    Eigen::Matrix3d c;
    c << cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,
         sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,
         -sp, cp * sr, cp * cr;
    return c;
}

Eigen::Vector3d rollPitchYaw(const Eigen::Matrix3d& c)
{
    const double pitch = std::asin(std::clamp(-c(2, 0), -1.0, 1.0));
    return {std::atan2(c(2, 1), c(2, 2)), pitch, std::atan2(c(1, 0), c(0, 0))};
}

void reorthonormalize(Eigen::Matrix3d& rotation)
{
    Eigen::Vector3d x = rotation.col(0).normalized();
    Eigen::Vector3d y = rotation.col(1);
    y = (y - x.dot(y) * x).normalized();
    rotation.col(0) = x;
    rotation.col(1) = y;
    rotation.col(2) = x.cross(y);
}

}  // namespace footpath
