#include "nav/Strapdown.h"

#include "nav/Attitude.h"

namespace footpath {

Eigen::Vector3d strapdownStep(NavState& state, const Eigen::Vector3d& acc_mps2, const Eigen::Vector3d& gyr_radps,
                              double dt_s, double gravity_mps2)
{
    const Eigen::Vector3d rate = gyr_radps - state.gyroBias_radps;
    state.bodyToNav = state.bodyToNav * padeRotation(rate * dt_s);
    const Eigen::Vector3d navSpecificForce = state.bodyToNav * (acc_mps2 - state.accBias_mps2);
    const Eigen::Vector3d previousVelocity = state.velocity_mps;
    state.velocity_mps += (navSpecificForce - Eigen::Vector3d(0.0, 0.0, gravity_mps2)) * dt_s;
    // Trapezoidal position step; the printed eq. 11 uses the new velocity alone (first order in dt).
    state.position_m += 0.5 * (previousVelocity + state.velocity_mps) * dt_s;
    return navSpecificForce;
}

}  // namespace footpath
