#include "commands/skips/skips_command.h"
#include "gl/readback.h"

#include "base/image.h"
#include "measure/bench_run.h"
#include "commands/skips/skips_report.h"
#include "display/capture.h"
#include "cli/headless_runner.h"
#include "metrics/evaluate.h"
#include "output/skip_report.h"
#include "reference/reference_cache.h"
#include "cli/scene_options.h"
#include "scene/scene.h"
#include "settings/params.h"
#include "settings/preset_store.h"
#include "techniques/technique.h"
#include "util/error.h"
#include "util/files.h"
#include "util/paths.h"

#include "cli/cli_util.h"
#include "cli/shared_options.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <set>

namespace ssao {

void addSkipsOptions(CLI::App& cmd, SkipsOptions& o) {
    addSceneOption(cmd, o.scenes, {"", "default builtin:showcase"});
    addSizeOption(cmd, o.size);
    addTimedFramesOption(cmd, o.frames, {"", "per variant"});
    addReferenceRaysOption(cmd, o.referenceRays, {"", "the adaptive rows' error"});
    cmd.add_option("--out", o.out, "output folder (skips.json, skips.md)")->type_name(kOutDir)->capture_default_str();
    addQuietFlag(cmd, o.quiet);
}

namespace {

using Clock = std::chrono::steady_clock;

struct FrameTime {
    double wallMs = 0;
    std::map<std::string, double> passMs; // passes that ran
    FrameReport report;
    double sum(const std::vector<std::string>& passes) const {
        double s = 0;
        for (const auto& p : passes) {
            auto it = passMs.find(p);
            if (it != passMs.end()) s += it->second;
        }
        return s;
    }
    double all() const {
        double s = 0;
        for (const auto& [p, ms] : passMs)
            s += ms;
        return s;
    }
};

// One frame, forced (every live pass) or incremental, timed by the passes' GPU timers and by the
// wall clock from an idle GPU to the frame's end.
FrameTime timeFrame(Renderer& r, bool force) {
    glFinish();
    const auto t0 = Clock::now();
    if (force) r.invalidate();
    FrameTime t;
    t.report = r.render();
    glFinish();
    t.wallMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    for (const auto& p : t.report.passes)
        if (p.ran && p.gpuMs >= 0) t.passMs[p.name] = p.gpuMs;
    return t;
}

// The largest |a - b| over the geometry pixels of `mask` (position w).
double maxDiff(const Image& a, const Image& b, const Image& mask) {
    double worst = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            if (mask.at(x, y) != 0.0f)
                for (int c = 0; c < a.channels; ++c)
                    worst = std::max(worst, double(std::abs(a.at(x, y, c) - b.at(x, y, c))));
    return worst;
}

Image geometryMask(const Renderer& r) {
    return readBack(r.texture("gbuffer.depth"), 1); // > 0 on geometry
}

// A/B: `frames` forced frames of each settings variant, alternating (drift hits both alike);
// medians of `measure` and of the wall time; the outputs' largest difference over geometry.
struct AbResult {
    double a = 0, b = 0, wallA = 0, wallB = 0, diff = 0;
};
AbResult compare(Renderer& r, const Settings& a, const Settings& b, int frames,
                 const std::function<double(const FrameTime&)>& measure, const std::string& output) {
    std::vector<double> ma, mb, wa, wb;
    Image outA, outB;
    for (int f = -1; f < frames; ++f) { // f = -1: warm-up (shader variants compile)
        r.setSettings(a);
        const FrameTime ta = timeFrame(r, true);
        // The outputs of the last frames (after the timing): a skip that learns from the frame before
        // (skip.occluded) is judged as it runs, not on its first frame.
        if (f == frames - 1) outA = readBack(r.texture(output), r.resource(output).desc.channels);
        r.setSettings(b);
        const FrameTime tb = timeFrame(r, true);
        if (f == frames - 1) outB = readBack(r.texture(output), r.resource(output).desc.channels);
        if (f < 0) continue;
        ma.push_back(measure(ta)), mb.push_back(measure(tb));
        wa.push_back(ta.wallMs), wb.push_back(tb.wallMs);
    }
    AbResult res{median(ma), median(mb), median(wa), median(wb), 0.0};
    res.diff = maxDiff(outA, outB, geometryMask(r));
    return res;
}

Camera moveEye(Camera c, float towardTarget) {
    c.eye = c.target + (c.eye - c.target) * (1.0f - towardTarget);
    return c;
}

struct Context {
    const SkipsOptions& o;
    Renderer& r;
    SkipsRun& run;
    std::string scene;
    void note(const std::string& s) const {
        if (!o.quiet) std::fprintf(stderr, "skips: %s %s\n", scene.c_str(), s.c_str());
    }
};

void dirtyRows(Context& c, const Camera& cam) {
    c.note("dirty passes");
    Renderer& r = c.r;
    Settings s = defaultSettings();
    r.setWanted(std::nullopt);
    r.setCamera(cam);
    r.setSettings(s);
    r.render();
    Camera moved = cam;
    struct Change {
        std::string what;
        std::function<void(int)> apply; // frame parity: toggles between two values
    };
    const std::vector<Change> changes = {
        {"camera moved (everything)",
         [&](int k) { moved.eye = cam.eye + glm::vec3(k % 2 ? 1e-3f : 0.0f) * glm::length(cam.target - cam.eye), r.setCamera(moved); }},
        {"AO setting (AO and after)", [&](int k) { s.ao.power = k % 2 ? 1.25f : 1.0f, r.setSettings(s); }},
        {"denoise setting (denoise and after)",
         [&](int k) { s.denoise.kind = k % 2 ? DenoiseKind::Box4Centred : DenoiseKind::Box4, r.setSettings(s); }},
        {"composite setting (composite)", [&](int k) { s.composite.light = k % 2 ? 0.5f : 0.6f, r.setSettings(s); }},
        {"view switch or idle frame (nothing)", [](int) {}},
    };
    for (const Change& ch : changes) {
        std::vector<double> inc, full, wInc, wFull;
        double diff = 0;
        std::vector<std::string> ran;
        for (int f = -1; f < c.o.frames; ++f) {
            ch.apply(f + 2);
            const FrameTime ti = timeFrame(r, false);
            const Image incremental = readBack(r.texture("composite"), 3);
            const FrameTime tf = timeFrame(r, true);
            diff = std::max(diff, maxDiff(readBack(r.texture("composite"), 3), incremental, geometryMask(r)));
            if (f < 0) continue;
            ran = ti.report.ran();
            inc.push_back(ti.all()), full.push_back(tf.all());
            wInc.push_back(ti.wallMs), wFull.push_back(tf.wallMs);
        }
        SkipRow row{"dirty", c.scene, "camera", ch.what, "GPU ms of the passes run"};
        row.with = median(inc), row.without = median(full);
        row.wallWith = median(wInc), row.wallWithout = median(wFull);
        row.errorChange = diff;
        row.extra["passes_run"] = ran;
        c.run.rows.push_back(row);
    }
    s = defaultSettings();
    r.setSettings(s);
    r.setCamera(cam);
}

void skyRows(Context& c, const Camera& cam) {
    c.note("sky");
    Renderer& r = c.r;
    r.setWanted(std::set<std::string>{"ao.denoised"});
    r.setCamera(cam);
    for (const TechniqueInfo& t : techniques()) {
        const std::string& tech = t.id;
        Settings on = defaultSettings();
        on.ao.technique = tech;
        Settings off = on;
        off.skip.sky = false;
        const AbResult ab = compare(
            r, on, off, c.o.frames, [](const FrameTime& t) { return t.sum({"ao", "denoise"}); }, "ao.denoised");
        r.setSettings(on);
        r.render();
        const FrameReport fr = r.render();
        const nlohmann::json k = skipCounters(captureFrame(r, {}, false), fr);
        SkipRow row{"sky", c.scene, "camera", tech, "AO + denoise GPU ms"};
        row.with = ab.a, row.without = ab.b, row.wallWith = ab.wallA, row.wallWithout = ab.wallB;
        row.errorChange = ab.diff;
        row.extra["sky_share"] = k["sky"]["share"];
        c.run.rows.push_back(row);
    }
}

void adaptiveRows(Context& c, ReferenceProvider& provider, const Camera& cam, const std::string& view,
                  float radiusScene) {
    c.note("adaptive, " + view);
    Renderer& r = c.r;
    r.setWanted(std::set<std::string>{"ao.denoised"});
    r.setCamera(cam);
    Settings probe = defaultSettings();
    probe.ao.radiusScene = radiusScene;
    r.setSettings(probe);
    r.render(); // fits the clip planes: the reference traces the camera as rendered
    const float radius = r.radiusAtCentre().world;
    const ReferenceImage ref =
        provider.get(r.camera(), r.width(), r.height(), {radius, c.o.referenceRays, ReferenceVariant::Visibility});
    for (const TechniqueInfo& t : techniques())
      for (const float px : {2.0f, 4.0f}) {
        if (!t.adaptive) break; // takes no adaptive count
        const std::string& tech = t.id;
        Settings full = probe;
        full.ao.technique = tech;
        Settings adaptive = full;
        adaptive.ao.adaptive = true;
        adaptive.ao.adaptivePx = px;
        const AbResult ab = compare(
            r, adaptive, full, c.o.frames, [](const FrameTime& t) { return t.sum({"ao"}); }, "ao.denoised");
        SkipRow row{"adaptive", c.scene, view, tech + ", " + std::to_string(int(px)) + " px/sample", "AO GPU ms"};
        row.with = ab.a, row.without = ab.b, row.wallWith = ab.wallA, row.wallWithout = ab.wallB;
        double rmse[2];
        for (int i = 0; i < 2; ++i) {
            r.setSettings(i == 0 ? adaptive : full);
            r.render();
            rmse[i] = evaluate(readBack(r.texture("ao.denoised"), 1), ref).metrics.rmse;
        }
        r.setSettings(adaptive);
        const FrameReport fr = r.render();
        const nlohmann::json k = skipCounters(captureFrame(r, {}, false), fr);
        row.errorChange = rmse[0] - rmse[1];
        row.extra["rmse_with"] = rmse[0], row.extra["rmse_without"] = rmse[1];
        row.extra["sample_share"] = k["adaptive"]["mean_sample_share"];
        c.run.rows.push_back(row);
      }
}

// Deinterleaved sampling (ao.deinterleave) against the same preset without it: the AO pass's time
// (its split, 16 layer draws and merge included) and the whole frame's wall time, and each one's
// RMSE against the reference - not a skip (the taps move to a 4-pixel grid), measured like one so
// the page says where it pays.
void deinterleaveRows(Context& c, ReferenceProvider& provider, const Camera& cam, const std::string& view) {
    c.note("deinterleave, " + view);
    Renderer& r = c.r;
    r.setWanted(std::set<std::string>{"ao.denoised"});
    r.setCamera(cam);
    for (const TechniqueInfo& t : techniques()) {
        if (!t.deinterleave) continue;
        Settings off = PresetStore::standard().open(t.id + "-medium").settings;
        Settings on = off;
        on.ao.deinterleave = true;
        r.setSettings(off);
        r.render(); // fits the clip planes: the reference traces the camera as rendered
        const ReferenceImage ref = provider.get(r.camera(), r.width(), r.height(),
                                                {r.radiusAtCentre().world, c.o.referenceRays, ReferenceVariant::Visibility});
        const AbResult ab = compare(
            r, on, off, c.o.frames, [](const FrameTime& f) { return f.sum({"ao"}); }, "ao.denoised");
        SkipRow row{"deinterleave", c.scene, view, t.id + "-medium", "AO GPU ms"};
        row.with = ab.a, row.without = ab.b, row.wallWith = ab.wallA, row.wallWithout = ab.wallB;
        double rmse[2];
        for (int i = 0; i < 2; ++i) {
            r.setSettings(i == 0 ? on : off);
            r.render();
            rmse[i] = evaluate(readBack(r.texture("ao.denoised"), 1), ref).metrics.rmse;
        }
        row.errorChange = rmse[0] - rmse[1];
        row.extra["rmse_with"] = rmse[0], row.extra["rmse_without"] = rmse[1];
        c.run.rows.push_back(row);
    }
}

double gbufferMs(const FrameTime& t) { return t.sum({"gbuffer"}); }

// The G-buffer's own skips: frustum culling, hidden faces, occluded draws; everything wanted (as
// the headless render and the app's grid).
void gbufferSkipRows(Context& c, const std::string& view) {
    Renderer& r = c.r;
    r.setWanted(std::nullopt);
    const Settings on = defaultSettings();
    // A G-buffer skip against the same frame with it off (everything wanted), alternating frames;
    // its counters from one more frame with it on.
    auto gbufferSkip = [&](const char* key, const char* variant, const char* unit, auto off,
                           const std::function<double(const FrameTime&)>& measure) {
        Settings without = on;
        off(without);
        const AbResult ab = compare(r, on, without, c.o.frames, measure, "gbuffer.position");
        r.setSettings(on);
        r.invalidate();
        const FrameReport fr = r.render();
        SkipRow row{key, c.scene, view, variant, unit};
        row.with = ab.a, row.without = ab.b, row.wallWith = ab.wallA, row.wallWithout = ab.wallB;
        row.errorChange = ab.diff;
        row.extra = skipCounters(captureFrame(r, {}, false), fr)["gbuffer"];
        c.run.rows.push_back(row);
    };
    gbufferSkip("cull", "frustum culling", "G-buffer GPU ms", [](Settings& s) { s.skip.cull = false; }, gbufferMs);
    // The hidden side of closed shells culled (skip.hidden_faces).
    gbufferSkip("faces", "hidden faces of closed shells", "G-buffer GPU ms",
                [](Settings& s) { s.skip.hiddenFaces = false; }, gbufferMs);
    // Draws the scene hides left out (skip.occluded): each variant's frames alternate, the culler
    // carrying its visible set from its own last frame; the whole frame's wall time (the box tests
    // wait for the draws before them, which GPU timers miss).
    gbufferSkip("occluded", "draws the scene hides", "frame wall ms",
                [](Settings& s) { s.skip.occluded = false; }, [](const FrameTime& t) { return t.wallMs; });
}

// Demand: a view of the AO alone (the app's single AO view, `bench`) culls the composite and
// the albedo target; whole frame, forced, against the same frame with everything wanted.
void demandRow(Context& c, const std::string& view) {
    Renderer& r = c.r;
    const Settings on = defaultSettings();
    std::vector<double> gpu[2], wall[2];
    r.setSettings(on);
    for (int f = -1; f < c.o.frames; ++f)
        for (int k = 0; k < 2; ++k) {
            if (k == 0)
                r.setWanted(std::set<std::string>{"ao.denoised"});
            else
                r.setWanted(std::nullopt);
            const FrameTime t = timeFrame(r, true);
            if (f >= 0) gpu[k].push_back(t.all()), wall[k].push_back(t.wallMs);
        }
    SkipRow row{"targets", c.scene, view, "AO view: composite culled, 3 targets (whole frame)",
                "frame GPU ms"};
    row.with = median(gpu[0]), row.without = median(gpu[1]);
    row.wallWith = median(wall[0]), row.wallWithout = median(wall[1]);
    row.extra["targets_written"] = 3;
    c.run.rows.push_back(row);
}

// The joint upsample fused into the composite (skip.fused_upsample): half-resolution AO, a
// composite view with nothing else reading ao.denoised (the app without the error or the
// readout), against the same view with the upsample as its own pass. Whole frame, forced.
void fusedUpsampleRow(Context& c, const std::string& view) {
    Renderer& r = c.r;
    Settings fused = defaultSettings();
    applyAssignment(fused, "ao.resolution=half");
    applyAssignment(fused, "denoise.upsample=joint");
    Settings own = fused;
    applyAssignment(fused, "skip.fused_upsample=true");
    r.setWanted(std::set<std::string>{"composite"});
    auto all = [](const FrameTime& t) { return t.all(); };
    const AbResult f = compare(r, fused, own, c.o.frames, all, "composite");
    SkipRow row{"fused", c.scene, view, "half-res AO: joint upsample inside the composite (whole frame)",
                "frame GPU ms"};
    row.with = f.a, row.without = f.b, row.wallWith = f.wallA, row.wallWithout = f.wallB;
    row.errorChange = f.diff;
    c.run.rows.push_back(row);
    r.setSettings(defaultSettings());
}

// Unused targets: only the AO wanted (as `bench` judges it); then normals from depth too.
void unusedTargetRows(Context& c, const std::string& view) {
    Renderer& r = c.r;
    r.setWanted(std::set<std::string>{"ao.denoised"});
    for (const bool depthNormals : {false, true}) {
        Settings t = defaultSettings();
        if (depthNormals) t.ao.normals = NormalSource::Depth;
        Settings all = t;
        all.skip.unusedTargets = false;
        const AbResult ab = compare(r, t, all, c.o.frames, gbufferMs, "ao.denoised");
        r.setSettings(t);
        r.invalidate();
        const FrameReport fr = r.render();
        const nlohmann::json k = skipCounters(captureFrame(r, {}, false), fr);
        SkipRow row{"targets", c.scene, view,
                    depthNormals ? "AO only, normals from depth" : "AO only (no composite: no albedo)",
                    "G-buffer GPU ms"};
        row.with = ab.a, row.without = ab.b, row.wallWith = ab.wallA, row.wallWithout = ab.wallB;
        row.errorChange = ab.diff;
        row.extra["targets_written"] = k["gbuffer"]["targets_written"];
        c.run.rows.push_back(row);
    }
}

// The second depth layer in the G-buffer's own pass (gbuffer.second_layer_build = previous) against
// its second geometry pass (peel): the G-buffer and the layer's passes, and the AO of the start
// preset's technique where it reads the layer (TechniqueInfo::secondLayer), else of the first that
// does, at its defaults. Each build's frames in a row - the single pass reprojects its own previous
// frame - and the same still frame from both.
void secondLayerRow(Context& c, const std::string& view) {
    Renderer& r = c.r;
    r.setWanted(std::set<std::string>{"ao.denoised"});
    Settings peel = defaultSettings();
    std::string reader = PresetStore::standard().open(kStartPreset).settings.ao.technique;
    if (!findTechnique(reader).secondLayer) {
        const auto& all = techniques();
        const auto first = std::find_if(all.begin(), all.end(), [](const TechniqueInfo& t) { return t.secondLayer; });
        if (first == all.end()) return; // no technique reads a second layer: nothing to compare
        reader = first->id;
    }
    applyAssignment(peel, "ao.technique=" + reader);
    applyAssignment(peel, "gbuffer.second_layer=true");
    Settings single = peel;
    applyAssignment(single, "gbuffer.second_layer_build=previous");
    std::vector<double> ms[2], wall[2];
    Image out[2];
    for (int k = 0; k < 2; ++k) {
        r.setSettings(k == 0 ? single : peel);
        for (int f = -1; f < c.o.frames; ++f) { // f = -1: warm-up (and the single pass's first frame)
            const FrameTime t = timeFrame(r, true);
            if (f >= 0) ms[k].push_back(t.sum({"gbuffer", "second_layer"})), wall[k].push_back(t.wallMs);
        }
        out[k] = readBack(r.texture("ao.denoised"), 1);
    }
    SkipRow row{"layer", c.scene, view, "second layer in the G-buffer's pass (bitmask defaults)",
                "G-buffer + layer GPU ms"};
    row.with = median(ms[0]), row.without = median(ms[1]);
    row.wallWith = median(wall[0]), row.wallWithout = median(wall[1]);
    row.errorChange = maxDiff(out[0], out[1], geometryMask(r));
    c.run.rows.push_back(row);
    r.setSettings(defaultSettings());
}

void gbufferRows(Context& c, const Camera& cam, const std::string& view) {
    c.note("G-buffer, " + view);
    c.r.setCamera(cam);
    gbufferSkipRows(c, view);
    demandRow(c, view);
    fusedUpsampleRow(c, view);
    unusedTargetRows(c, view);
    secondLayerRow(c, view);
}

} // namespace

int runSkips(const SkipsOptions& o) {
    int w = 0, h = 0;
    parseSizeOption(o.size, w, h);
    makeOutputFolder(o.out); // before minutes of measuring, not after
    std::vector<std::string> specs = o.scenes.empty() ? std::vector<std::string>{"builtin:showcase"} : o.scenes;
    std::vector<Scene> scenes = loadNamedScenes(specs);
    HeadlessRunner runner;
    std::unique_ptr<Renderer> r = runner.makeRenderer(w, h);
    SkipsRun run;
    run.facts = runFacts(runner.glRenderer());
    run.facts["size"] = o.size;
    run.facts["frames"] = o.frames;
    for (Scene& scene : scenes) {
        r->setScene(scene);
        ReferenceProvider provider(scene);
        Context c{o, *r, run, scene.name};
        const Camera cam = defaultCamera(scene);
        dirtyRows(c, cam);
        skyRows(c, cam);
        // Where a radius spans few pixels: the default R (5 % of the diagonal) seen from 4x
        // farther, and a small R (1 %) from the scene's camera.
        adaptiveRows(c, provider, cam, "camera", 0.05f);
        adaptiveRows(c, provider, moveEye(cam, -3.0f), "4x farther", 0.05f);
        adaptiveRows(c, provider, cam, "camera, R = 1 % of diagonal", 0.01f);
        deinterleaveRows(c, provider, cam, "camera");
        gbufferRows(c, cam, "camera");
        gbufferRows(c, moveEye(cam, 0.8f), "close-up (5x nearer)");
        runner.checkGl("while measuring the skips on " + scene.name);
        runner.readFinite(*r, "ao.denoised", "on " + scene.name);
    }
    writeSkipsFiles(run, o.out);
    if (!o.quiet) std::printf("skips: %zu rows; wrote %s/{skips.json,skips.md}\n", run.rows.size(), o.out.c_str());
    return 0;
}

} // namespace ssao
