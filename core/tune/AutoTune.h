#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Parameters.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace footpath {

/// What tuning minimises, per recording, averaged over the recordings (the metrics of docs/accuracy.md):
/// the end-to-start distance in % of the path for walks that end where they started, the distance
/// error in % for walks of known length, or the 2D ARMSE against a full reference.
enum class TuneCriterion { ClosedLoop, KnownLength, Reference };

const char* tuneCriterionName(TuneCriterion criterion);  ///< "closed-loop", "length", "reference"
std::optional<TuneCriterion> parseTuneCriterion(const std::string& name);

/// One parameter the search moves, within [low, high], on a log scale when the range spans decades.
struct TuneDimension {
    std::string name;  ///< a parameterFields() name
    double low = 0.0;
    double high = 1.0;
    bool logScale = false;
};

/// The shortest stance the default search space allows: a shorter one is no rest of a foot.
constexpr double kMinTunedStance_s = 0.03;

/// A walk's strides as tuning watches them: how many, and how much their lengths vary.
struct StrideFigures {
    std::size_t count = 0;
    double lengthSpread_m = 0.0;  ///< sample standard deviation of the stride lengths
};

/// What tuned parameters changed about a walk's strides that a better figure cannot explain: the
/// count by more than 10 % (two strides at least), or the lengths' spread past 1.5 times and
/// 5 cm more ("strides 23 -> 29, stride length spread 0.05 -> 0.31 m"); empty when they held.
std::string strideCaution(const StrideFigures& before, const StrideFigures& after);

/// The default search space: the adaptive detector (offset, fraction, "never" bound, minimum stance)
/// and the filter's noise (Q velocity, Q attitude, R ZUPT); with the C1/C2/C3 detector its three
/// bounds instead of the adaptive ones.
std::vector<TuneDimension> defaultTuneSpace(const Parameters& base);

/// Whether the recording has what the criterion needs: a walk marked closed, a known length, or
/// reference positions for every sample. tuneParameters runs only these.
bool tuneCriterionApplies(const Recording& recording, TuneCriterion criterion);

/// The criterion on one recording's result, lower is better; NaN when the recording lacks what
/// the criterion needs (not closed, no known length, no reference positions).
double tuneScore(const Recording& recording, const Result& result, TuneCriterion criterion);

struct TuneOptions {
    TuneCriterion criterion = TuneCriterion::ClosedLoop;
    int evaluations = 200;      ///< parameter sets tried, the starting one included
    int threads = 0;            ///< 0: one per core
    std::uint32_t seed = 1;     ///< the search is deterministic for a seed
    std::vector<TuneDimension> space;  ///< empty: defaultTuneSpace(base)
};

struct TuneProgress {
    int evaluations = 0;  ///< done so far
    int budget = 0;
    double bestScore = 0.0;
};

struct TuneOutcome {
    Parameters best;                     ///< the base when nothing better was found
    double baseScore = 0.0;              ///< mean criterion of the base over the recordings
    double bestScore = 0.0;
    std::vector<double> basePerRecording;  ///< in the order of the recordings (NaN: not scored)
    std::vector<double> bestPerRecording;
    int evaluations = 0;
    bool cancelled = false;
    std::string error;  ///< empty on success: no recording has what the criterion needs, a bad space
    /// Changes of the best parameters that a better figure cannot explain, one line a recording
    /// ("walk.csv: strides 23 -> 29, stride length spread 0.05 -> 0.31 m"): a swing split into
    /// two, a stance lost. Said before the parameters are used; empty when the strides held.
    std::vector<std::string> cautions;
};

/// Searches the space for the parameters that minimise the mean criterion over the recordings: the
/// base, then a spread of samples over the whole space, then a shrinking local search around the
/// best (each generation evaluated in parallel). A candidate that raises a plausibility warning the
/// base did not have on some recording is rejected however good its number: tuning must not trade
/// a plausible path for a smaller figure; so is, for the closed-loop criterion, one that changes a
/// path's length by more than 10 % (a shrunken path closes better without being better). progress is called from the calling thread after each
/// generation; cancel stops at the next one (the best so far is returned, cancelled set).
TuneOutcome tuneParameters(const std::vector<const Recording*>& recordings, const Parameters& base,
                           const TuneOptions& options,
                           const std::function<void(const TuneProgress&)>& progress = {},
                           const std::atomic<bool>* cancel = nullptr);

}  // namespace footpath
