#include "nav/sources/ZeroNavigationAcceleration.h"

#include "methods/SourceMethodSupport.h"
#include "nav/Attitude.h"
#include "nav/ErrorStateEkf.h"

#include <QtGlobal>

#include <sstream>

namespace footpath {

namespace {

/// The reference needs this much stance time in the reference period: the stance samples are
/// static, so half a second averages the noise well; less is a start without a standstill.
constexpr double kMinReferenceStance_s = 0.5;

}  // namespace

bool ZeroNavigationAccelerationSource::collectReference(const SourceContext& context)
{
    if (reference_ != Reference::Collecting)
        return reference_ == Reference::Ready;
    const double time_s = context.sample.time_s;
    if (!started_) {
        started_ = true;
        startTime_s_ = time_s;
    }
    if (time_s - startTime_s_ < params_.zuna_reference_s) {
        ++windowSamples_;
        if (context.flags.stance) {
            referenceSum_ += context.sample.acc_mps2;
            ++referenceSamples_;
        }
        return false;
    }
    // Stance time from the sample count and the window's mean spacing (the rate is not fixed).
    const double stance_s = windowSamples_ == 0 ? 0.0
        : params_.zuna_reference_s * static_cast<double>(referenceSamples_) / static_cast<double>(windowSamples_);
    if (stance_s < kMinReferenceStance_s) {
        reference_ = Reference::Missing;
        std::ostringstream message;
        message << "not applied: the foot rests for only " << stance_s << " s of the first " << params_.zuna_reference_s
                << " s, so there is no static reference for gravity (zuna_reference_s)";
        context.notes.push_back(MethodNote{"zuna", startTime_s_, time_s, message.str()});
        return false;
    }
    reference_ = Reference::Ready;
    referenceGravity_mps2 = (referenceSum_ / static_cast<double>(referenceSamples_)).norm();
    return true;
}

bool ZeroNavigationAccelerationSource::isMidStance(const SourceContext& context)
{
    if (!context.flags.stance) {
        inStance_ = false;
        return false;
    }
    if (!inStance_) {
        inStance_ = true;
        stanceStart_s_ = context.sample.time_s;
    }
    const bool settled = context.sample.time_s - stanceStart_s_ >= params_.zuna_min_stance_s;
    const bool quiet = context.flags.logStatistic <= context.flags.logThreshold - params_.zuna_margin_dec;
    return settled && quiet;
}

void ZeroNavigationAccelerationSource::update(ErrorStateEkf& ekf, const Eigen::Vector3d& specificForce_mps2) const
{
    const NavState& state = ekf.state();
    const Eigen::Vector3d gravityReaction_n(0.0, 0.0, referenceGravity_mps2);
    // Predicted minus measured (zero) navigation-frame acceleration.
    const Eigen::Vector3d innovation = state.bodyToNav * (specificForce_mps2 - state.accBias_mps2) - gravityReaction_n;
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(3, ErrorStateEkf::kStates);
    h.block<3, 3>(0, ErrorStateEkf::kAtt) = -skew(gravityReaction_n);
    h.block<3, 3>(0, ErrorStateEkf::kAccBias) = state.bodyToNav;
    ekf.updateRows(h, innovation, Eigen::VectorXd::Constant(3, params_.r_zuna_mps2 * params_.r_zuna_mps2));
}

void ZeroNavigationAccelerationSource::apply(ErrorStateEkf& ekf, const SourceContext& context)
{
    const bool midStance = isMidStance(context);  // tracks stance runs from the first sample
    if (!collectReference(context) || !midStance)
        return;
    update(ekf, context.sample.acc_mps2);
    ++updates_;
}

void ZeroNavigationAccelerationSource::finish(double endTime_s, std::vector<MethodNote>& notes)
{
    if (reference_ == Reference::Missing || updates_ > 0)
        return;  // a missing reference has its note already
    std::ostringstream message;
    if (reference_ == Reference::Collecting) {
        message << "not applied: the recording is shorter than the reference period zuna_reference_s ("
                << params_.zuna_reference_s << " s)";
        notes.push_back(MethodNote{"zuna", startTime_s_, endTime_s, message.str()});
        return;
    }
    message << "not applied: no stance lasted " << params_.zuna_min_stance_s << " s with the detector statistic "
            << params_.zuna_margin_dec << " decades below its threshold (zuna_min_stance_s, zuna_margin_dec)";
    notes.push_back(MethodNote{"zuna", startTime_s_ + params_.zuna_reference_s, endTime_s, message.str()});
}


// ---- registry entry (core/methods/SourceMethods.cpp lists it) ----------------------------

namespace {

const FieldCondition zunaOn{"zuna", methods::switchIsOn<&Parameters::use_zuna>,
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: ZUNA is off (use_zuna).")};

}  // namespace

SourceMethod zeroNavigationAccelerationMethod()
{
    const auto fields = [] {
        using P = Parameters;
        return std::vector<ParameterField>{
            flagField("use_zuna", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Zero navigation acceleration (ZUNA)"),
                 &P::use_zuna,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Zero navigation acceleration at mid-stance"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            realField("zuna_reference_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA reference period"),
                 &P::zuna_reference_s, 0.1, 60.0, "s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA: static start averaged for the reference"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA"), &zunaOn),
            realField("zuna_min_stance_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA shortest stance"),
                 &P::zuna_min_stance_s, 0.0, 2.0, "s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA: mid-stance needs a stance run this long"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA"), &zunaOn),
            realField("zuna_margin_dec", QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA margin below the threshold"),
                 &P::zuna_margin_dec, 0.0, 5.0, "decades",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "ZUNA: mid-stance statistic this far below the threshold"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA"), &zunaOn),
            realField("r_zuna_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA measurement std"), &P::r_zuna_mps2,
                 1e-6, 10.0, "m/s^2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA: R of the acceleration, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA"), &zunaOn),
        };
    };
    return {"zuna", "ZUNA", "use_zuna", methods::switchIsOn<&Parameters::use_zuna>, methods::setSwitch<&Parameters::use_zuna>,
            methods::makeWhenOn<ZeroNavigationAccelerationSource, &Parameters::use_zuna>, fields, 20};
}

}  // namespace footpath
