#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace footpath {

/// Proper skew-symmetric matrix: skew(a) * b == a.cross(b). (Guo's printed eq. 9 has sign errors.)
/// Inline, like padeRotation: both run several times a sample.
inline Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d s;
    s << 0.0, -v.z(), v.y(),
         v.z(), 0.0, -v.x(),
         -v.y(), v.x(), 0.0;
    return s;
}

/// The Padé (Cayley) rotation of eq. 8 for an increment theta = w*dt:
/// (2I + S(theta)) (2I - S(theta))^-1, evaluated in closed form. It is orthogonal for any theta
/// and matches the exact rotation to third order in |theta|.
inline Eigen::Matrix3d padeRotation(const Eigen::Vector3d& theta)
{
    // With A = S(theta): (2I + A)(2I - A)^-1 = I + 4/(4 + |theta|^2) (A + A^2/2), because A and
    // (2I - A) commute and A^3 = -|theta|^2 A; and A^2 = theta theta^T - |theta|^2 I. No 3x3
    // solve, no 3x3 product.
    const double squaredAngle = theta.squaredNorm();
    const double scale = 4.0 / (4.0 + squaredAngle);
    const double half = 0.5 * scale;
    Eigen::Matrix3d r = (half * theta) * theta.transpose();
    r.diagonal().array() += 1.0 - half * squaredAngle;
    const Eigen::Vector3d a = scale * theta;
    r(0, 1) -= a.z();
    r(1, 0) += a.z();
    r(0, 2) += a.y();
    r(2, 0) -= a.y();
    r(1, 2) -= a.x();
    r(2, 1) += a.x();
    return r;
}

/// Body-to-navigation rotation C = Rz(yaw) Ry(pitch) Rx(roll), navigation frame z up.
Eigen::Matrix3d rotationFromRollPitchYaw(double roll, double pitch, double yaw);
/// Inverse of rotationFromRollPitchYaw; pitch in [-pi/2, pi/2].
Eigen::Vector3d rollPitchYaw(const Eigen::Matrix3d& bodyToNav);

/// Re-orthonormalises a rotation drifted by rounding (nearest rotation via SVD-free Gram-Schmidt).
void reorthonormalize(Eigen::Matrix3d& rotation);

}  // namespace footpath
