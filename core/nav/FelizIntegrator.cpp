#include "nav/FelizIntegrator.h"

namespace footpath {

bool runFelizIntegrator(const Recording& /*recording*/, const Parameters& /*params*/,
                        const ProgressCallback& /*progress*/, Result& /*result*/)
{
    return true;
}

}  // namespace footpath
