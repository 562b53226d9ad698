#pragma once

#include "methods/MethodRegistry.h"
#include "nav/MeasurementSources.h"

#include <Eigen/Core>

namespace footpath {

/// ZUNA (zero unrefined acceleration update) of the five-method EKF paper. The mean specific force of the stance
/// samples in the first zuna_reference_s seconds is the reference: its magnitude is gravity as this
/// sensor measures it. At mid-stance - a stance run that has lasted zuna_min_stance_s and whose
/// detector statistic is at least zuna_margin_dec decades below the threshold, the paper's
/// "smaller thresholds and longer time" - the foot does not accelerate, so
///   z = C_est (f - b_a,est) - [0, 0, |f_ref|] = -S(g_ref) dphi + C_est da_b
/// (dphi = estimate - truth, da_b = truth - estimate): the horizontal rows observe the tilt
/// error, all three the accelerometer bias (only in the 15-state filter).
///
/// The paper compares in the body frame, m = f_k - f_ref, with H selecting the accelerometer bias
/// alone. That equals the form above when the foot rests in the same orientation as at the start
/// (flat on a level floor); on stairs, a slope or a foot set down at another angle it would call
/// the changed direction of gravity a bias. The navigation-frame form holds for any resting
/// orientation and also corrects the tilt, so it is used here.
class ZeroNavigationAccelerationSource : public MeasurementSource {
public:
    explicit ZeroNavigationAccelerationSource(const Parameters& params) : params_(params) {}
    const char* name() const override { return "zuna"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override;
    void finish(double endTime_s, std::vector<MethodNote>& notes) override;

private:
    /// Collects the reference while inside the first zuna_reference_s; false until it is formed.
    bool collectReference(const SourceContext& context);
    bool isMidStance(const SourceContext& context);
    void update(ErrorStateEkf& ekf, const Eigen::Vector3d& specificForce_mps2) const;

    Parameters params_;
    bool started_ = false;
    double startTime_s_ = 0.0;
    Eigen::Vector3d referenceSum_ = Eigen::Vector3d::Zero();
    std::size_t referenceSamples_ = 0;
    std::size_t windowSamples_ = 0;
    enum class Reference { Collecting, Ready, Missing } reference_ = Reference::Collecting;
    double referenceGravity_mps2 = 0.0;
    bool inStance_ = false;
    double stanceStart_s_ = 0.0;
    std::size_t updates_ = 0;
};

/// Its entry in the method registry (core/methods/MethodRegistry.h).
SourceMethod zeroNavigationAccelerationMethod();

}  // namespace footpath
