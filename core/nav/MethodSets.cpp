#include "nav/MethodSets.h"

#include "io/NearestNames.h"
#include "methods/MethodRegistry.h"
#include "metrics/Evaluation.h"

#include <algorithm>
#include <sstream>
#include <thread>

namespace footpath {

namespace {

std::string trimmed(const std::string& text)
{
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos)
        return {};
    const auto last = text.find_last_not_of(" \t");
    return text.substr(first, last - first + 1);
}

std::string nearestToken(const std::string& token)
{
    const std::vector<std::string> known = methodSetTokens();
    return *std::min_element(known.begin(), known.end(), [&](const std::string& a, const std::string& b) {
        return editDistance(token, a) < editDistance(token, b);
    });
}

Parameters withAllMethodsOff(const Parameters& base)
{
    Parameters params = base;
    params.estimator = static_cast<int>(EstimatorKind::Ekf);
    for (const SourceMethod& source : sourceMethods())
        source.setOn(params, false);
    return params;
}

int estimatorIndex(const std::string& token)
{
    const std::vector<EstimatorMethod>& estimators = estimatorMethods();
    for (std::size_t i = 0; i < estimators.size(); ++i)
        if (*estimators[i].setLabel && token == estimators[i].token)
            return static_cast<int>(i);
    return -1;
}

/// The filter size a token names ("9state" or "9", "15state" or "15"), if it names one.
std::optional<FilterStates> filterStatesOf(const std::string& token)
{
    if (token == "9state" || token == "9")
        return FilterStates::Nine;
    if (token == "15state" || token == "15")
        return FilterStates::Fifteen;
    return std::nullopt;
}

/// Sets the method a token names; false if the token is unknown.
bool applyToken(const std::string& token, Parameters& params, bool& statesNamed)
{
    if (const SourceMethod* source = findSourceMethod(token)) {
        source->setOn(params, true);
        return true;
    }
    if (const int estimator = estimatorIndex(token); estimator >= 0) {
        params.estimator = estimator;
        return true;
    }
    if (const std::optional<FilterStates> states = filterStatesOf(token)) {
        params.filter_states = static_cast<int>(*states);
        statesNamed = true;
        return true;
    }
    return false;
}

ComparisonRow evaluateSet(const Recording& recording, const MethodSet& set, const std::atomic<bool>* cancel,
                          RtsSmoother::Threads threads)
{
    ComparisonRow row;
    row.set = set;
    ProgressCallback progress;
    if (cancel)
        progress = [cancel](double) { return !cancel->load(); };
    // A comparison shows paths, heights and figures, no standard deviations.
    row.output = runPipeline(recording, set.params, progress, threads, {}, RtsSmoother::Variances::Skip);
    const Result& result = row.output.result;
    if (!row.output.error.empty() || result.cancelled || result.position_m.empty())
        return row;
    row.endToStart_m = result.summary.endToStart_m;
    row.endToStartPct = result.summary.endToStartPct;
    row.pathLength_m = result.summary.pathLength_m;
    row.heightChange_m = result.position_m.back().z() - result.position_m.front().z();
    const Reference& reference = recording.reference;
    if (!reference.positions_m.empty())
        row.armse2d_m = computeArmse(result.position_m, reference.positions_m).armse2d_m;
    if (!reference.swings.empty())
        row.stanceF1 = scoreStanceDetection(result.flags.stance, reference.swings,
                                            reference.hasTrialBoundaries ? &reference.trialBoundaries : nullptr)
                           .f1;
    return row;
}

}  // namespace

std::vector<std::string> methodTokens()
{
    return methodSetTokens();
}

std::optional<MethodSet> parseMethodSet(const std::string& spec, const Parameters& base, std::string& error)
{
    MethodSet set;
    set.params = withAllMethodsOff(base);
    bool statesNamed = false;
    std::vector<std::string> names;
    std::istringstream in(spec);
    for (std::string token; std::getline(in, token, ',');) {
        token = trimmed(token);
        std::transform(token.begin(), token.end(), token.begin(), [](unsigned char c) { return std::tolower(c); });
        if (token.empty())
            continue;
        if (!applyToken(token, set.params, statesNamed)) {
            error = "unknown method '" + token + "' in set '" + trimmed(spec) + "' (did you mean '" + nearestToken(token)
                    + "'?); known: " + methodSetTokensText();
            return std::nullopt;
        }
        names.push_back(token);
    }
    if (names.empty()) {
        error = "empty method set in '" + spec + "'";
        return std::nullopt;
    }
    if (set.params.use_zaru && !statesNamed)
        set.params.filter_states = static_cast<int>(FilterStates::Fifteen);
    for (std::size_t i = 0; i < names.size(); ++i)
        set.name += (i ? "," : "") + names[i];
    return set;
}

