// "Did you mean ...?": the valid name nearest a mistyped one - options and commands (app/cli/cli_util.h),
// parameter keys (--set, presets) and preset names alike.
#pragma once
#include <string>
#include <vector>

namespace ssao {

// The candidate nearest to `word` (edit distance), or "" when none is close.
std::string closestName(const std::string& word, const std::vector<std::string>& candidates);
// " (did you mean NAME?)" for the closest candidate, "" when none is close.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

} // namespace ssao
