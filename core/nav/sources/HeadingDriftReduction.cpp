#include "nav/sources/HeadingDriftReduction.h"

#include "methods/SourceMethodSupport.h"
#include "nav/ErrorStateEkf.h"

#include <QtGlobal>

#include <cmath>

namespace footpath {

void HeadingDriftReductionSource::integrateGyroHeading(const ErrorStateEkf& ekf, const ImuSample& sample)
{
    if (!std::isnan(previousTime_s_)) {
        const NavState& state = ekf.state();
        const Eigen::Vector3d rate_n = state.bodyToNav * (sample.gyr_radps - state.gyroBias_radps);
        gyroHeading_rad_ += rate_n.z() * (sample.time_s - previousTime_s_);
    }
    previousTime_s_ = sample.time_s;
}

const HeadingDriftReductionSource::StanceHeading* HeadingDriftReductionSource::stanceLagAgo(double time_s) const
{
    // The latest stance at least hdr_lag_s before now (history is in time order).
    for (auto it = history_.rbegin(); it != history_.rend(); ++it)
        if (time_s - it->time_s >= params_.hdr_lag_s)
            return &*it;
    return nullptr;
}

void HeadingDriftReductionSource::apply(ErrorStateEkf& ekf, const SourceContext& context)
{
    integrateGyroHeading(ekf, context.sample);
    if (!trigger_.fires(context.flags.stance, context.sample.time_s))
        return;
    const StanceHeading now{context.sample.time_s, gyroHeading_rad_, sources::currentYaw(ekf)};
    const StanceHeading* lagAgo = stanceLagAgo(now.time_s);
    const bool straight =
        lagAgo && std::abs(now.gyroHeading_rad - lagAgo->gyroHeading_rad) < params_.hdr_threshold_rad;
    if (!straight) {
        stretchOpen_ = false;
    } else if (!stretchOpen_ ||
               std::abs(now.gyroHeading_rad - stretchStart_.gyroHeading_rad) >= params_.hdr_threshold_rad) {
        // A new straight stretch, or a slow curve that has turned past the threshold since the
        // reference was taken: the reference restarts where the sliding test began.
        stretchOpen_ = true;
        stretchStart_ = *lagAgo;
    }
    if (stretchOpen_)
        sources::updateYaw(ekf, now.yaw_rad - stretchStart_.yaw_rad, params_.r_hdr_rad);
    history_.push_back(now);
    // Keep what the lag can still reach, plus the stance just before it.
    while (history_.size() > 2 && now.time_s - history_[1].time_s >= params_.hdr_lag_s)
        history_.pop_front();
}


// ---- registry entry (core/methods/SourceMethods.cpp lists it) ----------------------------

namespace {

const FieldCondition hdrOn{"hdr", methods::switchIsOn<&Parameters::use_hdr>,
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: HDR is off (use_hdr).")};

}  // namespace

SourceMethod headingDriftReductionMethod()
{
    const auto fields = [] {
        using P = Parameters;
        return std::vector<ParameterField>{
            flagField("use_hdr", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Heuristic drift reduction (HDR)"),
                 &P::use_hdr,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Heuristic drift reduction: heading held on straight walks"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            realField("hdr_lag_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR heading lag"), &P::hdr_lag_s, 0.05,
                 10.0, "s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR: heading compared with the heading this long ago"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR"), &hdrOn),
            realField("hdr_threshold_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR turn threshold"),
                 &P::hdr_threshold_rad, 0.0, 1.0, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "HDR: a smaller heading change is drift, a larger one a turn"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR"), &hdrOn),
            realField("r_hdr_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR measurement std"), &P::r_hdr_rad,
                 1e-6, 1.0, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR: R of the heading measurement, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR"), &hdrOn),
        };
    };
    return {"hdr", "HDR", "use_hdr", methods::switchIsOn<&Parameters::use_hdr>, methods::setSwitch<&Parameters::use_hdr>,
            methods::makeWhenOn<HeadingDriftReductionSource, &Parameters::use_hdr>, fields, 30};
}

}  // namespace footpath
