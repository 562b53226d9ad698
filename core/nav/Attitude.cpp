#include "nav/Attitude.h"

#include <algorithm>
#include <cmath>

namespace footpath {

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
