// A benchmark's results as data: the run's facts, the sweep's configurations, every view's
// measurement and the per-configuration summaries; results.json written and read back, so
// `bench merge` rebuilds a run from the shards' folders (commands/merge/merge_command.cpp).
#pragma once
#include "measure/sweep.h"
#include "metrics/bench_summary.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ssao {

struct BenchRun {
    nlohmann::json facts; // runFacts() + size, frames, reference, scenes (with their viewpoints)
    Sweep sweep;
    std::vector<ViewResult> views;
    std::vector<ConfigSummary> summary;
    // One entry per run that measured rows (ViewResult::shard indexes it): {"shard": "K/N",
    // "hostname", "cpu", "gl_renderer", "date", "git_revision", "rows"}.
    nlohmann::json shards = nlohmann::json::array();
};

// What the run ranks by: facts.objective ("still" when absent; results_check.h checks it).
Objective runObjective(const BenchRun& run);

// results.json: the facts, the shards, every configuration (with its complete settings) and its
// summary, every view's result.
nlohmann::json resultsJson(const BenchRun& run);
// Reads `dir`/results.json written by resultsJson; the summaries are recomputed by the caller.
// Throws ssao::Error naming the file and the field on anything missing or malformed.
BenchRun readResults(const std::string& dir);
// The run that results.json's JSON describes, unchecked (results_check.h checks it); `path` names it.
BenchRun parseResults(const nlohmann::json& j, const std::string& path);

} // namespace ssao
