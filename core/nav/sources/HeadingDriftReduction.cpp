#include "nav/sources/HeadingDriftReduction.h"

#include "nav/ErrorStateEkf.h"

namespace footpath {

void HeadingDriftReductionSource::apply(ErrorStateEkf& /*ekf*/, const SourceContext& /*context*/)
{
}

}  // namespace footpath
