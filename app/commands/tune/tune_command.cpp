#include "commands/tune/tune_command.h"
#include "scene/load/load_scene.h"

#include "base/image.h"
#include "measure/bench_run.h"
#include "commands/tune/engine_tune.h"
#include "measure/motion_measure.h"
#include "commands/tune/tune_guard.h"
#include "measure/viewpoints.h"
#include "cli/headless_runner.h"
#include "cli/progress_bar.h"
#include "reference/reference_cache.h"
#include "cli/scene_options.h"
#include "cli/view_radius.h"
#include "settings/applicability.h"
#include "settings/params.h"
#include "settings/preset.h"
#include "settings/preset_store.h"
#include "techniques/technique.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/paths.h"

#include "cli/cli_util.h"
#include "cli/shared_options.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>

namespace ssao {

void addTuneOptions(CLI::App& cmd, TuneOptions& o) {
    cmd.add_option("--technique", o.technique, "the technique to tune (ao.technique)")->type_name("TECHNIQUE")->capture_default_str();
    cmd.add_option("--preset", o.preset, "starting preset (default: the technique's defaults)")->type_name(kInFile);
    addSceneOption(cmd, o.scenes, {"training scene: ", "default builtin:showcase"});
    cmd.add_option("--held-out-scene", o.heldOutScenes,
                   "scene judged but never fitted on (repeatable; every viewpoint is held out)")->type_name(kInFile);
    addSizeOption(cmd, o.size);
    addViewsOption(cmd, o.views, {"", "even ones train, odd ones are held out: at least 2"});
    addStartCameraOption(cmd, o.camera);
    cmd.add_option("--rounds", o.rounds, "search rounds (each halves every bracket)")
        ->capture_default_str()
        ->check(cliRange(1, 10));
    cmd.add_option("--grid", o.grid, "values per parameter per round")
        ->capture_default_str()
        ->check(cliRange(3, 33));
    addReferenceRaysOption(cmd, o.referenceRays);
    addRadiusSceneOption(cmd, o.radiusScene);
    addSetOption(cmd, o.sets, {"", "applied to the start"});
    cmd.add_option("--knob", o.knobs,
                   "fit only this knob (repeatable: a float parameter key of the technique, or radius_multiplier "
                   "or ao.power; these two and a technique's own radius multiplier (gtao.radius_multiplier) are "
                   "never fitted unless named; default: the technique's other float rows)")->type_name("KEY");
    cmd.add_option("--out", o.out, "where to save the tuned preset (JSON)")->type_name(kOutFile)->capture_default_str();
    addPresetDirOption(cmd, o.presetDir);
    addShadersOption(cmd, o.shaderDir);
    cmd.add_flag("--save-overfit", o.saveOverfit,
                 "save the preset even when the fit raised the held-out error (by default: refused, exit 1)");
    addObjectiveOption(cmd, o.objective,
                       {"what the search minimises over the training views: ",
                        "see --motion-*; the motion score: the mean per-frame RMSE^2 + instability^2, instability = the "
                        "RMS of the AO's frame-to-frame change minus the reference's at the same surface points; the "
                        "scores printed are its square root"});
    addMotionPathOptions(cmd, o.motionPath);
    addEngineTuneOptions(cmd, o.engine);
    addQuietFlag(cmd, o.quiet);
}

namespace {

struct Knob {
    std::string key; // "radius_multiplier" or a parameter key
    double lo, hi, value;
};

// Which score a view counts in: fitted on; held out of a training scene; of a held-out scene.
enum class Role { Train, HeldOutView, HeldOutScene };

struct View {
    size_t scene;
    std::string viewpoint;
    Camera camera;
    float radius;
    ReferenceImage ref;
    Role role;
    std::shared_ptr<const MotionTruth> motion; // --objective motion: the references along its camera path
};

// What the scores are the square root of (--objective).
std::string objectiveName(const TuneOptions& o) {
    return o.objective == "motion" ? "motion score (sqrt of mean per-frame RMSE^2 + instability^2)" : "geometry RMSE";
}

// A technique's own radius multiplier (gtao.radius_multiplier) lengthens its search past R, as
// tune's radius_multiplier lengthens R itself: both fit the numbers, not the physics.
bool isRadiusMultiplier(const std::string& key) {
    const std::string own = ".radius_multiplier";
    return key == "radius_multiplier" ||
           (key.size() > own.size() && key.compare(key.size() - own.size(), own.size(), own) == 0);
}

// The knobs: the technique's own float rows that apply but its radius multiplier; or those named by
// --knob, which may add the radius multipliers and ao.power (never fitted unless asked).
std::vector<Knob> chooseKnobs(const TuneOptions& o, const Settings& start) {
    std::vector<Knob> own, extra = {{"radius_multiplier", 0.5, 3.0, 1.0}, {"ao.power", 0.5, 4.0, start.ao.power}};
    for (const Param& p : paramTable())
        if (p.group() == o.technique && p.type == Param::Type::Float && p.applies(start))
            own.push_back({p.key, p.min, p.max, p.get(start)});
    if (o.knobs.empty()) {
        std::vector<Knob> defaults;
        for (const Knob& k : own)
            if (!isRadiusMultiplier(k.key)) defaults.push_back(k);
        if (defaults.empty()) throw Error(o.technique + " has no float parameter to fit (name one with --knob)");
        return defaults;
    }
    std::vector<Knob> all = own;
    all.insert(all.end(), extra.begin(), extra.end());
    std::vector<Knob> chosen;
    for (const std::string& key : o.knobs) {
        auto it = std::find_if(all.begin(), all.end(), [&](const Knob& k) { return k.key == key; });
        if (it == all.end()) {
            std::string known;
            for (const Knob& k : all)
                known += (known.empty() ? "" : ", ") + k.key;
            throw Error("--knob " + key + " is not a knob of " + o.technique + " (knobs: " + known + ")");
        }
        chosen.push_back(*it);
    }
    return chosen;
}

// The search: the training views' mean geometry MSE (or motion objective) over candidate knob
// values, each refused when it darkens an open plane.
class Tuner {
  public:
    // `scenes`: the training scenes first, then `heldOut` held-out ones.
    Tuner(const TuneOptions& o, Settings start, std::vector<Scene> scenes, size_t heldOut, int w, int h)
        : o_(o), start_(std::move(start)), scenes_(std::move(scenes)), heldOut_(heldOut),
          runner_(HeadlessRunner::Options{o.shaderDir, false}), r_(runner_.makeRenderer(w, h)),
          plane_(loadScene("builtin:plane")), planeRenderer_(runner_.makeRenderer(160, 90)) {
        r_->setWanted(std::set<std::string>{"ao.denoised"}); // what is judged: no composite, no albedo
        planeRenderer_->setWanted(std::set<std::string>{"ao.denoised"});
        planeRenderer_->setScene(plane_);
        planeRenderer_->setCamera(*plane_.camera);
    }

