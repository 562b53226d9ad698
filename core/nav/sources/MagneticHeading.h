#pragma once

#include "nav/MeasurementSources.h"

namespace footpath {

/// Magnetometer heading during stance. (Being written: no measurement yet.)
class MagneticHeadingSource : public MeasurementSource {
public:
    explicit MagneticHeadingSource(const Parameters& params) : params_(params) {}
    const char* name() const override { return "mag"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override;

private:
    Parameters params_;
};

}  // namespace footpath
