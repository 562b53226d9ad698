#include "nav/sources/ZeroNavigationAcceleration.h"

#include "nav/ErrorStateEkf.h"

namespace footpath {

void ZeroNavigationAccelerationSource::apply(ErrorStateEkf& /*ekf*/, const SourceContext& /*context*/)
{
}

}  // namespace footpath
