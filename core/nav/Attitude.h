#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace footpath {

/// Proper skew-symmetric matrix: skew(a) * b == a.cross(b). (Guo's printed eq. 9 has sign errors.)
Eigen::Matrix3d skew(const Eigen::Vector3d& v);

/// The Padé (Cayley) rotation of eq. 8 for an increment theta = w*dt:
/// (2I + S(theta)) (2I - S(theta))^-1, evaluated in closed form. It is orthogonal for any theta
/// and matches the exact rotation to third order in |theta|.
Eigen::Matrix3d padeRotation(const Eigen::Vector3d& theta);

/// Body-to-navigation rotation C = Rz(yaw) Ry(pitch) Rx(roll), navigation frame z up.
Eigen::Matrix3d rotationFromRollPitchYaw(double roll, double pitch, double yaw);
/// Inverse of rotationFromRollPitchYaw; pitch in [-pi/2, pi/2].
Eigen::Vector3d rollPitchYaw(const Eigen::Matrix3d& bodyToNav);

/// Re-orthonormalises a rotation drifted by rounding (nearest rotation via SVD-free Gram-Schmidt).
void reorthonormalize(Eigen::Matrix3d& rotation);

}  // namespace footpath