std::string methodSetSpec(const Parameters& params)
{
    const EstimatorMethod& estimator = estimatorMethods()[static_cast<std::size_t>(params.estimator)];
    std::vector<std::string> tokens;
    if (params.estimatorKind() == EstimatorKind::Feliz) {
        tokens.emplace_back(estimator.token);  // Feliz runs no filter, so no source
    } else {
        for (const SourceMethod& source : sourceMethods())
            if (source.isOn(params))
                tokens.emplace_back(source.token);
        if (!tokens.empty() && params.filter_states != Parameters().filter_states)
            tokens.push_back(params.filterStates() == FilterStates::Fifteen ? "15state" : "9state");
        if (*estimator.setLabel)
            tokens.emplace_back(estimator.token);
    }
    std::string spec;
    for (std::size_t i = 0; i < tokens.size(); ++i)
        spec += (i ? "," : "") + tokens[i];
    return spec;
}

namespace {

/// How a set spells one token ("HDR" for "hdr"); the token itself when no method has it.
std::string tokenLabel(const std::string& token)
{
    if (const SourceMethod* source = findSourceMethod(token))
        return source->setLabel;
    if (const int estimator = estimatorIndex(token); estimator >= 0)
        return estimatorMethods()[static_cast<std::size_t>(estimator)].setLabel;
    if (const std::optional<FilterStates> states = filterStatesOf(token))
        return *states == FilterStates::Nine ? "9-state" : "15-state";
    return token;
}

}  // namespace

std::string methodSetLabel(const std::string& spec)
{
    std::string label;
    std::istringstream in(spec);
    for (std::string token; std::getline(in, token, ',');)
        label += (label.empty() ? "" : "+") + tokenLabel(token);
    return label;
}

std::vector<MethodSet> parseMethodSets(const std::string& specs, const Parameters& base, std::string& error)
{
    std::vector<MethodSet> sets;
    std::istringstream in(specs);
    for (std::string spec; std::getline(in, spec, ';');) {
        if (trimmed(spec).empty())
            continue;
        std::optional<MethodSet> set = parseMethodSet(spec, base, error);
        if (!set)
            return {};
        sets.push_back(std::move(*set));
    }
    if (sets.empty())
        error = "no method set given";
    return sets;
}

std::string suggestedMethodSetsSpec()
{
    return "zupt;zupt,zaru;zupt,zaru,hdr;zupt,zaru,hdr,iper;zupt,zaru,hdr,iper,zuna;zupt,baro;feliz;"
           "zupt,rts;zupt,9state;zupt,15state";
}

std::vector<MethodSet> suggestedMethodSets(const Parameters& base)
{
    std::string error;
    return parseMethodSets(suggestedMethodSetsSpec(), base, error);
}

std::vector<ComparisonRow> runComparison(const Recording& recording, const std::vector<MethodSet>& sets, int threads,
                                         const std::atomic<bool>* cancel)
{
    std::vector<ComparisonRow> rows(sets.size());
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t workers =
        std::min<std::size_t>(sets.size(), threads > 0 ? static_cast<std::size_t>(threads) : cores);
    const RtsSmoother::Threads perRun = threadsPerRun(workers);
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t i = next++; i < sets.size(); i = next++)
            rows[i] = evaluateSet(recording, sets[i], cancel, perRun);
    };
    std::vector<std::thread> pool;
    for (std::size_t w = 1; w < workers; ++w)
        pool.emplace_back(work);
    work();
    for (std::thread& thread : pool)
        thread.join();
    return rows;
}

int bestComparisonRow(const std::vector<ComparisonRow>& rows, const std::string& column)
{
    const bool larger = column == "stance_f1";
    int best = -1;
    double bestValue = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const ComparisonRow& row = rows[i];
        if (!row.output.error.empty() || row.output.result.cancelled)
            continue;
        const double value = column == "end_to_start_m"     ? row.endToStart_m
                             : column == "end_to_start_pct" ? row.endToStartPct
                             : column == "armse_2d_m"       ? row.armse2d_m
                             : column == "stance_f1"        ? row.stanceF1
                                                            : std::nan("");
        if (std::isnan(value))
            continue;
        if (best < 0 || (larger ? value > bestValue : value < bestValue)) {
            best = static_cast<int>(i);
            bestValue = value;
        }
    }
    return best;
}

}  // namespace footpath
