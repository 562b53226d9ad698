#include "nav/MeasurementSources.h"

#include "methods/MethodRegistry.h"
#include "nav/ErrorStateEkf.h"

#include <algorithm>

namespace footpath {

MeasurementSources::MeasurementSources(const Parameters& params)
{
    std::vector<const SourceMethod*> methods;
    for (const SourceMethod& method : sourceMethods())
        if (method.make)
            methods.push_back(&method);
    std::stable_sort(methods.begin(), methods.end(),
                     [](const SourceMethod* a, const SourceMethod* b) { return a->applyRank < b->applyRank; });
    for (const SourceMethod* method : methods)
        if (std::unique_ptr<MeasurementSource> source = method->make(params))
            sources_.push_back(std::move(source));
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
