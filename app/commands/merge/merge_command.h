// `ssaolab bench merge DIR...`: the output folders of `bench --shard K/N` runs joined into one
// run's results and reports, after checking that they are parts of the same benchmark.
#pragma once
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ssao {

struct BenchMergeOptions {
    std::vector<std::string> dirs; // shard output folders
    std::string out = "bench-merged";
    double budgetMs = 0, maxError = 0, budgetRatio = 0;
    std::string objective; // still | motion; "" = the one the shards ran with
    bool plot = true;
    bool quiet = false;
};

void addBenchMergeOptions(CLI::App& cmd, BenchMergeOptions& o);
// Throws ssao::Error on bad input; returns the exit code.
int runBenchMerge(const BenchMergeOptions& o);

} // namespace ssao
