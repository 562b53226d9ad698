#pragma once

#include "nav/MeasurementSources.h"

namespace footpath {

/// Seed 004: the barometric height at each stance. (Being written: no measurement yet.)
class BarometricHeightSource : public MeasurementSource {
public:
    explicit BarometricHeightSource(const Parameters& params) : params_(params) {}
    const char* name() const override { return "baro"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override;

private:
    Parameters params_;
};

}  // namespace footpath
