// A web engine's AO, rendered for real: Node.js runs tools/peers/run_engine.mjs, which drives
// Debian's Chromium (playwright-core from the npm packages tools/peers/package-lock.json pins,
// installed by `make engine-modules` into the build folder) through one browser session a harness
// page, kept for the runner's life and fed batch after batch of jobs (a tune's search steps): one
// scene, several views (ssaolab's camera and R), many parameter sets (of one engine, or of several:
// bench --engines). Each job's AO comes back as a PGM, read here as AO in [0, 1] at the
// view's pixels, to be scored in-process with metrics/evaluate.h, as `render --score` scores it.
#pragma once
#include "base/image.h"
#include "engines/engine_table.h"
#include "util/process.h"

#include <nlohmann/json.hpp>

#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ssao {

struct EngineTools {
    std::string node;    // the Node.js program (found on PATH)
    std::string modules; // the installed node_modules
    std::string scripts; // the folder of run_engine.mjs, peers.js and the tables
};

// Node.js, Chromium (CHROMIUM or /usr/bin/chromium) and the pinned packages at the versions the
// table names; `modules` "" = the build folder's peers/node_modules (beside app/ssaolab). Anything
// missing throws one line naming what to install.
EngineTools locateEngineTools(const std::string& modules, const EngineTable& table);
// The same, its messages opening with `command` ("bench --engines") instead of `tune --engine`'s.
EngineTools locateEngineTools(const std::string& modules, const EngineTable& table, const std::string& command);

// The build folder's peers/node_modules, found from this binary's place in it ("" when unknown).
std::string defaultEngineModules();

struct EngineView {
    nlohmann::json camera; // metrics.json's camera: the file's coordinates, the fitted clip planes
    float radius = 0;      // R, scene units
};

struct EngineJob {
    int view = 0;
    std::map<std::string, double> values; // rows left out keep the make-peers settings
    int frames = 0;                       // 0: one image, no timing; else the median of this many frames
    std::map<std::string, double> scale;  // rows set to the make-peers value times this (a tune's relative settings)
    const EngineTable* table = nullptr;   // another engine than the runner's, in the same session (bench --engines)
    // A search's candidate, dropped (hung) once it takes 30 times what the runner's jobs took
    // (run_engine.mjs); any other job has the browser's whole time limit.
    bool droppable = false;
    // Droppable jobs of one group (a candidate on each of its views): once one is dropped the rest
    // come back hung without running - a candidate missing one view is never the best. -1: none.
    int group = -1;
};

struct EngineResult {
    Image ao;                             // 1 channel, [0, 1], top row first
    std::map<std::string, double> values; // what the pass ran with, every non-fixed row
    double aoMs = std::numeric_limits<double>::quiet_NaN(); // frame with the pass - frame without (frames > 0)
    // The fastest and slowest timed frame with the pass, less the same frame without (frames > 0).
    double aoMsMin = std::numeric_limits<double>::quiet_NaN(), aoMsMax = std::numeric_limits<double>::quiet_NaN();
    // Frames timed: the job's frames, or fewer once they took the harness's cap (harness.js kTimedMs).
    int timedFrames = 0;
    // The browser hung on this job past its time limit (a setting some GL driver never finishes):
    // no image; the session went on without it in a new browser.
    bool hung = false;
};

class EngineRunner {
  public:
    // Refuses a scene whose buffers or images the browser must not load (scene/load/browser_assets.h).
    EngineRunner(EngineTools tools, EngineTable table, std::string sceneFile, int width, int height,
                 std::vector<EngineView> views);
    ~EngineRunner(); // removes its work folder
    EngineRunner(const EngineRunner&) = delete;
    EngineRunner& operator=(const EngineRunner&) = delete;

    // Every job in the runner's session of its page; throws with the runner's last message when it
    // fails. A job the page hangs on past SSAOLAB_BROWSER_MAX_SECONDS comes back `hung` and the jobs after it run
    // in a new session, up to kMaxHungJobs in one call (then it throws); a droppable job's hang
    // (a search's candidate) never counts against that.
    std::vector<EngineResult> run(const std::vector<EngineJob>& jobs);
    static constexpr int kMaxHungJobs = 3;
    int sessions() const { return sessions_; }
    int batches() const { return batches_; } // run() calls, one per page each

  private:
    // One session of `page`'s engines.
    std::vector<EngineResult> runPage(const std::vector<EngineJob>& jobs, const std::string& page, int hung = 0);
    std::vector<EngineResult> afterHang(const std::vector<EngineJob>& jobs, const std::string& page, int hung,
                                        const std::string& dir, const std::string& failure);
    std::string serve(const std::string& page, const std::string& dir, const std::string& who);
    // One job's result as run_engine.mjs wrote it (DIR/jN.json and DIR/jN.pgm).
    EngineResult readResult(const std::string& dir, size_t i, const nlohmann::json& j, int frames);

    EngineTools tools_;
    EngineTable table_;
    std::string scene_, work_;
    int width_, height_;
    std::vector<EngineView> views_;
    int sessions_ = 0, batches_ = 0;
    std::map<std::string, std::unique_ptr<ChildProcess>> live_; // page -> its browser session
    std::map<int, std::vector<double>> jobSeconds_; // timed frames -> the last jobs' seconds (run_engine.mjs's limit)
};

// A PGM (or any image decodeImage reads) as AO: channel 0, width x height, every value in [0, 1].
Image readEngineAo(const std::string& file, int width, int height);

} // namespace ssao
