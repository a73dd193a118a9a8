#include "measure/motion_measure.h"

#include "cli/cli_util.h"
#include "gl/readback.h"
#include "metrics/evaluate.h"
#include "metrics/reprojection.h"
#include "scene/view_fit.h"
#include "util/error.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ssao {

void addMotionPathOptions(CLI::App& cmd, CameraPathSpec& spec) {
    cmd.add_option("--motion-frames", spec.frames, "motion: frames along the camera path, the start included")
        ->capture_default_str()
        ->check(cliRange(2, 64));
    cmd.add_option("--motion-orbit", spec.orbitDeg, "motion: degrees the path orbits about the view's target")
        ->capture_default_str()
        ->check(cliRange(-90, 90));
    cmd.add_option("--motion-dolly", spec.dolly,
                   "motion: fraction of the distance to the target the path moves toward it")
        ->capture_default_str()
        ->check(cliRange(-0.5, 0.9));
    cmd.add_option("--motion-max-mib", spec.maxMib,
                   "motion: memory the path's frames may keep at once (references, reprojection, AO), checked before any work")
        ->capture_default_str()
        ->check(cliRange(16, 1 << 20));
}

std::vector<std::string> unusedMotionOptions(const CameraPathSpec& spec, const std::string& needs) {
    const CameraPathSpec d;
    std::vector<std::string> out;
    auto note = [&](bool set, const std::string& option) {
        if (set) out.push_back(option + " does nothing without " + needs + " (no camera path is measured)");
    };
    note(spec.frames != d.frames, "--motion-frames " + std::to_string(spec.frames));
    note(spec.orbitDeg != d.orbitDeg, "--motion-orbit");
    note(spec.dolly != d.dolly, "--motion-dolly");
    note(spec.maxMib != d.maxMib, "--motion-max-mib");
    return out;
}

void checkMotionBudget(const CameraPathSpec& spec, int width, int height, size_t truths) {
    const double mib = double(truths) * spec.frames * double(width) * height * kMotionBytesPerPixelFrame / double(1 << 20);
    if (mib <= spec.maxMib) return;
    char b[320];
    std::snprintf(b, sizeof b,
                  "motion: %zu path%s of %d frames at %dx%d keep %.0f MiB at once, over --motion-max-mib %u: lower "
                  "--motion-frames or --size, or raise --motion-max-mib",
                  truths, truths == 1 ? "" : "s", spec.frames, width, height, mib, spec.maxMib);
    throw Error(b);
}

MotionTruth traceMotionTruth(ReferenceProvider& provider, const Bounds& bounds, const Camera& start, int w, int h,
                             const CameraPathSpec& spec, const ReferenceSettings& rs,
                             const std::function<void(double)>& progress, const std::atomic<bool>* cancel) {
    checkMotionBudget(spec, w, h, 1);
    MotionTruth t;
    t.spec = spec, t.width = w, t.height = h, t.settings = rs;
    t.path = cameraPath(start, spec);
    const size_t n = t.path.size();
    for (size_t k = 0; k < n; ++k) {
        if (cancel && cancel->load()) throw Error("motion: the path's references were cancelled");
        t.rendered.push_back(effectiveCamera(t.path[k], bounds)); // as Renderer::render() fits it
        bool cached = false;
        t.refs.push_back(provider.get(t.rendered[k], w, h, rs,
                                      [&](double f) {
                                          if (progress) progress((double(k) + f) / double(n));
                                      },
                                      &cached));
        t.cached += cached;
        if (!cached) t.seconds += t.refs.back().seconds;
        if (k == 0) {
            t.toPrevious.emplace_back();
            continue;
        }
        const ReferenceImage &cur = t.refs[k], &prev = t.refs[k - 1];
        t.toPrevious.push_back(reprojectToPrevious({&t.rendered[k], cur.depth.data(), cur.geometry.data()},
                                                   {&t.rendered[k - 1], prev.depth.data(), prev.geometry.data()}, w, h));
    }
    if (progress) progress(1.0);
    return t;
}

MotionMetrics measureMotion(Renderer& r, const Settings& s, const MotionTruth& truth) {
    MotionMeasurement m(s, truth);
    while (!m.step(r)) {
    }
    return m.result();
}

bool MotionMeasurement::step(Renderer& r) {
    if (done_) return true;
    const MotionTruth& t = *truth_;
    if (!started_) {
        started_ = true;
        r.setCamera(t.path[0]);
        if (settings_.temporal.enabled) { // an empty history: one frame without accumulation drops it
            Settings off = settings_;
            off.temporal.enabled = false;
            r.setSettings(off);
            r.render();
            r.setSettings(settings_);
            return false;
        }
        r.setSettings(settings_);
    }
    if (!inFrame_) {
        r.setCamera(t.path[frame_]);
        inFrame_ = true;
    }
    r.render();
    if (frame_ == 0 && r.accumulating()) return false; // the still view the path starts from
    tests_.push_back(evaluate(readBack(r.texture("ao.denoised"), 1), t.refs[frame_]).test);
    inFrame_ = false;
    if (++frame_ < t.path.size()) return false;
    finish(r);
    return true;
}

