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
std::string listKey(const std::vector<Candidate>& c) {
    std::string k;
    for (const auto& x : c)
        k += toEffectiveJson(x.settings).dump() + (x.current ? "*" : "") + ";";
    return k;
}
} // namespace

void FrontMeasurer::request(const FrontView& view, std::vector<Candidate> candidates) {
    const std::string key = view.key() + "#" + listKey(candidates);
    if (key == key_) return;
    cancel();
    key_ = key;
    view_ = view;
    total_ = candidates.size();
    if (auto it = cache_.find(key); it != cache_.end()) {
        points_ = it->second;
        return;
    }
    pending_ = std::move(candidates);
    std::reverse(pending_.begin(), pending_.end()); // popped from the back: the baseline first
}

void FrontMeasurer::cancel() {
    pending_.clear();
    current_.reset();
    points_.clear();
    key_.clear();
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
    if (!busy()) cache_[key_] = points_;
}

void FrontMeasurer::finishCurrent() {
    FrontPoint p;
    p.candidate = std::move(current_->first);
    p.result = current_->second.result();
    current_.reset();
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
