#include "nav/sources/MagneticHeading.h"

#include "nav/ErrorStateEkf.h"

namespace footpath {

void MagneticHeadingSource::apply(ErrorStateEkf& /*ekf*/, const SourceContext& /*context*/)
{
}

}  // namespace footpath
