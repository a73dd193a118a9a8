// What results.json may hold, checked before anything is merged or reported: a shard's folder comes
// from another machine (a CI matrix, a job array), so every fact of it is foreign input. Types,
// ranges, finiteness, sizes, rows of scenes and viewpoints that the run names, each row once.
// Pure: no files, no GL (tests/fuzz/fuzz_shard.cpp drives it).
#pragma once
#include "results/bench_results.h"

#include <nlohmann/json.hpp>

#include <string>

namespace ssao {

constexpr size_t kMaxResultRows = 1000000;
constexpr size_t kMaxResultScenes = 256;
constexpr size_t kMaxResultViewpoints = 1024; // per scene
constexpr size_t kMaxResultText = 4096;       // bytes of any name, label or fact

// Throws ssao::Error("ORIGIN: FIELD ...") naming the first fact or row that is not what a run writes.
void checkResults(const BenchRun& run, const std::string& origin);

// results.json's text (as read from a shard folder) to a checked run; `origin` names the file.
BenchRun parseResultsText(const std::string& text, const std::string& origin);

} // namespace ssao
