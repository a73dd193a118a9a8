#include "util/unique_suffix.h"

#include <algorithm>
#include <filesystem>
#include <set>

namespace fs = std::filesystem;

namespace ssao {

namespace {
// Every name `path` may be shown by, shortest first: stem, file name, then longer suffixes.
std::vector<std::string> candidates(const std::string& path) {
    const fs::path p(path);
    std::vector<fs::path> parts(p.begin(), p.end());
    while (!parts.empty() && parts.back().empty()) parts.pop_back(); // "dir/" ends in an empty part
    std::vector<std::string> out;
    if (parts.empty()) return {path};
    out.push_back(parts.back().stem().generic_string());
    for (size_t k = 1; k <= parts.size(); ++k) {
        fs::path s;
        for (size_t i = parts.size() - k; i < parts.size(); ++i)
            s /= parts[i];
        out.push_back(s.generic_string());
    }
    out.push_back(path);
    return out;
}
} // namespace

std::vector<std::string> shortestUniqueSuffixes(const std::vector<std::string>& paths,
                                                const std::vector<std::string>& taken) {
    std::vector<std::vector<std::string>> cands;
    for (const auto& p : paths)
        cands.push_back(candidates(p));
    std::vector<std::string> out;
    for (size_t i = 0; i < paths.size(); ++i) {
        std::set<std::string> others(taken.begin(), taken.end());
        for (size_t j = 0; j < paths.size(); ++j)
            if (j != i) others.insert(cands[j].begin(), cands[j].end());
        auto free = std::find_if(cands[i].begin(), cands[i].end(), [&](const std::string& c) {
            return !c.empty() && !others.count(c);
        });
        out.push_back(free != cands[i].end() ? *free : paths[i]);
    }
    return out;
}

} // namespace ssao
