#include "nav/StreamingEstimator.h"

#include "detect/StanceDetector.h"
#include "metrics/Evaluation.h"
#include "nav/Alignment.h"
#include "nav/ErrorStateEkf.h"
#include "nav/InputCheck.h"
#include "nav/MeasurementSources.h"
#include "nav/Pipeline.h"
#include "nav/Plausibility.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <sstream>

namespace footpath {

namespace {

std::string joinProblems(const std::vector<std::string>& problems)
{
    std::ostringstream out;
    for (std::size_t i = 0; i < problems.size(); ++i)
        out << (i > 0 ? "\n" : "") << problems[i];
    return out.str();
}

}  // namespace

struct StreamingEstimator::Impl {
    explicit Impl(const Parameters& p)
        : params(p)
        , detector(makeCausalStanceDetector(p))
    {
        // Feliz's de-drift corrects each swing once the next stance has begun: a live estimate
        // cannot wait for it, so the filter runs instead, and the result says so.
        if (params.estimatorKind() == EstimatorKind::Feliz)
            result.methodNotes.push_back({"feliz", 0.0, 0.0,
                                          "live estimate by the Kalman filter: Feliz's de-drift needs the "
                                          "stance that ends each swing, so it runs on recordings only"});
    }

    bool accepts(const ImuSample& sample) const;
    void accept(const ImuSample& sample);
    void end();
    bool locateAlignmentStart();
    bool alignmentInputsFinal();
    void align();
    void estimateDecided();
    void estimate(const ImuSample& sample, const SampleStanceFlags& flags);
    void hold(const ImuSample& sample, const SampleStanceFlags& flags);
    void closeStancePhase(std::size_t end);

    Parameters params;
    std::string error;
    std::unique_ptr<CausalStanceDecider> detector;
    std::deque<ImuSample> pending;               ///< pushed, not yet estimated; oldest first
    std::deque<SampleStanceFlags> decidedFlags;  ///< final flags of the oldest pending samples
    std::size_t received = 0;
    std::optional<double> newestTime_s;
    std::size_t rejected = 0;
    bool finished = false;

    // Alignment starts at alignmentStart() of the decided flags: sample 0, or after a mid-walk
    // start the first stance; the samples before it are held at the start state.
    std::size_t flagsSearched = 0;               ///< decided flags searched for the first stance
    std::optional<std::size_t> alignmentStartIndex;
    std::size_t heldSamples = 0;

