#include "nav/MeasurementSources.h"

#include "methods/MethodRegistry.h"
#include "nav/ErrorStateEkf.h"

#include <algorithm>
#include <cmath>
#include <sstream>

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
    gates_.resize(sources_.size());
    gateProbability_ = params.gate_probability;
}

MeasurementSources::~MeasurementSources() = default;
MeasurementSources::MeasurementSources(MeasurementSources&&) noexcept = default;
MeasurementSources& MeasurementSources::operator=(MeasurementSources&&) noexcept = default;

void MeasurementSources::apply(ErrorStateEkf& ekf, const SourceContext& context)
{
    for (std::size_t i = 0; i < sources_.size(); ++i) {
        const ErrorStateEkf::GateCounts before = ekf.gateCounts();
        sources_[i]->apply(ekf, context);
        gates_[i].add(before, ekf.gateCounts(), context.sample.time_s);
    }
}

void MeasurementSources::GateTally::add(const ErrorStateEkf::GateCounts& before, const ErrorStateEkf::GateCounts& after,
                                         double time_s)
{
    tested += after.tested - before.tested;
    if (after.rejected == before.rejected)
        return;
    rejected += after.rejected - before.rejected;
    if (std::isnan(firstRejected_s))
        firstRejected_s = time_s;
    lastRejected_s = time_s;
}

void MeasurementSources::finish(double endTime_s, std::vector<MethodNote>& notes)
{
    for (std::size_t i = 0; i < sources_.size(); ++i) {
        sources_[i]->finish(endTime_s, notes);
        const GateTally& gate = gates_[i];
        if (gate.rejected == 0)
            continue;
        std::ostringstream message;
        message << gate.rejected << " of " << gate.tested
                << " measurements rejected by the innovation gate (chi-square, p = " << gateProbability_
                << "): the filter's own uncertainty says they cannot be right";
        notes.push_back({sources_[i]->name(), gate.firstRejected_s, gate.lastRejected_s, message.str()});
    }
}

}  // namespace footpath
