#include "front/engine_front.h"

#include "settings/preset.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ssao {

namespace {
constexpr size_t kCachedViews = 16;

std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v)
        s += x + ";";
    return s;
}
} // namespace

std::vector<std::string> EngineFront::engineList() const {
    return engines.empty() ? engineNames() : engines;
}

std::vector<EngineCandidate> EngineFront::candidates(const std::string& tunedDir) {
    const std::vector<std::string> names = engineList();
    std::vector<EngineCandidate> out = engineDefaultCandidates(names);
    for (EngineCandidate& c : tunedEnginesIn(tunedDir, names, tunedErrors_))
        out.push_back(std::move(c));
    for (const std::string& f : files) {
        try {
            EngineCandidate c = tunedEngineCandidate(f);
            const bool seen = std::any_of(out.begin(), out.end(), [&](const EngineCandidate& o) { return o.label == c.label; });
            if (!seen && std::find(names.begin(), names.end(), c.engine) != names.end()) out.push_back(std::move(c));
        } catch (const std::exception& e) {
            tunedErrors_.push_back(oneLine(e.what()));
        }
    }
    return out;
}

void EngineFront::request(const FrontView& v, const std::string& sceneFile, const std::string& tunedDir) {
    if (modules != toolsErrorModules_) toolsError_.clear(); // another folder may hold the packages
    if (!enabled || off()) {
        cancel();
        return;
    }
    const std::string key = v.key() + "|" + sceneFile + "|" + tunedDir + "|" + modules + "|" + joined(engines) + "|" +
                            joined(files) + "|" + std::to_string(frames);
    if (key == requestKey_ && !rescan_) return;
    rescan_ = false;
    cancel();
    requestKey_ = key;
    builtin_ = sceneFile.rfind("builtin:", 0) == 0;
    if (builtin_ || !v.scene || !v.reference) return;
    std::vector<EngineCandidate> cands = candidates(tunedDir);
    jobKey_ = key + "#";
    for (const EngineCandidate& c : cands)
        jobKey_ += c.label + "=" + c.file + ";";
    total_ = cands.size();
    if (const auto it = cache_.find(jobKey_); it != cache_.end()) {
        samples_ = it->second;
        done_ = true;
        return;
    }
    EngineWorker::Job job{jobKey_, sceneFile, v.scene->name, cameraToJson(cameraToFile(v.camera, *v.scene)),
                          v.radius, v.width, v.height, v.reference, std::move(cands), modules, frames};
    worker_.start(std::move(job));
}

void EngineFront::cancel() {
    if (requestKey_.empty()) return;
    if (busy()) worker_.cancel();
    requestKey_.clear(), jobKey_.clear(), running_.clear();
    builtin_ = done_ = false;
    total_ = 0;
    errors_.clear(), tunedErrors_.clear(), samples_.clear();
}

void EngineFront::poll() {
    if (!busy()) return;
    const EngineWorker::State st = worker_.state();
    if (st.version == seen_ || st.key != jobKey_) return;
    seen_ = st.version;
    samples_ = st.samples;
    running_ = st.running;
    errors_ = st.errors;
    done_ = st.done;
    if (!st.toolsError.empty()) {
        toolsError_ = st.toolsError, toolsErrorModules_ = modules;
        cancel();
        return;
    }
    if (!done_) return;
    if (cache_.size() >= kCachedViews) cache_.clear();
    cache_[jobKey_] = samples_;
}

std::string EngineFront::addFile(const std::string& path) {
    try {
        tunedEngineCandidate(path);
    } catch (const std::exception& e) {
        return oneLine(e.what());
    }
    if (std::find(files.begin(), files.end(), path) == files.end()) files.push_back(path);
    return "";
}

std::string EngineFront::status() const {
    if (off()) return "engines are off: " + toolsError_;
    if (!enabled || requestKey_.empty()) return "";
    if (builtin_) return "engines load glTF files; this scene is built in";
    char b[200];
    if (!done_)
        std::snprintf(b, sizeof b, "engines: %s in Chromium (%zu / %zu measured)",
                      running_.empty() ? "starting" : running_.c_str(), samples_.size(), total_);
    else
        std::snprintf(b, sizeof b, "engines: %zu of %zu measured in Chromium%s", samples_.size(), total_,
                      errors_.empty() ? "" : " (some failed: below)");
    return b;
}

std::shared_ptr<const EngineSample> EngineFront::sample(const std::string& label) const {
    for (const auto& s : samples_)
        if (s->candidate.label == label) return s;
    return nullptr;
}

std::vector<FrontPoint> EngineFront::points() const {
    std::vector<FrontPoint> out;
    for (const auto& s : samples_) {
        if (!(s->aoMs > 0)) continue; // below the browser's timer: no place on a log time axis
        FrontPoint p;
        p.candidate.label = s->candidate.label;
        p.candidate.origin = "engine";
        p.result.gpuMs = p.result.gpuMsMin = p.result.gpuMsMax = s->aoMs;
        p.result.error = s->error;
        p.result.rmseFirstFrame = s->error.rmse;
        p.score = s->error.rmse;
        out.push_back(std::move(p));
    }
    return out;
}

} // namespace ssao
