#include "front/front_motion.h"

#include "settings/params.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <thread>

namespace ssao {

namespace {
std::string settingsKey(const Candidate& c) {
    return toEffectiveJson(c.settings).dump();
}
} // namespace

std::string MotionView::key() const {
    std::ostringstream k;
    k.precision(9);
    k << sceneVersion << "|" << camera.eye.x << "," << camera.eye.y << "," << camera.eye.z << "|"
      << camera.target.x << "," << camera.target.y << "," << camera.target.z << "|" << camera.up.x << ","
      << camera.up.y << "," << camera.up.z << "|" << camera.fovYDeg << "|" << camera.nearZ << "|"
      << camera.farZ << "|" << int(camera.projectionKind) << int(camera.depth) << "|" << width << "x"
      << height << "|" << spec.frames << "," << spec.orbitDeg << "," << spec.dolly << "|" << settings.radius
      << "," << settings.samples << "," << int(settings.variant) << "|" << cacheDir;
    return k.str();
}

std::pair<int, int> motionSize(int w, int h, int maxW, int maxH) {
    const double s = std::min({1.0, double(maxW) / std::max(w, 1), double(maxH) / std::max(h, 1)});
    return {std::max(1, int(std::lround(w * s))), std::max(1, int(std::lround(h * s)))};
}

void FrontMotion::request(const MotionView& view, const std::vector<Candidate>& candidates) {
    std::string key = view.key() + "#";
    for (const auto& c : candidates)
        key += settingsKey(c) + ";";
    if (key == key_) return;
    const std::string viewKey = view.key();
    if (viewKey != viewKey_) { // another view: its own references
        cancel();
        viewKey_ = viewKey;
        view_ = view;
        MotionTruthWorker::Job job;
        job.key = viewKey;
        job.scene = view.scene;
        job.start = view.camera;
        job.width = view.width, job.height = view.height;
        job.spec = view.spec;
        job.settings = view.settings;
        // One core stays with the renderer (llvmpipe draws the frames on the CPU too).
        job.settings.threads = std::max(1, int(std::thread::hardware_concurrency()) - 1);
        job.cacheDir = view.cacheDir;
        worker_.start(std::move(job));
    }
    key_ = key;
    pending_.clear();
    current_.reset();
    total_ = candidates.size();
    done_ = 0;
    if (cache_.size() > 32 && !cache_.count(viewKey_)) cache_.clear();
    const auto& cached = cache_[viewKey_];
    for (const auto& c : candidates)
        if (cached.count(settingsKey(c)))
            ++done_;
        else
            pending_.push_back(c);
    std::reverse(pending_.begin(), pending_.end()); // popped from the back: in the list's order
}

void FrontMotion::cancel() {
    worker_.cancel();
    truth_.reset();
    pending_.clear();
    current_.reset();
    key_.clear();
    viewKey_.clear();
    total_ = done_ = 0;
    secondsSpent_ = 0;
}

bool FrontMotion::tracing() const {
    if (!hasView() || truth_) return false;
    const MotionTruthWorker::State s = worker_.state();
    return s.key == viewKey_ && s.error.empty();
}

void FrontMotion::work(double budgetMs) {
    if (!hasView()) return;
    if (!truth_) {
        MotionTruthWorker::State s = worker_.state();
        if (s.key != viewKey_ || !s.truth) return;
        truth_ = std::move(s.truth);
    }
    if (!measuring()) return;
    const auto t0 = std::chrono::steady_clock::now();
    if (!renderer_) {
        renderer_ = std::make_unique<Renderer>(shaderDir_);
        renderer_->setWanted(std::set<std::string>{"ao.denoised"}); // what is judged, as in bench
    }
    Renderer& r = *renderer_;
    r.setSize(truth_->width, truth_->height);
    if (uploaded_ != view_.scene) { // setScene uploads the geometry: once per scene
        r.setScene(*view_.scene);
        uploaded_ = view_.scene;
    }
    double spent = 0;
    do {
        if (!current_) {
            currentKey_ = settingsKey(pending_.back());
            current_.emplace(pending_.back().settings, *truth_);
            pending_.pop_back();
        }
        if (current_->step(r)) {
            cache_[viewKey_][currentKey_] = current_->result();
            current_.reset();
            ++done_;
        }
        spent = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    } while (measuring() && spent < budgetMs);
    secondsSpent_ += spent * 1e-3;
}

FrontMotion::Progress FrontMotion::progress() const {
    Progress p;
    if (!hasView()) return p;
    const MotionTruthWorker::State s = worker_.state();
    p.traceFraction = truth_ ? 1.0 : s.key == viewKey_ ? s.fraction : 0.0;
    if (!truth_ && s.key == viewKey_) p.error = s.error;
    p.done = done_, p.total = total_;
    const double inFlight = current_ ? current_->progress() : 0.0;
    p.fraction =
        total_ ? std::min((double(done_) + inFlight) / double(total_), measuring() ? 0.999 : 1.0) : 0.0;
    p.seconds = secondsSpent_;
    return p;
}

const MotionMetrics* FrontMotion::find(const Candidate& c) const {
    const auto v = cache_.find(viewKey_);
    if (v == cache_.end()) return nullptr;
    const auto it = v->second.find(settingsKey(c));
    return it == v->second.end() ? nullptr : &it->second;
}

} // namespace ssao