    // References of every viewpoint (cached): in a training scene even ones train and odd ones are
    // held out; every viewpoint of a held-out scene is held out.
    void traceViews() {
        for (size_t si = 0; si < scenes_.size(); ++si) {
            const Scene& sc = scenes_[si];
            providers_.push_back(std::make_unique<ReferenceProvider>(sc));
            const float radius = o_.radiusScene * 2.0f * sc.bounds.radius();
            r_->setScene(sc);
            int k = 0;
            const bool heldOutScene = si >= scenes_.size() - heldOut_;
            for (const auto& [name, cam] : viewpoints(heldOutScene ? defaultCamera(sc) : startCamera(o_.camera, sc), o_.views)) {
                r_->setCamera(cam);
                r_->setSettings(withRadius(start_, radius));
                r_->render();
                ProgressBar bar("  reference " + sc.name + " " + name, !o_.quiet);
                ReferenceImage ref = providers_.back()->get(r_->camera(), r_->width(), r_->height(),
                                                            {radius, o_.referenceRays}, [&](double f) { bar.update(f); });
                radius_.check(sc.name, name, ref, r_->camera(), o_.radiusScene, 2.0 * sc.bounds.radius());
                views_.push_back({si, name, r_->camera(), radius, std::move(ref),
                                  heldOutScene ? Role::HeldOutScene : k % 2 == 0 ? Role::Train : Role::HeldOutView});
                if (o_.objective == "motion")
                    views_.back().motion = std::make_shared<MotionTruth>(traceMotionTruth(
                        *providers_.back(), sc.bounds, cam, r_->width(), r_->height(), o_.motionPath, {radius, o_.referenceRays}));
                ++k;
            }
        }
        current_ = size_t(-1);
        runner_.checkGl("while tracing the references");
        printWarnings(radius_.lines());
    }

