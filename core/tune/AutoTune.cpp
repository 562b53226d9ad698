#include "tune/AutoTune.h"

#include "metrics/Evaluation.h"
#include "metrics/GaitStatistics.h"
#include "nav/Pipeline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <thread>

namespace footpath {

namespace {

constexpr double kRejected = std::numeric_limits<double>::infinity();
/// Candidates per generation of the local search: fixed, so the search does not depend on the
/// number of cores.
constexpr int kGenerationSize = 8;
/// Closed-loop tuning may not change a walk's path length by more than this share: a path that
/// shrank closes better without being better (rectangle_72m: 0.54 -> 0.19 % by a path 34 % short).
constexpr double kClosedLoopLengthTolerance = 0.1;
/// Share of the budget spent spreading samples over the whole space before searching locally.
constexpr double kGlobalShare = 0.4;
/// A tuned result is cautioned about (TuneOutcome::cautions) when it changes a walk's stride count
/// by more than this share (and by two strides at least) ...
constexpr double kStrideCountTolerance = 0.1;
/// ... or makes its stride lengths' standard deviation grow past this factor and margin.
constexpr double kStrideSpreadTolerance = 1.5;
constexpr double kStrideSpreadMargin_m = 0.05;

/// A candidate in the unit cube, one coordinate per dimension.
using UnitPoint = std::vector<double>;

double toValue(const TuneDimension& d, double u)
{
    u = std::clamp(u, 0.0, 1.0);
    if (d.logScale)
        return d.low * std::pow(d.high / d.low, u);
    return d.low + u * (d.high - d.low);
}

double toUnit(const TuneDimension& d, double value)
{
    const double u = d.logScale ? std::log(value / d.low) / std::log(d.high / d.low) : (value - d.low) / (d.high - d.low);
    return std::isfinite(u) ? std::clamp(u, 0.0, 1.0) : 0.5;
}

Parameters applyPoint(const Parameters& base, const std::vector<TuneDimension>& space, const UnitPoint& point)
{
    Parameters params = base;
    for (std::size_t i = 0; i < space.size(); ++i)
        params.*(findParameterField(space[i].name)->real) = toValue(space[i], point[i]);
    return params;
}

std::set<PlausibilityWarning::Kind> warningKinds(const Result& result)
{
    std::set<PlausibilityWarning::Kind> kinds;
    for (const PlausibilityWarning& warning : result.warnings)
        kinds.insert(warning.kind);
    return kinds;
}

/// One candidate's criterion and warnings on every recording.
struct Evaluation {
    std::vector<double> scores;
    std::vector<double> pathLengths_m;
    std::vector<std::set<PlausibilityWarning::Kind>> warnings;
    std::vector<StrideFigures> strides;
};

StrideFigures strideFiguresOf(const Result& result)
{
    const GaitStatistics stats = computeGaitStatistics(result);
    return {stats.strides, stats.strides > 1 ? stats.strideLengthStd_m : 0.0};
}

/// Runs every candidate on every recording, the (candidate, recording) pairs spread over threads.
std::vector<Evaluation> evaluateAll(const std::vector<const Recording*>& recordings,
                                    const std::vector<Parameters>& candidates, TuneCriterion criterion, int threads,
                                    const std::atomic<bool>* cancel)
{
    std::vector<Evaluation> evaluations(candidates.size());
    for (Evaluation& evaluation : evaluations) {
        evaluation.scores.assign(recordings.size(), std::nan(""));
        evaluation.pathLengths_m.assign(recordings.size(), std::nan(""));
        evaluation.warnings.resize(recordings.size());
        evaluation.strides.resize(recordings.size());
    }
    const std::size_t tasks = candidates.size() * recordings.size();
    const RtsSmoother::Threads perRun = threadsPerRun(static_cast<std::size_t>(std::max(threads, 1)));
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        const ProgressCallback keepGoing = [cancel](double) { return !(cancel && cancel->load()); };
        for (std::size_t task = next++; task < tasks; task = next++) {
            const std::size_t c = task / recordings.size(), r = task % recordings.size();
            const PipelineOutput output =
                runPipeline(*recordings[r], candidates[c], keepGoing, perRun, {}, RtsSmoother::Variances::Skip);
            if (!output.error.empty() || output.result.cancelled)
                continue;
            evaluations[c].scores[r] = tuneScore(*recordings[r], output.result, criterion);
            evaluations[c].pathLengths_m[r] = output.result.summary.pathLength_m;
            evaluations[c].warnings[r] = warningKinds(output.result);
            evaluations[c].strides[r] = strideFiguresOf(output.result);
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread& thread : pool)
        thread.join();
    return evaluations;
}

/// The mean over the recordings the base could be scored on; rejected (infinite) when the
/// candidate failed one of them, raised a warning the base did not have, or (closed loop) changed
/// a path's length by more than kClosedLoopLengthTolerance.
double meanScore(const Evaluation& candidate, const Evaluation& base, TuneCriterion criterion)
{
    double sum = 0.0;
    int count = 0;
    for (std::size_t r = 0; r < base.scores.size(); ++r) {
        if (std::isnan(base.scores[r]))
            continue;
        if (std::isnan(candidate.scores[r]))
            return kRejected;
        for (const PlausibilityWarning::Kind kind : candidate.warnings[r])
            if (!base.warnings[r].count(kind))
                return kRejected;
        if (criterion == TuneCriterion::ClosedLoop
            && std::abs(candidate.pathLengths_m[r] - base.pathLengths_m[r]) > kClosedLoopLengthTolerance * base.pathLengths_m[r])
            return kRejected;
        sum += candidate.scores[r];
        ++count;
    }
    return count > 0 ? sum / count : kRejected;
}

/// Latin hypercube: every dimension's range cut into `count` strata, each used once.
std::vector<UnitPoint> spreadSamples(std::size_t dimensions, int count, std::mt19937& random)
{
    std::uniform_real_distribution<double> within(0.0, 1.0);
    std::vector<UnitPoint> points(static_cast<std::size_t>(count), UnitPoint(dimensions));
    for (std::size_t d = 0; d < dimensions; ++d) {
        std::vector<int> strata(static_cast<std::size_t>(count));
        std::iota(strata.begin(), strata.end(), 0);
        std::shuffle(strata.begin(), strata.end(), random);
        for (int i = 0; i < count; ++i)
            points[static_cast<std::size_t>(i)][d] = (strata[static_cast<std::size_t>(i)] + within(random)) / count;
    }
    return points;
}

std::vector<UnitPoint> neighbours(const UnitPoint& centre, double stepSize, int count, std::mt19937& random)
{
    std::normal_distribution<double> step(0.0, stepSize);
    std::vector<UnitPoint> points(static_cast<std::size_t>(count), centre);
    for (UnitPoint& point : points)
        for (double& u : point)
            u = std::clamp(u + step(random), 0.0, 1.0);
    return points;
}

std::string checkSpace(const std::vector<TuneDimension>& space)
{
    if (space.empty())
        return "nothing to tune: the search space is empty";
    for (const TuneDimension& d : space) {
        const ParameterField* field = findParameterField(d.name);
        if (!field || field->kind != ParameterField::Kind::Real)
            return "cannot tune '" + d.name + "': not a numeric parameter";
        if (!(d.low < d.high) || (d.logScale && !(d.low > 0.0)))
            return "cannot tune '" + d.name + "': its range is empty or not positive on a log scale";
        if (d.low < field->minimum || d.high > field->maximum)
            return "cannot tune '" + d.name + "': its range leaves the parameter's own limits";
    }
    return {};
}

/// The search's state: the best point and score so far, and the budget left.
struct Search {
    const std::vector<const Recording*>& recordings;
    const Parameters& base;
    const TuneOptions& options;
    const std::vector<TuneDimension>& space;
    const std::function<void(const TuneProgress&)>& progress;
    const std::atomic<bool>* cancel;
    int threads;
    Evaluation baseEvaluation;
    UnitPoint bestPoint;
    Evaluation bestEvaluation;
    double bestScore = kRejected;
    int evaluations = 0;

