#pragma once

#include "methods/MethodRegistry.h"
#include "nav/MeasurementSources.h"
#include "nav/sources/SourceSupport.h"

namespace footpath {

/// Magnetometer heading during stance (the future work of Guo et al. 2015). The field's norm and dip
/// angle during the alignment period are the reference of an undisturbed field; at each stance
/// whose field matches them (within mag_norm_tolerance and mag_dip_tolerance_rad) the
/// tilt-compensated heading (magneticHeading(), the alignment's convention) is a yaw measurement.
/// Near steel or electronics the field changes norm or dip and the stance is skipped; the skipped
/// spans go into the notes with the measured figures.
class MagneticHeadingSource : public MeasurementSource {
public:
    explicit MagneticHeadingSource(const Parameters& params) : params_(params) {}
    const char* name() const override { return "mag"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override;
    void finish(double endTime_s, std::vector<MethodNote>& notes) override;

private:
    struct FieldSums {
        double norm = 0.0;
        double dip_rad = 0.0;
        int count = 0;
        void add(double n, double d) { norm += n; dip_rad += d; ++count; }
    };
    void collectReference(const ErrorStateEkf& ekf, const SourceContext& context);
    void measure(ErrorStateEkf& ekf, const SourceContext& context);

    Parameters params_;
    sources::StanceTrigger trigger_{0.03};
    sources::SpanNotes notes_{"mag"};
    double firstTime_s_ = std::nan("");
    bool sawMagnetometer_ = false;
    FieldSums stanceReference_;
    FieldSums anyReference_;  ///< when the alignment period has no stance
    bool referenceReady_ = false;
    double referenceNorm_ = 0.0;
    double referenceDip_rad_ = 0.0;
};

/// Its entry in the method registry (core/methods/MethodRegistry.h).
SourceMethod magneticHeadingMethod();

}  // namespace footpath
