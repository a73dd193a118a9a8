// The rows of `ssaolab skips` and their files: skips.json (every row) and skips.md (one table per
// skip, docs/bench/skips.md).
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ssao {

struct SkipRow {
    std::string skip;    // "dirty", "sky", "adaptive", "cull", "targets", "idle"
    std::string scene, view, variant;
    std::string measured; // what the times cover, e.g. "ao + denoise GPU ms"
    double with = 0, without = 0;         // medians, ms
    double wallWith = 0, wallWithout = 0; // frame wall time (glFinish to glFinish), ms
    double errorChange = 0;               // exact skips: max |AO difference| over geometry
    nlohmann::json extra = nlohmann::json::object(); // counters, RMSEs, passes run
    double ratio() const { return without > 0 ? with / without : 0.0; }
};

struct SkipsRun {
    nlohmann::json facts;
    std::vector<SkipRow> rows;
};

std::string skipsMarkdown(const SkipsRun& run);
void writeSkipsFiles(const SkipsRun& run, const std::string& dir);

} // namespace ssao
