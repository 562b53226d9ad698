#include "nav/MethodSets.h"

#include "io/NearestNames.h"
#include "metrics/Evaluation.h"

#include <algorithm>
#include <map>
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
    const std::vector<std::string>& known = methodTokens();
    return *std::min_element(known.begin(), known.end(), [&](const std::string& a, const std::string& b) {
        return editDistance(token, a) < editDistance(token, b);
    });
}

std::string knownTokensText()
{
    std::string text;
    for (const std::string& token : methodTokens())
        text += (text.empty() ? "" : ", ") + token;
    return text;
}

Parameters withAllMethodsOff(const Parameters& base)
{
    Parameters params = base;
    params.estimator = static_cast<int>(EstimatorKind::Ekf);
    params.use_zupt = params.use_zaru = params.use_hdr = params.use_iper = false;
    params.use_zuna = params.use_baro = params.use_mag_heading = false;
    return params;
}

/// Sets the method a token names; false if the token is unknown.
bool applyToken(const std::string& token, Parameters& params, bool& statesNamed)
{
    if (token == "zupt")
        params.use_zupt = true;
    else if (token == "zaru")
        params.use_zaru = true;
    else if (token == "hdr")
        params.use_hdr = true;
    else if (token == "iper")
        params.use_iper = true;
    else if (token == "zuna")
        params.use_zuna = true;
    else if (token == "baro")
        params.use_baro = true;
    else if (token == "mag")
        params.use_mag_heading = true;
    else if (token == "feliz")
        params.estimator = static_cast<int>(EstimatorKind::Feliz);
    else if (token == "rts")
        params.estimator = static_cast<int>(EstimatorKind::Smoother);
    else if (token == "9state" || token == "9")
        params.filter_states = static_cast<int>(FilterStates::Nine);
    else if (token == "15state" || token == "15")
        params.filter_states = static_cast<int>(FilterStates::Fifteen);
    else
        return false;
    statesNamed = statesNamed || token == "9state" || token == "9" || token == "15state" || token == "15";
    return true;
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

const std::vector<std::string>& methodTokens()
{
    static const std::vector<std::string> tokens{"zupt", "zaru", "hdr", "iper", "zuna", "baro", "mag", "feliz",
                                                 "rts", "9state", "15state"};
    return tokens;
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
                    + "'?); known: " + knownTokensText();
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
    std::vector<std::string> tokens;
    if (params.estimatorKind() == EstimatorKind::Feliz) {
        tokens.push_back("feliz");
    } else {
        const std::pair<bool, const char*> switches[] = {
            {params.use_zupt, "zupt"}, {params.use_zaru, "zaru"}, {params.use_hdr, "hdr"},
            {params.use_iper, "iper"}, {params.use_zuna, "zuna"}, {params.use_baro, "baro"},
            {params.use_mag_heading, "mag"}};
        for (const auto& [on, token] : switches)
            if (on)
                tokens.push_back(token);
        if (!tokens.empty() && params.filter_states != Parameters().filter_states)
            tokens.push_back(params.filterStates() == FilterStates::Fifteen ? "15state" : "9state");
        if (params.estimatorKind() == EstimatorKind::Smoother)
            tokens.push_back("rts");
    }
    std::string spec;
    for (std::size_t i = 0; i < tokens.size(); ++i)
        spec += (i ? "," : "") + tokens[i];
    return spec;
}

std::string methodSetLabel(const std::string& spec)
{
    static const std::map<std::string, std::string> labels{
        {"zupt", "ZUPT"}, {"zaru", "ZARU"}, {"hdr", "HDR"}, {"iper", "IPER"}, {"zuna", "ZUNA"},
        {"baro", "barometer"}, {"mag", "magnetometer"}, {"feliz", "Feliz"}, {"rts", "RTS smoother"}, {"9state", "9-state"},
        {"15state", "15-state"}, {"9", "9-state"}, {"15", "15-state"}};
    std::string label;
    std::istringstream in(spec);
    for (std::string token; std::getline(in, token, ',');) {
        const auto known = labels.find(token);
        label += (label.empty() ? "" : "+") + (known != labels.end() ? known->second : token);
    }
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
