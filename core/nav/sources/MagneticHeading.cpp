#include "nav/sources/MagneticHeading.h"

#include "methods/SourceMethodSupport.h"
#include "nav/Alignment.h"
#include "nav/Attitude.h"
#include "nav/ErrorStateEkf.h"

#include <QtGlobal>

#include <cmath>
#include <cstdio>

namespace footpath {

namespace {

/// Dip (inclination) of the field below the horizontal, from the navigation-frame field (z up).
double dipAngle(const Eigen::Vector3d& field_n)
{
    return std::atan2(-field_n.z(), field_n.head<2>().norm());
}

}  // namespace

void MagneticHeadingSource::collectReference(const ErrorStateEkf& ekf, const SourceContext& context)
{
    const Eigen::Vector3d field_n = ekf.state().bodyToNav * context.sample.mag;
    anyReference_.add(field_n.norm(), dipAngle(field_n));
    if (context.flags.stance)
        stanceReference_.add(field_n.norm(), dipAngle(field_n));
}

void MagneticHeadingSource::apply(ErrorStateEkf& ekf, const SourceContext& context)
{
    const ImuSample& sample = context.sample;
    if (std::isnan(firstTime_s_))
        firstTime_s_ = sample.time_s;
    if (!sample.hasMag())
        return;
    sawMagnetometer_ = true;
    if (!referenceReady_) {
        if (sample.time_s - firstTime_s_ < params_.alignment_s) {
            collectReference(ekf, context);
            return;
        }
        const FieldSums& sums = stanceReference_.count > 0 ? stanceReference_ : anyReference_;
        if (sums.count == 0)
            return;  // the first magnetometer sample came after the alignment: nothing to compare with
        referenceNorm_ = sums.norm / sums.count;
        referenceDip_rad_ = sums.dip_rad / sums.count;
        referenceReady_ = referenceNorm_ > 0.0;
    }
    if (referenceReady_ && trigger_.fires(context.flags.stance, sample.time_s))
        measure(ekf, context);
}

void MagneticHeadingSource::measure(ErrorStateEkf& ekf, const SourceContext& context)
{
    const ImuSample& sample = context.sample;
    const Eigen::Vector3d field_n = ekf.state().bodyToNav * sample.mag;
    const double normRatio = field_n.norm() / referenceNorm_;
    const double dipDeviation = dipAngle(field_n) - referenceDip_rad_;
    const bool normOk = std::abs(normRatio - 1.0) <= params_.mag_norm_tolerance;
    const bool dipOk = std::abs(dipDeviation) <= params_.mag_dip_tolerance_rad;
    if (!normOk || !dipOk) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "skipped: disturbed field (norm %.2f x the alignment's, dip %+.1f deg from it; "
                      "tolerance %.0f %%, %.1f deg)",
                      normRatio, dipDeviation * 180.0 / M_PI, params_.mag_norm_tolerance * 100.0,
                      params_.mag_dip_tolerance_rad * 180.0 / M_PI);
        notes_.mark(sample.time_s, "disturbed", context.notes);
        notes_.detail(text);
        return;
    }
    notes_.mark(sample.time_s, {}, context.notes);
    const Eigen::Vector3d rpy = rollPitchYaw(ekf.state().bodyToNav);
    const double measuredYaw = magneticHeading(sample.mag, rpy.x(), rpy.y(), params_.declination_rad);
    sources::updateYaw(ekf, rpy.z() - measuredYaw, params_.r_mag_rad);
}

void MagneticHeadingSource::finish(double endTime_s, std::vector<MethodNote>& notes)
{
    if (!sawMagnetometer_) {
        const double start = std::isnan(firstTime_s_) ? endTime_s : firstTime_s_;
        notes.push_back(MethodNote{"mag", start, endTime_s, "not applied: the recording has no magnetometer"});
        return;
    }
    notes_.finish(endTime_s, notes);
}


// ---- registry entry (core/methods/SourceMethods.cpp lists it) ----------------------------

namespace {

const FieldCondition magOn{"mag", methods::switchIsOn<&Parameters::use_mag_heading>,
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: the magnetometer heading update is off (use_mag_heading).")};

}  // namespace

SourceMethod magneticHeadingMethod()
{
    const auto fields = [] {
        using P = Parameters;
        return std::vector<ParameterField>{
            flagField("use_mag_heading", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer heading"),
                 &P::use_mag_heading,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Magnetometer heading during stance, skipped near steel"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            realField("r_mag_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer heading std"), &P::r_mag_rad,
                 1e-6, 3.0, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer: R of the heading, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer"), &magOn),
            realField("mag_norm_tolerance", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Field strength tolerance"),
                 &P::mag_norm_tolerance, 0.0, 1.0, "x",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Magnetometer: |m| within this fraction of its value at alignment"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer"), &magOn),
            realField("mag_dip_tolerance_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Dip angle tolerance"),
                 &P::mag_dip_tolerance_rad, 0.0, 1.6, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Magnetometer: dip within this of its value at alignment"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer"), &magOn),
        };
    };
    return {"mag", "magnetometer", "use_mag_heading", methods::switchIsOn<&Parameters::use_mag_heading>, methods::setSwitch<&Parameters::use_mag_heading>,
            methods::makeWhenOn<MagneticHeadingSource, &Parameters::use_mag_heading>, fields, 40};
}

}  // namespace footpath
