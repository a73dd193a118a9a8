// `ssaolab bench`: run time against error for every configuration of a sweep, on scenes and
// viewpoints, against the cached ray-traced reference — results.csv/json, summary.csv, a Markdown
// report of the Pareto front, report.html and a plot (matplotlib, tools/plot_pareto.py).
// `--shard K/N` runs a part of the work; `ssaolab bench merge DIR...` (commands/merge/) joins the parts.
#pragma once
#include "results/bench_answer.h"
#include "commands/bench/bench_engines.h"
#include "results/bench_results.h"
#include "scene/camera_path.h"

#include <cmath>
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
    int views = 3;   // the scene's camera (or --camera) + orbits
    std::string camera; // --camera: the first viewpoint of every scene, file coordinates ("" = its own)
    int frames = 20; // timed frames per configuration and view (median, min, max)
    int warmup = 2;  // untimed frames first (shader compilation, caches)
    int referenceRays = 512;
    std::string referenceVariant = "visibility";
    float radiusScene = 0.05f; // R = radiusScene x the scene's bounding-box diagonal
    std::string out = "bench-out";
    std::string presetDir;
    std::string shaderDir;                // default: the installation's (or source tree's) shaders/
    std::string baseline = "learnopengl"; // the preset every row is compared with
    bool oracle = true;                   // trace the screen-space oracle: split every error
    int oracleLayers = 1;                 // its depth layers (2: a deep G-buffer)
    double oracleThickness = 1.0;         // its surfaces' thickness, x R (inf: a height field)
    int oracleGuard = 0;                  // pixels its G-buffer holds beyond each edge of the frame
    std::string shard = "1/1";            // K/N: run only this part of the work (results/shard.h)
    bool motion = false;                  // also score every row along a camera path (measure/motion_measure.h)
    CameraPathSpec motionPath;
    double budgetMs = 0, maxError = 0;    // the question to answer (results/bench_answer.h); 0 = none
    double budgetRatio = 0;               // a budget as a multiple of the baseline's time; 0 = none
    std::string objective = "still";      // what the front and the answers rank by; "motion" implies --motion
    BenchEngineOptions engines;           // web engines as rows (commands/bench/bench_engines.h)
    bool plot = true;
    bool quiet = false;
};

void addBenchOptions(CLI::App& cmd, BenchOptions& o);
// Throw ssao::Error on bad input; return the exit code.
int runBench(const BenchOptions& o);

} // namespace ssao
