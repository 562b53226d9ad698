#include "metrics/ResultEvaluation.h"

#include "metrics/Evaluation.h"

namespace footpath {

ResultEvaluation evaluate(const Result& result, const Recording* recording)
{
    ResultEvaluation evaluation;
    evaluation.statistics = computeGaitStatistics(result, recording);
    if (recording)
        evaluation.alignedReference = alignReferenceToEstimate(recording->reference.positions_m, result.position_m);
    evaluation.strideLengths = makeHistogram(evaluation.statistics.strideLengths_m, kStrideLengthBin_m);
    evaluation.stanceDurations = makeHistogram(evaluation.statistics.stanceDurations_s, kStanceDurationBin_s);
    return evaluation;
}

}  // namespace footpath
