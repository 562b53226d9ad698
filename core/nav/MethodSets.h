#pragma once

#include "Recording.h"
#include "nav/Parameters.h"
#include "nav/Pipeline.h"

#include <atomic>
#include <string>
#include <vector>

namespace footpath {

/// A named combination of the methods for the comparison mode, e.g. "zupt,zaru,hdr".
struct MethodSet {
    std::string name;   ///< the tokens as given, normalised ("zupt,zaru,hdr")
    Parameters params;  ///< base parameters with exactly the named methods on
};

/// The tokens a method set is written with, in a stable order: zupt, zaru, hdr, iper, zuna, baro,
/// mag, feliz, 9state, 15state.
std::vector<std::string> methodTokens();

/// One method set from a comma-separated list of tokens. Every method not named is off; the
/// detector, noise and method parameters come from base. "zaru" means the 15-state filter unless
/// "9state" is named too (ZARU corrects the gyro-bias states, which 9 states hold at zero); without
/// either, the filter size is base's. "feliz" replaces the filter by Feliz 2009's de-drift. An
/// unknown token gives an error naming it and the nearest known token, and an empty optional.
std::optional<MethodSet> parseMethodSet(const std::string& spec, const Parameters& base, std::string& error);
/// The set params runs, written as parseMethodSet reads it ("zupt,hdr,baro"; "feliz" for Feliz's
/// estimator; the filter size is named only when it is not the default's): what a report's
/// "method set" line and the CLI's "methods" line show. Empty when no method is on.
std::string methodSetSpec(const Parameters& params);
/// How people write a set: "ZUPT+ZARU+HDR" for "zupt,zaru,hdr" (barometer, magnetometer, Feliz,
/// 9-state and 15-state spelled out).
std::string methodSetLabel(const std::string& spec);
/// Several sets separated by ';' ("zupt;zupt,zaru;feliz"); empty with error on the first bad one.
std::vector<MethodSet> parseMethodSets(const std::string& specs, const Parameters& base, std::string& error);

/// The comparison a user gets before choosing: ZUPT; ZUPT+ZARU; +HDR; +HDR+IPER; +HDR+IPER+ZUNA;
/// ZUPT+barometer; Feliz; 9-state against 15-state.
std::vector<MethodSet> suggestedMethodSets(const Parameters& base);
std::string suggestedMethodSetsSpec();

/// One set's estimate and the figures the comparison table shows (NaN where the recording has no
/// reference for that figure).
struct ComparisonRow {
    MethodSet set;
    PipelineOutput output;
    double endToStart_m = 0.0;
    double endToStartPct = 0.0;  ///< of the estimated path length
    double pathLength_m = 0.0;
    double heightChange_m = 0.0;  ///< last minus first estimated height
    double armse2d_m = std::nan("");
    double stanceF1 = std::nan("");
};

/// Runs every set on the recording, up to `threads` at once (0: one per core); rows in the order
/// of sets. cancel, when given and set, stops the runs (their rows say cancelled).
std::vector<ComparisonRow> runComparison(const Recording& recording, const std::vector<MethodSet>& sets,
                                         int threads = 0, const std::atomic<bool>* cancel = nullptr);

/// Index of the best row for a column (smallest error; for stanceF1 the largest), or -1 when no
/// row has a value. column: "end_to_start_m", "end_to_start_pct", "armse_2d_m", "stance_f1".
int bestComparisonRow(const std::vector<ComparisonRow>& rows, const std::string& column);

}  // namespace footpath
