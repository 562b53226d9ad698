#pragma once

#include <optional>
#include <string>
#include <vector>

namespace footpath {

enum class FootSide { Unknown, Left, Right };

/// The foot a file name says it was recorded on: its stem (without folder and extension) ends in
/// `_lf`/`_rf` (the IPOL MTw files), `_left`/`_right` or `_l`/`_r`, after `_`, `-`, `.` or a space,
/// in any case. trialName gets the stem without that ending ("1-4" for "1-4_lf.txt").
FootSide footSideOfName(const std::string& path, std::string* trialName = nullptr);

/// The left and right file of one trial.
struct FootPair {
    std::string left, right;
    std::vector<std::string> notes;  ///< how the sides were decided, when the names do not say it
};

/// Two files opened together as the two feet of one walk. The names decide the sides; when they
/// say nothing the first is taken as the left (with a note). Nothing, with problem set, when both
/// names say the same foot or the two names are of different trials (`1-4_lf`, `10-1_rf`).
std::optional<FootPair> pairFeet(const std::string& first, const std::string& second, std::string& problem);

/// The one left/right pair among a folder's file names (full paths); nothing, with problem set,
/// when there is none or more than one (then the folder holds several trials: open two files).
std::optional<FootPair> footPairInFolder(const std::vector<std::string>& paths, std::string& problem);

}  // namespace footpath