    Settings settingsWith(const std::vector<Knob>& ks, float radius) const {
        Settings s = withRadius(start_, radius);
        for (const Knob& k : ks) {
            if (k.key == "radius_multiplier")
                s.ao.radius = float(radius * k.value);
            else
                findParam(k.key)->set(s, k.value);
        }
        return s;
    }

    // Mean geometry MSE over the views of one role (NaN when there are none); each view's MSE is also
    // added to its scene's entry of `perScene` (sum, views; indexed as the scenes).
    double score(const std::vector<Knob>& ks, Role role, std::vector<std::pair<double, int>>* perScene = nullptr) {
        double mse = 0;
        int n = 0;
        for (const View& v : views_) {
            if (v.role != role) continue;
            if (v.scene != current_) r_->setScene(scenes_[v.scene]), current_ = v.scene;
            r_->setCamera(v.camera);
            const Settings s = settingsWith(ks, v.radius);
            const ViewResult res = measure(*r_, s, v.ref, 0, 0);
            if (res.error.nonFinite > 0)
                throw Error(std::to_string(res.error.nonFinite) + " non-finite AO pixels on " + scenes_[v.scene].name);
            const double e = v.motion ? motionObjective(measureMotion(*r_, s, *v.motion)) : res.error.rmse * res.error.rmse;
            mse += e;
            ++n;
            if (perScene) (*perScene)[v.scene].first += e, ++(*perScene)[v.scene].second;
            if (&v == &views_.front()) firstRmse_ = res.error.rmse;
        }
        runner_.checkGl("while tuning");
        return n ? mse / n : std::numeric_limits<double>::quiet_NaN();
    }

    // Physics before numbers: a candidate that darkens an open plane is refused whatever it
    // scores - a bias of 0 or a darkening power fits the error by shading everything. The plane is
    // judged as tests/gl/test_physics_limits.cpp judges the shipped presets: builtin:plane in its
    // own view at 160x90 with R = 1 (about 17 pixels), mean AO >= 0.99.
    bool darkensOpenPlane(const std::vector<Knob>& ks) {
        planeRenderer_->setSettings(settingsWith(ks, 1.0f));
        planeRenderer_->render();
        const Image ao = runner_.readFinite(*planeRenderer_, "ao.denoised", "on the open plane");
        double sum = 0;
        for (float v : ao.data)
            sum += v; // the plane fills its view
        return sum / double(ao.data.size()) < 0.99;
    }

    // Coordinate search: each knob over a grid inside its bracket, which halves every round.
    void search(std::vector<Knob>& knobs, double before) {
        ProgressBar bar("  search " + std::to_string(knobs.size()) + " parameters", !o_.quiet);
        const int total = o_.rounds * int(knobs.size()) * o_.grid;
        int done = 0;
        double best = before;
        for (int round = 0; round < o_.rounds; ++round)
            for (Knob& k : knobs) {
                const double lo = k.lo, hi = k.hi;
                double bestValue = k.value;
                for (int i = 0; i < o_.grid; ++i) {
                    k.value = lo + (hi - lo) * i / double(o_.grid - 1);
                    const double s = darkensOpenPlane(knobs) ? std::numeric_limits<double>::infinity()
                                                             : score(knobs, Role::Train);
                    if (s < best) best = s, bestValue = k.value;
                    bar.update(double(++done) / total);
                }
                k.value = bestValue;
                const double half = (hi - lo) / 4.0;
                const Param* p = k.key == "radius_multiplier" ? nullptr : findParam(k.key);
                const double minV = p ? p->min : 0.05, maxV = p ? p->max : 10.0;
                k.lo = std::max(minV, k.value - half);
                k.hi = std::min(maxV, k.value + half);
            }
    }

    size_t count(Role r) const {
        return size_t(std::count_if(views_.begin(), views_.end(), [&](const View& v) { return v.role == r; }));
    }
    const View& firstView() const { return views_.front(); }
    const Scene& scene(size_t i) const { return scenes_[i]; }
    size_t sceneCount() const { return scenes_.size(); }
    size_t heldOutScenes() const { return heldOut_; }
    // The first training view's RMSE at the last score over the training views: what
    // `render --preset` of the saved preset reproduces.
    double firstRmse() const { return firstRmse_; }

