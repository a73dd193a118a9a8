// `ssaolab bench`: run time against error for every configuration of a sweep, on scenes and
// viewpoints, against the cached ray-traced reference — results.csv/json, summary.csv, a Markdown
// report of the Pareto front and a plot (matplotlib, app/bench/plot_pareto.py).
#pragma once
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ssao {

struct BenchOptions {
    std::vector<std::string> scenes; // default: builtin:showcase
    std::string sweep = "builtin";
    std::string size = "1280x720";
    int views = 3;   // the scene's camera + orbits
    int frames = 20; // timed frames per configuration and view (median, min, max)
    int warmup = 2;  // untimed frames first (shader compilation, caches)
    int referenceRays = 512;
    std::string referenceVariant = "visibility";
    float radiusScene = 0.05f; // R = radiusScene x the scene's bounding-box diagonal
    std::string out = "bench-out";
    std::string presetDir;
    bool plot = true;
    bool quiet = false;
};

void addBenchOptions(CLI::App& cmd, BenchOptions& o);
// Throws ssao::Error on bad input; returns the exit code.
int runBench(const BenchOptions& o);

} // namespace ssao
