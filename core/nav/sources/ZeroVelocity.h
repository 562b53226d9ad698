#pragma once

#include "methods/MethodRegistry.h"
#include "nav/MeasurementSources.h"

namespace footpath {

/// Guo 2015 eq. 34-35: during stance the velocity is zero (ZUPT) and the bias-compensated angular
/// rate is zero (ZARU, which needs the gyro-bias states of the 15-state filter), as enabled.
class ZeroVelocitySource : public MeasurementSource {
public:
    explicit ZeroVelocitySource(const Parameters& params) : zupt_(params.use_zupt), zaru_(params.use_zaru) {}
    const char* name() const override { return "zupt"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override;

private:
    bool zupt_;
    bool zaru_;
};

/// Its entry in the method registry (core/methods/MethodRegistry.h).
SourceMethod zeroVelocityMethod();
/// Its entry in the method registry (core/methods/MethodRegistry.h).
SourceMethod zeroAngularRateMethod();

}  // namespace footpath