  private:
    const TuneOptions& o_;
    Settings start_;
    std::vector<Scene> scenes_;
    size_t heldOut_;
    HeadlessRunner runner_;
    std::unique_ptr<Renderer> r_;
    Scene plane_;
    std::unique_ptr<Renderer> planeRenderer_;
    std::vector<View> views_;
    std::vector<std::unique_ptr<ReferenceProvider>> providers_;
    SceneRadiusWarnings radius_; // R against what each view spans
    size_t current_ = size_t(-1);
    double firstRmse_ = std::numeric_limits<double>::quiet_NaN();
};

struct Scores {
    double train, heldOutViews, heldOutScenes; // mean geometry MSE per role (NaN: no such views)
};

double rmseOf(double mse) { return std::sqrt(mse); }

// Per scene with held-out views, their mean MSE before and after (sums and counts as score() adds them).
std::vector<HeldOutScore> heldOutScores(const Tuner& t, const std::vector<std::pair<double, int>>& before,
                                        const std::vector<std::pair<double, int>>& after) {
    std::vector<HeldOutScore> out;
    for (size_t i = 0; i < t.sceneCount(); ++i) {
        if (before[i].second == 0) continue;
        const bool training = i < t.sceneCount() - t.heldOutScenes();
        out.push_back({t.scene(i).name + (training ? " (held-out views)" : ""), before[i].first / before[i].second,
                       after[i].first / after[i].second, before[i].second});
    }
    return out;
}

// Where the search started: what "start -> tuned" compares with.
std::string startName(const TuneOptions& o) {
    return o.preset.empty() ? "the technique's defaults" : "preset " + o.preset;
}

// The fitted values at an edge of their row's range (tune's own range for radius_multiplier): the
// optimum may lie beyond what the row allows, and the fit says so.
std::vector<std::string> atRangeEdge(const std::vector<Knob>& knobs, std::vector<std::string>* keys = nullptr) {
    std::vector<std::string> out;
    for (const Knob& k : knobs) {
        const Param* p = k.key == "radius_multiplier" ? nullptr : findParam(k.key);
        const double minV = p ? p->min : 0.05, maxV = p ? p->max : 10.0, eps = 1e-6 * std::max(1.0, maxV - minV);
        if (k.value > minV + eps && k.value < maxV - eps) continue;
        char b[320];
        std::snprintf(b, sizeof b, "tuned %s = %.4g is the %s of its range [%.4g, %.4g]: the optimum may lie beyond",
                      k.key.c_str(), k.value, k.value <= minV + eps ? "bottom" : "top", minV, maxV);
        out.push_back(b);
        if (keys) keys->push_back(k.key);
    }
    return out;
}

nlohmann::json scoresJson(const Scores& before, const Scores& after, const FitVerdict& v, const Tuner& t,
                          const TuneOptions& o, const std::vector<Knob>& knobs) {
    auto side = [](const Scores& s) {
        nlohmann::json j;
        auto put = [&](const char* k, double mse) { j[k] = std::isfinite(mse) ? nlohmann::json(rmseOf(mse)) : nlohmann::json(); };
        put("train", s.train), put("held_out_views", s.heldOutViews), put("held_out_scenes", s.heldOutScenes);
        return j;
    };
    nlohmann::json train = nlohmann::json::array(), held = nlohmann::json::array();
    for (size_t i = 0; i < t.sceneCount(); ++i)
        (i >= t.sceneCount() - t.heldOutScenes() ? held : train).push_back(t.scene(i).name);
    std::vector<std::string> edgeKeys;
    atRangeEdge(knobs, &edgeKeys);
    const std::string path = o.objective != "motion" ? "" : ", along a " + std::to_string(o.motionPath.frames) +
        "-frame path (orbit " + std::to_string(o.motionPath.orbitDeg) + " deg, dolly " + std::to_string(o.motionPath.dolly) + ")";
    return {{"metric", objectiveName(o) + " against the ray-traced reference (visibility, R = " + std::to_string(o.radiusScene) +
                           " x diagonal, " + std::to_string(o.referenceRays) + " rays), " + o.size + path},
            {"training_scenes", train},
            {"held_out_scenes", held},
            {"views", {{"train", t.count(Role::Train)}, {"held_out_views", t.count(Role::HeldOutView)},
                       {"held_out_scenes", t.count(Role::HeldOutScene)}}},
            {"start_point", startName(o)},
            {"start", side(before)},
            {"tuned", side(after)},
            {"held_out", {{"start", v.before}, {"tuned", v.after}}}, // every held-out view, both kinds
            {"at_range_edge", edgeKeys},
            {"overfit", v.overfit}};
}

void printTuned(const TuneOptions& o, const Tuner& t, const std::vector<Knob>& knobs, const Scores& before,
                const Scores& after) {
    if (o.quiet) return;
    std::printf("tuned %s on %zu views (held out: %zu views of the same scenes, %zu views of %zu other scenes):",
                o.technique.c_str(), t.count(Role::Train), t.count(Role::HeldOutView), t.count(Role::HeldOutScene),
                t.heldOutScenes());
    for (const Knob& k : knobs)
        std::printf(" %s=%.4g", k.key == "radius_multiplier" ? "R x" : k.key.c_str(), k.value);
    std::printf("\n%s, start (%s) -> tuned: training %.4f -> %.4f, held-out views %.4f -> %.4f", objectiveName(o).c_str(),
                startName(o).c_str(), rmseOf(before.train), rmseOf(after.train), rmseOf(before.heldOutViews),
                rmseOf(after.heldOutViews));
    if (t.heldOutScenes())
        std::printf(", held-out scenes %.4f -> %.4f", rmseOf(before.heldOutScenes), rmseOf(after.heldOutScenes));
    std::printf("\n");
}

// The tuned preset carries what reproduces tune's numbers: the first training scene, the size,
// the first training view's camera; the radius follows the scene (radius_scene = multiplier x the
// reference's fraction), and when a multiplier was fitted, the reference's own R
// (reference_radius_scene) so `render --reference` judges against the R tune used.
void saveTuned(const TuneOptions& o, const Tuner& t, const std::vector<Knob>& knobs, const Scores& before,
               const Scores& after, const FitVerdict& v, int w, int h) {
    Preset p;
    p.name = o.technique + "-tuned";
    Settings tuned = t.settingsWith(knobs, 1.0f);
    tuned.ao.radius = defaultSettings().ao.radius; // not a stray "1 x multiplier": the scene rule decides
    tuned.ao.radiusMode = RadiusMode::Scene;
    double multiplier = 1.0;
    for (const Knob& k : knobs)
        if (k.key == "radius_multiplier") multiplier = k.value;
    tuned.ao.radiusScene = float(o.radiusScene * multiplier);
    if (multiplier != 1.0) p.referenceRadiusScene = o.radiusScene;
    p.settings = tuned;
    const std::string& spec = o.scenes.empty() ? std::string("builtin:showcase") : o.scenes.front();
    std::error_code ec;
    p.scene = spec.rfind("builtin:", 0) == 0 ? spec : std::filesystem::absolute(spec, ec).string();
    p.size = std::make_pair(w, h);
    p.camera = cameraToFile(t.firstView().camera, t.scene(t.firstView().scene));
    p.scores = scoresJson(before, after, v, t, o, knobs);
    char desc[640];
    std::snprintf(desc, sizeof desc,
                  "ssaolab tune: %s fitted to the ray-traced reference (R = %.3g x diagonal) on %zu training views; "
                  "%s train %.4f -> %.4f, held-out views %.4f -> %.4f",
                  o.technique.c_str(), o.radiusScene, t.count(Role::Train), objectiveName(o).c_str(), rmseOf(before.train), rmseOf(after.train),
                  rmseOf(before.heldOutViews), rmseOf(after.heldOutViews));
    p.description = desc;
    if (!std::isnan(before.heldOutScenes)) { // "nan -> nan" said nothing where there are none
        std::snprintf(desc, sizeof desc, ", held-out scenes %.4f -> %.4f", rmseOf(before.heldOutScenes),
                      rmseOf(after.heldOutScenes));
        p.description += desc;
    }
    if (v.overfit) {
        std::snprintf(desc, sizeof desc, " rose %.4f -> %.4f", v.before, v.after);
        p.description += "; overfit (saved with --save-overfit): held-out " + v.metric + desc;
    }
    writePresetFile(p, o.out);
    if (o.quiet) return;
    std::printf("saved %s; its view '%s' alone: RMSE %.6f (ssaolab render --preset %s --reference --reference-rays %d)\n",
                o.out.c_str(), t.firstView().viewpoint.c_str(), t.firstRmse(), o.out.c_str(), o.referenceRays);
}

} // namespace

int runTune(const TuneOptions& o) {
    if (o.views < 2) // --views is declared once for bench and tune (cli/shared_options.h): tune's own floor
        throw Error("--views " + std::to_string(o.views) + ": tune needs at least 2 viewpoints a scene, one fitted and one held out");
    if (!o.engine.engine.empty()) return runEngineTune(o);
    if (!o.engine.snippet.empty()) throw Error("--snippet writes an engine's settings as JavaScript: add --engine NAME");
    if (o.engine.budgetMs > 0 || o.engine.budgetRatio > 0)
        throw Error("--budget-ms and --budget-ratio choose an engine's sample counts: add --engine NAME (bench --budget-ms answers for ssaolab's techniques)");
    int w = 0, h = 0;
    parseSizeOption(o.size, w, h);
    if (o.objective == "motion") // every view's path is kept for the whole search
        checkMotionBudget(o.motionPath, w, h, size_t(o.views) * (o.scenes.size() + o.heldOutScenes.size() + (o.scenes.empty() ? 1 : 0)));
    checkOutputPath(o.out); // before minutes of tuning: a device or a FIFO is never replaced
    findTechnique(o.technique); // throws naming the choices
    Settings start = defaultSettings();
    std::vector<std::string> warnings; // settings that do nothing, said so once they are valid
    if (!o.preset.empty()) {
        Preset p = PresetStore::standard(o.presetDir).open(o.preset);
        start = p.settings;
        warnings = p.warnings;
    }
    setParam(start, "ao.technique", o.technique);
    for (std::string& w : applyAssignments(start, o.sets))
        warnings.push_back(std::move(w));
    validateSettings(start);
    if (o.objective != "motion")
        for (std::string& w : unusedMotionOptions(o.motionPath, "--objective motion"))
            warnings.push_back(std::move(w));
    printWarnings(warnings);
    std::vector<Scene> scenes;
    std::set<std::string> seen;
    for (const auto& s : o.scenes.empty() ? std::vector<std::string>{"builtin:showcase"} : o.scenes)
        scenes.push_back(loadNamedScene(s)), seen.insert(s);
    for (const auto& s : o.heldOutScenes) {
        if (seen.count(s)) throw Error("--held-out-scene " + s + " is also a training scene: a scene is one or the other");
        scenes.push_back(loadNamedScene(s));
    }
    std::vector<Knob> knobs = chooseKnobs(o, start);

    Tuner t(o, start, std::move(scenes), o.heldOutScenes.size(), w, h);
    t.traceViews();
    using PerScene = std::vector<std::pair<double, int>>; // held-out MSE sum and views, per scene
    auto scores = [&](PerScene& held) {
        held.assign(t.sceneCount(), {0.0, 0});
        const double heldViews = t.score(knobs, Role::HeldOutView, &held);
        const double heldScenes = t.score(knobs, Role::HeldOutScene, &held);
        const double train = t.score(knobs, Role::Train); // last: firstRmse() is the first training view's
        return Scores{train, heldViews, heldScenes};
    };
    PerScene heldBefore, heldAfter;
    const Scores before = scores(heldBefore);
    t.search(knobs, before.train);
    const Scores after = scores(heldAfter);
    FitVerdict verdict = judgeFit(heldOutScores(t, heldBefore, heldAfter));
    verdict.metric = objectiveName(o);
    printTuned(o, t, knobs, before, after);
    if (verdict.overfit && !o.saveOverfit) throw Error(refusalText(verdict, o.out)); // nothing written
    saveTuned(o, t, knobs, before, after, verdict, w, h);
    printWarnings(atRangeEdge(knobs)); // once saved: a failed write is its one line
    if (verdict.overfit)
        printWarnings({overfitSavedText(verdict, o.out)});
    else if (!verdict.worse.empty())
        printWarnings({worseScenesText(verdict)});
    return 0;
}

} // namespace ssao
