#include "front/front_measurer.h"

#include "metrics/bench_summary.h"
#include "settings/params.h"

#include <cmath>
#include <set>
#include <sstream>

namespace ssao {

std::string FrontView::key() const {
    std::ostringstream k;
    k.precision(9);
    k << sceneVersion << "|" << camera.eye.x << "," << camera.eye.y << "," << camera.eye.z << "|" << camera.target.x
      << "," << camera.target.y << "," << camera.target.z << "|" << camera.up.x << "," << camera.up.y << ","
      << camera.up.z << "|" << camera.fovYDeg << "|" << camera.nearZ << "|" << camera.farZ << "|"
      << int(camera.projectionKind) << int(camera.depth) << "|" << width << "x" << height << "|" << radius << "|"
      << (reference ? reference->samples : 0);
    return k.str();
}

namespace {
std::string settingsKey(const Candidate& c) {
    return toEffectiveJson(c.settings).dump();
}
} // namespace

void FrontMeasurer::request(const FrontView& view, std::vector<Candidate> candidates) {
    std::string key = view.key() + "#";
    for (const auto& c : candidates)
        key += settingsKey(c) + (c.current ? "*" : "") + ";";
    if (key == key_) return;
    cancel();
    key_ = key;
    viewKey_ = view.key();
    view_ = view;
    total_ = candidates.size();
    // What this view already measured (an earlier visit, or the same presets before a slider moved
    // the current setting) comes from the cache; the rest is measured, the baseline first.
    if (cache_.size() > 32 && !cache_.count(viewKey_)) cache_.clear();
    const auto& cached = cache_[viewKey_];
    for (auto& c : candidates) {
        const auto it = cached.find(settingsKey(c));
        if (it == cached.end()) {
            pending_.push_back(std::move(c));
            continue;
        }
        FrontPoint p = it->second;
        p.candidate = std::move(c); // this list's label and flags
        points_.push_back(std::move(p));
    }
    std::reverse(pending_.begin(), pending_.end()); // popped from the back: in the list's order
    updateFront();
}

void FrontMeasurer::cancel() {
    pending_.clear();
    current_.reset();
    points_.clear();
    key_.clear();
    viewKey_.clear();
    total_ = 0;
    secondsSpent_ = 0;
    stepsDone_ = 0;
}

void FrontMeasurer::work(double budgetMs) {
    if (!busy()) return;
    const auto t0 = std::chrono::steady_clock::now();
    if (!renderer_) {
        renderer_ = std::make_unique<Renderer>(shaderDir_);
        renderer_->setWanted(std::set<std::string>{"ao.denoised"}); // what is judged, as in bench
    }
    Renderer& r = *renderer_;
    r.setSize(view_.width, view_.height);
    if (uploaded_ != view_.scene) { // setScene uploads the geometry: once per scene
        r.setScene(*view_.scene);
        uploaded_ = view_.scene;
    }
    r.setCamera(view_.camera);
    double spent = 0;
    do {
        if (!current_) {
            Candidate c = std::move(pending_.back());
            pending_.pop_back();
            Settings s = c.settings;
            current_.emplace(std::move(c), Measurement(s, warmup_, frames_));
        }
        if (current_->second.step(r, *view_.reference)) finishCurrent();
        ++stepsDone_;
        spent = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    } while (busy() && spent < budgetMs);
    secondsSpent_ += spent * 1e-3;
}

void FrontMeasurer::finishCurrent() {
    FrontPoint p;
    p.candidate = std::move(current_->first);
    p.result = current_->second.result();
    current_.reset();
    cache_[viewKey_][settingsKey(p.candidate)] = p;
    points_.push_back(std::move(p));
    updateFront();
}

void FrontMeasurer::updateFront() {
    const size_t b = baselineIndex();
    std::vector<double> t, e;
    for (auto& p : points_) {
        if (b != std::string::npos) {
            p.timeRatio = p.result.gpuMs / points_[b].result.gpuMs;
            p.rmseRatio = p.result.error.rmse / points_[b].result.error.rmse;
        }
        t.push_back(p.result.gpuMs), e.push_back(p.result.error.rmse);
        p.score = p.result.error.rmse, p.scoreRatio = p.rmseRatio;
    }
    const std::vector<bool> f = paretoFront(t, e);
    for (size_t i = 0; i < points_.size(); ++i)
        points_[i].front = f[i];
}

size_t FrontMeasurer::baselineIndex() const {
    for (size_t i = 0; i < points_.size(); ++i)
        if (points_[i].candidate.baseline) return i;
    return std::string::npos;
}

FrontMeasurer::Progress FrontMeasurer::progress() const {
    Progress p;
    p.total = total_;
    p.done = points_.size();
    // Frames: each candidate needs about 1 + warm-up + timed frames (temporal ones more).
    const double per = 1.0 + warmup_ + frames_;
    const double doneFrames = double(p.done) * per + (current_ ? current_->second.progress() * per : 0.0);
    const double totalFrames = std::max(double(total_) * per, 1.0);
    p.fraction = busy() ? std::min(doneFrames / totalFrames, 0.999) : (total_ ? 1.0 : 0.0);
    p.seconds = secondsSpent_;
    p.etaSeconds = doneFrames > 0 ? secondsSpent_ / doneFrames * (totalFrames - doneFrames) : 0.0;
    return p;
}

} // namespace ssao