    bool cancelled() const { return cancel && cancel->load(); }

    /// Evaluates the points; true if one of them became the best.
    bool tryPoints(const std::vector<UnitPoint>& points)
    {
        std::vector<Parameters> candidates;
        for (const UnitPoint& point : points)
            candidates.push_back(applyPoint(base, space, point));
        const std::vector<Evaluation> results = evaluateAll(recordings, candidates, options.criterion, threads, cancel);
        bool improved = false;
        for (std::size_t i = 0; i < points.size() && !cancelled(); ++i) {
            const double score = meanScore(results[i], baseEvaluation, options.criterion);
            if (score < bestScore) {
                bestScore = score;
                bestPoint = points[i];
                bestEvaluation = results[i];
                improved = true;
            }
        }
        evaluations += static_cast<int>(points.size());
        if (progress)
            progress(TuneProgress{evaluations, options.evaluations, bestScore});
        return improved;
    }
};

}  // namespace

const char* tuneCriterionName(TuneCriterion criterion)
{
    switch (criterion) {
    case TuneCriterion::ClosedLoop:
        return "closed-loop";
    case TuneCriterion::KnownLength:
        return "length";
    case TuneCriterion::Reference:
        return "reference";
    }
    return "closed-loop";
}

std::optional<TuneCriterion> parseTuneCriterion(const std::string& name)
{
    for (const TuneCriterion criterion : {TuneCriterion::ClosedLoop, TuneCriterion::KnownLength, TuneCriterion::Reference})
        if (name == tuneCriterionName(criterion))
            return criterion;
    return std::nullopt;
}

std::vector<TuneDimension> defaultTuneSpace(const Parameters& base)
{
    std::vector<TuneDimension> space;
    if (base.detectorKind() == DetectorKind::PaperC1C2C3) {
        space.push_back({"acc_std_max_mps2", 0.1, 3.0, true});
        space.push_back({"gyr_max_radps", 0.3, 6.0, true});
        space.push_back({"window_half_s", 0.02, 0.3, false});
    } else {
        space.push_back({"zv_adapt_offset_dec", 0.0, 0.6, false});
        space.push_back({"zv_adapt_fraction", 0.1, 0.5, false});
        space.push_back({"zv_log_never", 5.0, 8.0, false});
        // From 30 ms: a shorter "stance" is no rest of a foot (three samples at 100 Hz; a running
        // foot rests longer), and allowing it let the search split swings into strides of
        // millimetres (closure 3.34 -> 0.04 % with 0.001 s and strides 23 -> 29).
        space.push_back({"zv_min_stance_s", kMinTunedStance_s, 0.15, false});
    }
    space.push_back({"q_vel_mps", 1e-4, 3e-3, true});
    space.push_back({"q_att_rad", 1e-5, 3e-4, true});
    space.push_back({"r_zupt_mps", 2e-3, 5e-2, true});
    return space;
}

std::string strideCaution(const StrideFigures& before, const StrideFigures& after)
{
    std::ostringstream out;
    out.precision(3);
    const double countChange = std::abs(static_cast<double>(after.count) - static_cast<double>(before.count));
    if (countChange >= 2.0 && countChange > kStrideCountTolerance * static_cast<double>(before.count))
        out << "strides " << before.count << " -> " << after.count;
    if (after.lengthSpread_m > kStrideSpreadTolerance * before.lengthSpread_m + kStrideSpreadMargin_m)
        out << (out.tellp() > 0 ? ", " : "") << "stride length spread " << before.lengthSpread_m << " -> "
            << after.lengthSpread_m << " m";
    return out.str();
}

bool tuneCriterionApplies(const Recording& recording, TuneCriterion criterion)
{
    const Reference& reference = recording.reference;
    switch (criterion) {
    case TuneCriterion::ClosedLoop:
        return reference.closedLoop;
    case TuneCriterion::KnownLength:
        return reference.knownLength_m > 0.0;
    case TuneCriterion::Reference:
        return !reference.positions_m.empty() && reference.positions_m.size() == recording.samples.size();
    }
    return false;
}

double tuneScore(const Recording& recording, const Result& result, TuneCriterion criterion)
{
    const Reference& reference = recording.reference;
    if (!tuneCriterionApplies(recording, criterion) || result.position_m.size() != recording.samples.size())
        return std::nan("");
    switch (criterion) {
    case TuneCriterion::ClosedLoop:
        return computeLoopClosure(result.position_m, result.summary.pathLength_m, reference.knownLength_m).dbsePct;
    case TuneCriterion::KnownLength:
        return computeDistanceError(result.summary.pathLength_m, reference.knownLength_m).errorPct;
    case TuneCriterion::Reference:
        return computeArmse(result.position_m, reference.positions_m).armse2d_m;
    }
    return std::nan("");
}

namespace {

/// Per-recording figures of the scored recordings back in the order of all of them (NaN for the
/// others).
std::vector<double> inAllRecordings(const std::vector<double>& scoredValues, const std::vector<std::size_t>& scoredIndex,
                                    std::size_t recordings)
{
    std::vector<double> all(recordings, std::nan(""));
    for (std::size_t i = 0; i < scoredIndex.size(); ++i)
        all[scoredIndex[i]] = scoredValues[i];
    return all;
}

}  // namespace

TuneOutcome tuneParameters(const std::vector<const Recording*>& recordings, const Parameters& base,
                           const TuneOptions& options, const std::function<void(const TuneProgress&)>& progress,
                           const std::atomic<bool>* cancel)
{
    TuneOutcome outcome;
    outcome.best = base;
    const std::vector<TuneDimension> space = options.space.empty() ? defaultTuneSpace(base) : options.space;
    outcome.error = checkSpace(space);
    if (!outcome.error.empty())
        return outcome;
    const int threads = options.threads > 0 ? options.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    // Recordings the criterion cannot score are not run at all (they would cost every candidate
    // a pipeline run for nothing).
    std::vector<const Recording*> scored;
    std::vector<std::size_t> scoredIndex;
    for (std::size_t i = 0; i < recordings.size(); ++i)
        if (tuneCriterionApplies(*recordings[i], options.criterion)) {
            scored.push_back(recordings[i]);
            scoredIndex.push_back(i);
        }
    Search search{scored, base, options, space, progress, cancel, threads, {}, {}, {}, kRejected, 0};

    // The base itself: what every candidate must beat, and the warnings it may not add to.
    search.baseEvaluation = evaluateAll(scored, {base}, options.criterion, threads, cancel).front();
    search.evaluations = 1;
    const double baseScore = meanScore(search.baseEvaluation, search.baseEvaluation, options.criterion);
    if (!std::isfinite(baseScore)) {
        outcome.error = std::string("none of the recordings can be scored by the ") + tuneCriterionName(options.criterion)
                        + " criterion (a walk marked closed, a known length or reference positions is needed)";
        return outcome;
    }
    search.bestScore = baseScore;
    search.bestEvaluation = search.baseEvaluation;
    for (const TuneDimension& d : space)
        search.bestPoint.push_back(toUnit(d, parameterValue(base, *findParameterField(d.name))));
    const UnitPoint basePoint = search.bestPoint;

    std::mt19937 random(options.seed);
    const int globalCount = std::min(options.evaluations - 1, static_cast<int>(kGlobalShare * options.evaluations));
    if (globalCount > 0 && !search.cancelled())
        search.tryPoints(spreadSamples(space.size(), globalCount, random));
    double stepSize = 0.15;
    while (search.evaluations < options.evaluations && !search.cancelled()) {
        const int count = std::min(kGenerationSize, options.evaluations - search.evaluations);
        if (!search.tryPoints(neighbours(search.bestPoint, stepSize, count, random)))
            stepSize = std::max(0.01, stepSize * 0.6);
    }

    outcome.cancelled = search.cancelled();
    outcome.evaluations = search.evaluations;
    outcome.baseScore = baseScore;
    outcome.bestScore = search.bestScore;
    outcome.basePerRecording = inAllRecordings(search.baseEvaluation.scores, scoredIndex, recordings.size());
    outcome.bestPerRecording = inAllRecordings(search.bestEvaluation.scores, scoredIndex, recordings.size());
    if (search.bestPoint != basePoint) {
        outcome.best = applyPoint(base, space, search.bestPoint);
        for (std::size_t i = 0; i < scored.size(); ++i)
            if (std::string caution = strideCaution(search.baseEvaluation.strides[i], search.bestEvaluation.strides[i]);
                !caution.empty())
                outcome.cautions.push_back(scored[i]->source + ": " + caution);
    }
    return outcome;
}

}  // namespace footpath
