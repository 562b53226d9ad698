#include "nav/sources/PositionErrorReduction.h"

#include "nav/ErrorStateEkf.h"

namespace footpath {

void PositionErrorReductionSource::apply(ErrorStateEkf& /*ekf*/, const SourceContext& /*context*/)
{
}

}  // namespace footpath
