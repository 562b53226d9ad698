// libFuzzer target: the parameter preset JSON reader. A preset that reads without error must
// round-trip through the writer unchanged, and any set it yields must be safe to run: the
// pipeline either refuses it with a message (Parameters::validate) or estimates a short walk.

#include "io/ParameterIo.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include "FuzzInput.h"

#include <cstdlib>

using namespace footpath;

namespace {

const Recording& shortWalk()
{
    static const Recording walk = [] {
        WalkSimulatorConfig config;
        config.initialStill_s = 1.0;
        config.finalStill_s = 0.5;
        return simulateWalk(straightLinePath(2.8), config).recording;
    }();
    return walk;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    Parameters params;
    if (!parametersFromJson(fuzz::asText(data, size), "fuzz.json", params).empty())
        return 0;
    Parameters again;
    if (!parametersFromJson(parametersToJson(params), "written.json", again).empty()
        || parametersToJson(again) != parametersToJson(params))
        std::abort();
    const PipelineOutput output = runPipeline(shortWalk(), params);
    if (output.error.empty() == !params.validate().empty())
        std::abort();  // the pipeline ran a set validate() rejects, or refused a valid one
    return 0;
}
