// The Front tab's web engines (front/engine_worker.h) as state and answers, without drawing: for
// the view on screen, each engine's defaults and each tuned result (front/engine_candidates.h:
// the `tune --engine --out` files in the user's folder for them and those added by path), run in
// Chromium in the background and scored against the view's finished reference; their points join
// the front (origin "engine"). What the engines need and may lack - a glTF file (the browser loads
// the scene), Node.js, the browser and the pinned packages - is one line, and the engines are off.
#pragma once
#include "front/engine_worker.h"
#include "front/front_measurer.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ssao {

class EngineFront {
  public:
    // `wake` (may be empty) is called from the worker thread when a result arrives.
    explicit EngineFront(std::function<void()> wake = {}) : worker_(std::move(wake)) {}

    bool enabled = true;              // the Front tab's "engines" checkbox
    std::string modules;              // the npm packages ("" = the build folder's peers/node_modules)
    std::vector<std::string> engines; // which engines (empty = every table, engines/engine_table.h)
    std::vector<std::string> files;   // tune results added by path (besides the folder's)
    int frames = 5;                   // timed frames per candidate (median)

    // Measures on `v` (a glTF file `sceneFile`, tune results from `tunedDir`) unless it does already.
    void request(const FrontView& v, const std::string& sceneFile, const std::string& tunedDir);
    void cancel(); // the view left (its results stay cached)
    void poll();   // takes the worker's news (UI thread, once per frame)
    void rescan() { rescan_ = true; } // read the tuned files again on the next request
    // Adds a tune result by path; "" or why it does not read (one line).
    std::string addFile(const std::string& path);

    bool off() const { return !toolsError_.empty(); } // Node.js, the browser or the packages missing
    bool busy() const { return !jobKey_.empty() && !done_; }
    // One line: why the engines are off, that the scene is built in, or how far they are ("" idle).
    std::string status() const;
    const std::vector<std::string>& errors() const { return errors_; }           // engines failed here
    const std::vector<std::string>& tunedErrors() const { return tunedErrors_; } // files that do not read
    const std::vector<std::shared_ptr<const EngineSample>>& samples() const { return samples_; }
    std::shared_ptr<const EngineSample> sample(const std::string& label) const;
    // The measured samples as points of the front (those the browser could time).
    std::vector<FrontPoint> points() const;

  private:
    std::vector<std::string> engineList() const;
    std::vector<EngineCandidate> candidates(const std::string& tunedDir);

    EngineWorker worker_;
    std::string requestKey_, jobKey_;
    bool builtin_ = false, done_ = false, rescan_ = false;
    size_t total_ = 0;
    std::string running_;
    std::string toolsError_, toolsErrorModules_;
    std::vector<std::string> errors_, tunedErrors_;
    std::vector<std::shared_ptr<const EngineSample>> samples_;
    unsigned seen_ = ~0u;
    // By job key: a view's engine points come back at once when the view does.
    std::map<std::string, std::vector<std::shared_ptr<const EngineSample>>> cache_;
};

} // namespace ssao
