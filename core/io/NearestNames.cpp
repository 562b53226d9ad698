#include "io/NearestNames.h"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace footpath {

namespace {

std::string lowercase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return text;
}

std::size_t commonPrefix(const std::string& a, const std::string& b)
{
    const auto mismatch = std::mismatch(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(std::min(a.size(), b.size())),
                                        b.begin());
    return static_cast<std::size_t>(mismatch.first - a.begin());
}

/// How far apart two names are for ranking: the edit distance, lowered when one starts like the
/// other, because a user who types "gyr" or "acc_std" means a name that begins so.
std::size_t rank(const std::string& word, const std::string& candidate)
{
    const std::size_t distance = editDistance(word, candidate);
    const std::size_t prefix = commonPrefix(word, candidate);
    return prefix >= 3 && prefix == std::min(word.size(), candidate.size()) ? std::min<std::size_t>(distance, 1)
                                                                          : distance;
}

bool isClose(const std::string& word, const std::string& candidate)
{
    const std::size_t allowed = std::max<std::size_t>(1, word.size() / 3);
    const std::size_t prefix = commonPrefix(word, candidate);
    return editDistance(word, candidate) <= allowed || (prefix >= 3 && prefix >= word.size() / 2);
}

}  // namespace

std::size_t editDistance(const std::string& first, const std::string& second)
{
    const std::string a = lowercase(first);
    const std::string b = lowercase(second);
    // Optimal string alignment: the Levenshtein table plus a swap of two neighbours as one edit.
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
    std::iota(d[0].begin(), d[0].end(), std::size_t{0});
    for (std::size_t i = 1; i <= a.size(); ++i) {
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[a.size()][b.size()];
}

std::vector<std::string> nearestNames(const std::string& word, const std::vector<std::string>& candidates,
                                      std::size_t limit)
{
    const std::string key = lowercase(word);
    std::vector<std::pair<std::size_t, std::string>> close;
    for (const std::string& candidate : candidates)
        if (isClose(key, lowercase(candidate)))
            close.emplace_back(rank(key, lowercase(candidate)), candidate);
    std::stable_sort(close.begin(), close.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::string> names;
    for (std::size_t i = 0; i < close.size() && names.size() < limit; ++i)
        names.push_back(close[i].second);
    return names;
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates, std::size_t limit)
{
    const std::vector<std::string> names = nearestNames(word, candidates, limit);
    if (names.empty())
        return {};
    std::string text = "; did you mean ";
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0)
            text += i + 1 == names.size() ? " or " : ", ";
        text += names[i];
    }
    return text + "?";
}

}  // namespace footpath
