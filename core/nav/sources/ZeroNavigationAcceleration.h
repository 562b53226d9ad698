#pragma once

#include "nav/MeasurementSources.h"

namespace footpath {

/// Seed 002 ZUNA. (Being written: no measurement yet.)
class ZeroNavigationAccelerationSource : public MeasurementSource {
public:
    explicit ZeroNavigationAccelerationSource(const Parameters& params) : params_(params) {}
    const char* name() const override { return "zuna"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override;

private:
    Parameters params_;
};

}  // namespace footpath
