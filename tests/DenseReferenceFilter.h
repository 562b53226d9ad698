#pragma once

// The offline estimator written the textbook way, with dense matrices: the reference that the
// structured ErrorStateEkf and RtsSmoother must reproduce (tst_densereference) and beat in speed
// (bench_pipeline's BM_DenseReference). Small and readable rather than fast; not part of core.

#include "Recording.h"
#include "nav/Parameters.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace footpath {

struct DenseReferenceOutput {
    std::vector<Eigen::Vector3d> position_m;  ///< per sample, smoothed when params choose the smoother
    std::vector<Eigen::Vector3d> velocity_mps;
    std::string error;  ///< empty when the parameters are ones the reference implements
};

/// Eq. 33 as printed, the Joseph form (I - K H) P (I - K H)^T + K R K^T for the gain K, with R the
/// diagonal r: the reference's covariance update, and what tests hold the structured one to.
template <class Covariance>
Covariance josephForm(const Covariance& p, const Eigen::MatrixXd& gain, const Eigen::MatrixXd& h,
                      const Eigen::VectorXd& r)
{
    const Covariance iMinusKh = Covariance::Identity(p.rows(), p.cols()) - gain * h;
    return iMinusKh * p * iMinusKh.transpose() + gain * r.asDiagonal() * gain.transpose();
}

/// The same detector and alignment as runPipeline (core's), then: the error-state EKF of the running
/// states (9, or 15 with biases) with Phi P Phi^T + Q, the ZUPT/ZARU update as
/// K = P H^T (H P H^T + R)^-1 and the Joseph form, all as dense N x N products; then, for the
/// smoother, the Rauch-Tung-Striebel gain G = P(k|k) Phi^T P(k+1|k)^-1 by a dense solve. Only the
/// ZUPT/ZARU source and the Ekf and Smoother estimators are implemented.
DenseReferenceOutput runDenseReference(const Recording& recording, const Parameters& params);

}  // namespace footpath
