#include "nav/sources/ZeroVelocity.h"

#include "methods/FieldConditions.h"
#include "methods/SourceMethodSupport.h"
#include "nav/ErrorStateEkf.h"

#include <QtGlobal>

namespace footpath {

void ZeroVelocitySource::apply(ErrorStateEkf& ekf, const SourceContext& context)
{
    if (!context.flags.stance)
        return;
    if (zupt_ && zaru_)
        ekf.updateZeroVelocityAndRate(context.sample.gyr_radps);
    else if (zupt_)
        ekf.updateZeroVelocity();
    else if (zaru_)
        ekf.updateZeroAngularRate(context.sample.gyr_radps);
}


// ---- registry entry (core/methods/SourceMethods.cpp lists it) ----------------------------

namespace {

/// ZUPT's source also carries ZARU (one 6-row update when both are on).
std::unique_ptr<MeasurementSource> makeZeroVelocitySource(const Parameters& params)
{
    if (!params.use_zupt && !params.use_zaru)
        return nullptr;
    return std::make_unique<ZeroVelocitySource>(params);
}

}  // namespace

SourceMethod zeroVelocityMethod()
{
    const auto fields = [] {
        using P = Parameters;
        return std::vector<ParameterField>{
            flagField("use_zupt", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Zero-velocity update (ZUPT)"),
                 &P::use_zupt, QT_TRANSLATE_NOOP("footpath::ParameterFields", "Zero-velocity update during stance"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
        };
    };
    return {"zupt", "ZUPT", "use_zupt", methods::switchIsOn<&Parameters::use_zupt>, methods::setSwitch<&Parameters::use_zupt>,
            makeZeroVelocitySource, fields, 10};
}

SourceMethod zeroAngularRateMethod()
{
    const auto fields = [] {
        using P = Parameters;
        return std::vector<ParameterField>{
            flagField("use_zaru", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Zero angular rate update (ZARU)"),
                 &P::use_zaru, QT_TRANSLATE_NOOP("footpath::ParameterFields", "Zero angular rate update during stance"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements"), &conditions::zaru),
        };
    };
    return {"zaru", "ZARU", "use_zaru", methods::switchIsOn<&Parameters::use_zaru>, methods::setSwitch<&Parameters::use_zaru>,
            nullptr, fields, 11};
}

}  // namespace footpath
