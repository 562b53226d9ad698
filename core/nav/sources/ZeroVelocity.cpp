#include "nav/sources/ZeroVelocity.h"

#include "nav/ErrorStateEkf.h"

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

}  // namespace footpath
