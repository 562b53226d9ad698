#include "nav/MeasurementSources.h"

#include "nav/ErrorStateEkf.h"
#include "nav/sources/BarometricHeight.h"
#include "nav/sources/HeadingDriftReduction.h"
#include "nav/sources/MagneticHeading.h"
#include "nav/sources/PositionErrorReduction.h"
#include "nav/sources/ZeroNavigationAcceleration.h"
#include "nav/sources/ZeroVelocity.h"

namespace footpath {

MeasurementSources::MeasurementSources(const Parameters& params)
{
    if (params.use_zupt || params.use_zaru)
        sources_.push_back(std::make_unique<ZeroVelocitySource>(params));
    if (params.use_zuna)
        sources_.push_back(std::make_unique<ZeroNavigationAccelerationSource>(params));
    if (params.use_hdr)
        sources_.push_back(std::make_unique<HeadingDriftReductionSource>(params));
    if (params.use_mag_heading)
        sources_.push_back(std::make_unique<MagneticHeadingSource>(params));
    if (params.use_iper)
        sources_.push_back(std::make_unique<PositionErrorReductionSource>(params));
    if (params.use_baro)
        sources_.push_back(std::make_unique<BarometricHeightSource>(params));
}

MeasurementSources::~MeasurementSources() = default;
MeasurementSources::MeasurementSources(MeasurementSources&&) noexcept = default;
MeasurementSources& MeasurementSources::operator=(MeasurementSources&&) noexcept = default;

void MeasurementSources::apply(ErrorStateEkf& ekf, const SourceContext& context)
{
    for (const std::unique_ptr<MeasurementSource>& source : sources_)
        source->apply(ekf, context);
}

void MeasurementSources::finish(double endTime_s, std::vector<MethodNote>& notes)
{
    for (const std::unique_ptr<MeasurementSource>& source : sources_)
        source->finish(endTime_s, notes);
}

}  // namespace footpath
