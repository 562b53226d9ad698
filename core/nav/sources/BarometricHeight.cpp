#include "nav/sources/BarometricHeight.h"

#include "nav/ErrorStateEkf.h"

namespace footpath {

void BarometricHeightSource::apply(ErrorStateEkf& /*ekf*/, const SourceContext& /*context*/)
{
}

}  // namespace footpath