    std::optional<ErrorStateEkf> ekf;  ///< set once aligned
    MeasurementSources sources{params};
    std::optional<double> previousTime_s;  ///< of the last estimated sample
    std::optional<std::size_t> stancePhaseStart;  ///< index in result of the open stance phase
    double peakRateSinceStance_radps = 0.0;  ///< of the samples since the last stance phase (appendStep)
    double pathLength_m = 0.0;  ///< sum of the strides so far (stancePathLength, kept running)
    Result result;
};

bool StreamingEstimator::Impl::accepts(const ImuSample& sample) const
{
    if (finished || !hasFiniteInertialValues(sample))
        return false;
    return !newestTime_s || sample.time_s > *newestTime_s;
}

void StreamingEstimator::Impl::accept(const ImuSample& sample)
{
    ++received;
    newestTime_s = sample.time_s;
    pending.push_back(sample);
    detector->push(sample, decidedFlags);
    if (!ekf && alignmentInputsFinal())
        align();
    estimateDecided();
}

void StreamingEstimator::Impl::end()
{
    if (received < 2) {
        // runPipeline refuses such a recording too; its result stays empty.
        error = "only " + std::to_string(received) + " samples arrived; at least 2 are needed";
        return;
    }
    detector->finish(decidedFlags);
    if (!ekf)
        align();
    estimateDecided();
    if (stancePhaseStart)
        closeStancePhase(result.time_s.size());  // offline, a stance phase up to the end is a step too
    if (!result.time_s.empty())
        sources.finish(result.time_s.back(), result.methodNotes);
    summarize(result, pathLength_m);
    result.warnings = checkPlausibility(result, params);
}

/// Before alignment nothing is estimated, so decided flag k is sample k's: the first stance among
/// them is alignmentStart() of the whole recording (sample 0 when it is stance).
bool StreamingEstimator::Impl::locateAlignmentStart()
{
    for (; !alignmentStartIndex && flagsSearched < decidedFlags.size(); ++flagsSearched)
        if (decidedFlags[flagsSearched].stance)
            alignmentStartIndex = flagsSearched;
    return alignmentStartIndex.has_value();
}

/// The alignment period (alignment_s from its start) is over and every sample in it is decided.
bool StreamingEstimator::Impl::alignmentInputsFinal()
{
    if (!locateAlignmentStart())
        return false;
    const double end_s = pending[*alignmentStartIndex].time_s + params.alignment_s;  // as averageStatic computes it
    const std::size_t decided = decidedFlags.size();
    return decided < pending.size() && pending[decided].time_s > end_s;
}

/// alignInitialAttitude on exactly what runPipeline gives it (its loop stops at the first sample
/// after the alignment period), so the initial attitude is the offline one. Without any stance
/// (only at the end of data) it starts at sample 0, as offline.
void StreamingEstimator::Impl::align()
{
    const std::size_t start = alignmentStartIndex.value_or(0);
    const double end_s = pending[start].time_s + params.alignment_s;
    std::size_t count = start;
    while (count < pending.size() && count < decidedFlags.size() && pending[count].time_s <= end_s)
        ++count;
    count = std::max<std::size_t>(count, 1);
    const std::vector<ImuSample> samples(pending.begin(), pending.begin() + static_cast<std::ptrdiff_t>(count));
    std::vector<std::uint8_t> stance(std::min(count, decidedFlags.size()));
    for (std::size_t k = 0; k < stance.size(); ++k)
        stance[k] = decidedFlags[k].stance;
    ekf.emplace(params, alignInitialAttitude(samples, stance, params).bodyToNav);
    heldSamples = start;
}

void StreamingEstimator::Impl::estimateDecided()
{
    if (!ekf || decidedFlags.empty())
        return;
    while (!decidedFlags.empty()) {
        if (result.time_s.size() < heldSamples)
            hold(pending.front(), decidedFlags.front());
        else
            estimate(pending.front(), decidedFlags.front());
        pending.pop_front();
        decidedFlags.pop_front();
    }
    summarize(result, pathLength_m);
}

void StreamingEstimator::Impl::estimate(const ImuSample& sample, const SampleStanceFlags& flags)
{
    filterSample(*ekf, sources, sample, previousTime_s, flags, result);
    appendFlags(result.flags, flags);
    previousTime_s = sample.time_s;
    const std::size_t k = result.time_s.size() - 1;
    if (!flags.stance)
        peakRateSinceStance_radps = std::max(peakRateSinceStance_radps, sample.gyr_radps.norm());
    if (flags.stance && !stancePhaseStart)
        stancePhaseStart = k;
    else if (!flags.stance && stancePhaseStart)
        closeStancePhase(k);
}

/// A sample before the mid-walk start's first stance: the start state, as runFilter holds it.
void StreamingEstimator::Impl::hold(const ImuSample& sample, const SampleStanceFlags& flags)
{
    holdAtStart(*ekf, sample.time_s, result);
    appendFlags(result.flags, flags);
}

/// The open stance phase, result samples [start, end), becomes a step as fillStepsAndSummary makes it.
void StreamingEstimator::Impl::closeStancePhase(std::size_t end)
{
    // Summed as stancePathLength sums, so live and offline agree to the last bit.
    if (appendStep(result, *stancePhaseStart, end, peakRateSinceStance_radps))
        pathLength_m = stancePathLength(result.steps);
    else
        pathLength_m += result.steps.back().strideLength_m;
    stancePhaseStart.reset();
    peakRateSinceStance_radps = 0.0;
}

StreamingEstimator::StreamingEstimator(const Parameters& params)
    : impl_(std::make_unique<Impl>(params))
{
    impl_->error = joinProblems(params.validate());
}

StreamingEstimator::~StreamingEstimator() = default;

const std::string& StreamingEstimator::error() const
{
    return impl_->error;
}

void StreamingEstimator::push(const ImuSample& sample)
{
    if (!impl_->error.empty())
        return;
    if (!impl_->accepts(sample)) {
        ++impl_->rejected;
        return;
    }
    impl_->accept(sample);
}

void StreamingEstimator::finish()
{
    if (impl_->finished)
        return;
    impl_->finished = true;
    if (impl_->error.empty())
        impl_->end();
}

const Result& StreamingEstimator::result() const
{
    return impl_->result;
}

std::size_t StreamingEstimator::pendingSamples() const
{
    return impl_->pending.size();
}

std::size_t StreamingEstimator::rejectedSamples() const
{
    return impl_->rejected;
}

bool StreamingEstimator::aligned() const
{
    return impl_->ekf.has_value();
}

const Parameters& StreamingEstimator::parameters() const
{
    return impl_->params;
}

double StreamingEstimator::latency_s(const Parameters& params)
{
    return stanceDetectorLatency_s(params);
}

}  // namespace footpath
