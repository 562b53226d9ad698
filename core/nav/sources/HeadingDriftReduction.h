#pragma once

#include "nav/MeasurementSources.h"

namespace footpath {

/// Seed 002 HDR. (Being written: no measurement yet.)
class HeadingDriftReductionSource : public MeasurementSource {
public:
    explicit HeadingDriftReductionSource(const Parameters& params) : params_(params) {}
    const char* name() const override { return "hdr"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override;

private:
    Parameters params_;
};

}  // namespace footpath
