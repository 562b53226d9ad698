#pragma once

#include <string>
#include <vector>

namespace footpath {

/// Edit distance (insertions, deletions, substitutions and swaps of neighbours, case-insensitive).
std::size_t editDistance(const std::string& a, const std::string& b);

/// The candidates a mistyped word most likely meant, best first, at most `limit`: those within a
/// few edits of it (about a third of its length) or that share a long prefix with it. Empty when
/// nothing is close, so a wild guess is never offered.
std::vector<std::string> nearestNames(const std::string& word, const std::vector<std::string>& candidates,
                                      std::size_t limit = 3);

/// "; did you mean a, b or c?" for the nearest names, or empty when there are none.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates, std::size_t limit = 3);

}  // namespace footpath
