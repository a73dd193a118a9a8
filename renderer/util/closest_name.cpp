#include "util/closest_name.h"

#include <algorithm>
#include <cctype>

namespace ssao {

namespace {
// Letters differing only in case cost nothing: "N8AO" is n8ao mistyped, not another name.
bool sameLetter(char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
}

size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (sameLetter(a[i - 1], b[j - 1]) ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}
} // namespace

std::string closestName(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    size_t bestD = std::string::npos;
    for (const auto& c : candidates) {
        const size_t d = editDistance(word, c);
        if (d < bestD) bestD = d, best = c;
    }
    // Close: at most a third of the word's letters wrong (typos, not another word).
    return bestD <= std::max<size_t>(2, word.size() / 3) ? best : "";
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
    const std::string near = closestName(word, candidates);
    return near.empty() ? "" : " (did you mean " + near + "?)";
}

} // namespace ssao