void MotionMeasurement::finish(Renderer& r) {
    const MotionTruth& t = *truth_;
    r.setCamera(t.path[0]); // back at the view: the next still measurement sets no camera of its own
    std::vector<MotionFrameInput> frames;
    for (size_t k = 0; k < tests_.size(); ++k) {
        const ReferenceImage& ref = t.refs[k];
        MotionFrameInput f;
        f.test = tests_[k].data.data(), f.reference = ref.ao.data(), f.geometry = ref.geometry.data();
        f.depth = ref.depth.data(), f.referenceStdErr = ref.stdErr.data();
        if (ref.ambiguous.size() == ref.ao.size()) f.exclude = ref.ambiguous.data();
        if (k) f.toPrevious = t.toPrevious[k].data();
        frames.push_back(f);
    }
    result_ = computeMotionMetrics(t.width, t.height, frames);
    tests_.clear();
    done_ = true;
}

double MotionMeasurement::progress() const {
    return done_ ? 1.0 : double(frame_) / double(std::max<size_t>(truth_->path.size(), 1));
}

namespace {
nlohmann::json num(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}
} // namespace

nlohmann::json motionJson(const MotionMetrics& m, const MotionTruth& t) {
    nlohmann::json frames = nlohmann::json::array();
    for (double v : m.frameRmse)
        frames.push_back(num(v));
    return {{"path", {{"frames", t.spec.frames}, {"orbit_deg", t.spec.orbitDeg}, {"dolly", t.spec.dolly}}},
            {"rmse_mean", num(m.rmseMean)},
            {"rmse_max", num(m.rmseMax)},
            {"rmse_frames", frames},
            {"instability", num(m.instability)},
            {"instability_floor", num(m.instabilityFloor)},
            {"pairs", m.pairs},
            {"ghosting", num(m.ghosting)},
            {"disoccluded_mae", num(m.disoccludedMae)},
            {"stable_mae", num(m.stableMae)},
            {"stable_edge_mae", num(m.stableEdgeMae)},
            {"disoccluded_pixels", m.disoccludedPixels},
            {"stable_pixels", m.stablePixels},
            {"objective", num(motionObjective(m))},
            {"reference", {{"rays_per_pixel", t.settings.samples}, {"radius", t.settings.radius},
                           {"variant", variantName(t.settings.variant)}, {"cached_frames", t.cached},
                           {"trace_seconds", t.seconds}}},
            {"notes", "a path orbiting the view's target and moving toward it; each frame against its own reference; "
                      "instability = RMS over pixels followed from the frame before (same surface point, depth "
                      "within 2%) of the technique's change minus the reference's, floor = a bound on what the "
                      "references' noise adds to it in quadrature (from their standard errors); ghosting = mean |AO - reference| at pixels in their first "
                      "2 frames after a disocclusion minus the same at stable pixels (stable_edge_mae: stable "
                      "pixels within 3 px of a depth edge, where disocclusions happen); objective = mean per-frame "
                      "MSE + instability^2 (tune --objective motion)"}};
}

std::string motionLine(const MotionMetrics& m, const MotionTruth& t) {
    // A figure no pixel backs is "n/a", never "nan".
    auto fig = [](double v, const char* spec) {
        char s[32];
        std::snprintf(s, sizeof s, spec, v);
        return std::isfinite(v) ? std::string(s) : std::string("n/a");
    };
    const std::string ghosting =
        ghostingText(m) + (std::isfinite(m.ghosting) ? " (MAE " + fig(m.disoccludedMae, "%.4f") + " at " +
                                                           std::to_string(m.disoccludedPixels) + " disoccluded pixels, "
                                                     : " (fewer than " + std::to_string(MotionOptions{}.minGhostPixels) +
                                                           " disoccluded pixels back a figure; ");
    char b[512];
    std::snprintf(b, sizeof b,
                  "motion (%d frames, orbit %.3g deg, dolly %.3g, %d-ray references%s): RMSE mean %.4f, max %.4f; "
                  "instability %s (reference floor %s); ghosting %s%s stable, %s stable near edges)",
                  t.spec.frames, t.spec.orbitDeg, t.spec.dolly, t.settings.samples,
                  t.cached == t.spec.frames ? ", cached" : "", m.rmseMean, m.rmseMax, fig(m.instability, "%.4f").c_str(),
                  fig(m.instabilityFloor, "%.4f").c_str(), ghosting.c_str(), fig(m.stableMae, "%.4f").c_str(),
                  fig(m.stableEdgeMae, "%.4f").c_str());
    return b;
}

} // namespace ssao
