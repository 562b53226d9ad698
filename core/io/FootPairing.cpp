#include "io/FootPairing.h"

#include <algorithm>
#include <cctype>
#include <map>

namespace footpath {

namespace {

std::string fileName(const std::string& path)
{
    const std::size_t slash = path.find_last_of("/\\");
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string stemOf(const std::string& path)
{
    std::string name = fileName(path);
    if (const std::size_t dot = name.find_last_of('.'); dot != std::string::npos && dot > 0)
        name.resize(dot);
    return name;
}

std::string lowered(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

}  // namespace

FootSide footSideOfName(const std::string& path, std::string* trialName)
{
    const std::string stem = stemOf(path);
    const std::string lower = lowered(stem);
    static const std::pair<const char*, FootSide> endings[] = {{"lf", FootSide::Left},   {"rf", FootSide::Right},
                                                               {"left", FootSide::Left}, {"right", FootSide::Right},
                                                               {"l", FootSide::Left},    {"r", FootSide::Right}};
    for (const auto& [ending, side] : endings) {
        const std::string suffix(ending);
        if (lower.size() <= suffix.size() + 1 || lower.compare(lower.size() - suffix.size(), suffix.size(), suffix) != 0)
            continue;
        const char separator = lower[lower.size() - suffix.size() - 1];
        if (separator != '_' && separator != '-' && separator != '.' && separator != ' ')
            continue;
        if (trialName)
            *trialName = stem.substr(0, stem.size() - suffix.size() - 1);
        return side;
    }
    if (trialName)
        *trialName = stem;
    return FootSide::Unknown;
}

std::optional<FootPair> pairFeet(const std::string& first, const std::string& second, std::string& problem)
{
    std::string firstTrial, secondTrial;
    const FootSide firstSide = footSideOfName(first, &firstTrial);
    const FootSide secondSide = footSideOfName(second, &secondTrial);
    if (firstSide != FootSide::Unknown && firstSide == secondSide) {
        problem = fileName(first) + " and " + fileName(second) + " are both named as the "
                  + (firstSide == FootSide::Left ? "left" : "right") + " foot: open the left and the right file of one walk";
        return std::nullopt;
    }
    if (firstSide != FootSide::Unknown && secondSide != FootSide::Unknown && lowered(firstTrial) != lowered(secondTrial)) {
        problem = fileName(first) + " and " + fileName(second) + " are of different walks (" + firstTrial + ", "
                  + secondTrial + "): open the left and the right file of one walk";
        return std::nullopt;
    }
    FootPair pair;
    const bool swapped = firstSide == FootSide::Right || secondSide == FootSide::Left;
    pair.left = swapped ? second : first;
    pair.right = swapped ? first : second;
    if (firstSide == FootSide::Unknown || secondSide == FootSide::Unknown)
        pair.notes.push_back("the names do not say both feet: " + fileName(pair.left) + " is taken as the left foot and "
                             + fileName(pair.right) + " as the right");
    return pair;
}

std::optional<FootPair> footPairInFolder(const std::vector<std::string>& paths, std::string& problem)
{
    std::map<std::string, std::pair<std::string, std::string>> trials;  // lowered trial name -> left, right
    for (const std::string& path : paths) {
        std::string trial;
        const FootSide side = footSideOfName(path, &trial);
        if (side == FootSide::Left)
            trials[lowered(trial)].first = path;
        else if (side == FootSide::Right)
            trials[lowered(trial)].second = path;
    }
    std::vector<FootPair> pairs;
    for (const auto& [trial, files] : trials)
        if (!files.first.empty() && !files.second.empty())
            pairs.push_back({files.first, files.second, {}});
    if (pairs.size() == 1)
        return pairs.front();
    problem = pairs.empty() ? "the folder holds no left/right pair (files named like walk_lf.txt and walk_rf.txt)"
                            : "the folder holds " + std::to_string(pairs.size())
                                  + " left/right pairs: open the two files of one walk";
    return std::nullopt;
}

}  // namespace footpath
