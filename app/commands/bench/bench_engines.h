// `bench --engines`: web engines (engines/engine_table.h) as rows of a sweep beside ssaolab's own
// configurations. Each engine runs for real (engines/engine_runner.h) on each view of each glTF scene
// at the bench's camera (the clip planes ssaolab's renderer fits, which the reference traced), size
// and R, every view and engine of a scene in one browser session; its AO is scored in-process
// against the view's reference and screen-space oracle as measure/measurement.h scores a
// configuration, and its time is the runner's AO ms (frame with the pass - frame without, median,
// min and max of --frames). An engine's row on a view is a work unit like any configuration's
// (results/shard.h): the shard that owns it runs it, beside the baseline every shard measures there.
#pragma once
#include "results/bench_results.h"
#include "engines/engine_runner.h"
#include "reference/reference_ao.h"
#include "scene/camera.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ssao {

struct Scene;

struct BenchEngineOptions {
    std::vector<std::string> names;    // --engines: engine names (comma-separated), or all
    std::vector<std::string> settings; // --engine-settings FILE (repeatable): `tune --engine`'s --out
    std::string modules;               // --engine-modules DIR (default: the build folder's peers/node_modules)
};

void addBenchEngineOptions(CLI::App& cmd, BenchEngineOptions& o);

// What a view hands the engines: everything its rows are scored with.
struct EngineViewWork {
    std::string viewpoint;
    Camera camera; // as rendered (fitted clip planes), scene frame
    ReferenceImage ref;
    std::optional<ReferenceImage> oracle; // none with --no-oracle
    ErrorMetrics screen;                  // the oracle against the reference
    double baselineMs = 0;                // the baseline's median on this view, this run
    std::string thumbs;                   // thumbnail folder ("" none: not the scene's first view)
    std::vector<size_t> configs;          // the engine rows of this view that this run owns
};

class BenchEngines {
  public:
    // Reads the engines and settings files and finds Node.js, Chromium and the packages; refuses
    // (one line, before any work) an unknown engine, a builtin scene, a settings file that is not
    // `tune --engine`'s for an installed table, a missing tool. Nothing to do without options.
    BenchEngines(const BenchEngineOptions& o, const std::vector<std::string>& sceneSpecs, int width, int height,
                 int frames);
    bool active() const { return !rows_.empty(); }
    // Appends the engines' configurations to the sweep (after its own); keeps their indices.
    void appendTo(Sweep& sweep);
    bool isEngine(size_t config) const { return config >= first_ && config < first_ + rows_.size(); }

    void addView(EngineViewWork w) { pending_.push_back(std::move(w)); }
    // The pending views of this scene in one browser session; their rows appended to run.views.
    void runScene(const std::string& spec, const Scene& scene, float radius, bool quiet, BenchRun& run);

  private:
    struct Row {
        size_t table; // into tables_
        BenchConfig config;
        std::map<std::string, double> values, scale;
        std::map<std::string, std::pair<double, int>> perRadius; // factor x R^exponent
    };
    void addSettingsFile(const std::string& path, std::vector<Row>& tuned);
    size_t tableOf(const std::string& engine);

    std::vector<EngineTable> tables_;
    std::vector<Row> rows_;
    EngineTools tools_;
    int width_, height_, frames_;
    size_t first_ = 0;
    std::vector<EngineViewWork> pending_;
};

} // namespace ssao
