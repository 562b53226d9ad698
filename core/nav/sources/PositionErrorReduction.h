#pragma once

#include "nav/MeasurementSources.h"

namespace footpath {

/// Seed 002 IPER. (Being written: no measurement yet.)
class PositionErrorReductionSource : public MeasurementSource {
public:
    explicit PositionErrorReductionSource(const Parameters& params) : params_(params) {}
    const char* name() const override { return "iper"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override;

private:
    Parameters params_;
};

}  // namespace footpath
