#include "commands/bench/bench_command.h"

#include "results/bench_answer.h"
#include "results/bench_finish.h"
#include "results/bench_report.h"
#include "measure/bench_run.h"
#include "measure/motion_measure.h"
#include "results/shard.h"
#include "measure/thumbnails.h"
#include "measure/viewpoints.h"
#include "cli/headless_runner.h"
#include "metrics/evaluate.h"
#include "cli/progress_bar.h"
#include "reference/reference_cache.h"
#include "cli/scene_options.h"
#include "cli/view_radius.h"
#include "scene/scene.h"
#include "settings/preset.h"
#include "util/error.h"
#include "util/files.h"
#include "util/paths.h"

#include "cli/cli_util.h"
#include "cli/shared_options.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

namespace ssao {

void addBenchOptions(CLI::App& cmd, BenchOptions& o) {
    addSceneOption(cmd, o.scenes, {"scene to measure: ", "default builtin:showcase"});
    cmd.add_option("--sweep", o.sweep, "builtin, or a sweep JSON file (see assets/bench/sweep_builtin.json)")->type_name(kInFile)
        ->capture_default_str();
    addSizeOption(cmd, o.size);
    addViewsOption(cmd, o.views);
    addStartCameraOption(cmd, o.camera);
    addTimedFramesOption(cmd, o.frames, {"", "per configuration and view; min and max too"});
    cmd.add_option("--warmup", o.warmup, "untimed frames before timing")
        ->capture_default_str()
        ->check(cliRange(0, 1000));
    addReferenceRaysOption(cmd, o.referenceRays);
    addReferenceVariantOption(cmd, o.referenceVariant);
    addRadiusSceneOption(cmd, o.radiusScene, {"", "every configuration's and the reference's"});
    cmd.add_option("--out", o.out, "output folder")->type_name(kOutDir)->capture_default_str();
    addPresetDirOption(cmd, o.presetDir);
    addShadersOption(cmd, o.shaderDir);
    cmd.add_option("--baseline", o.baseline, "the preset every row is compared with")->type_name("PRESET")->capture_default_str();
    cmd.add_flag(
        "--no-oracle", [&o](int64_t) { o.oracle = false; },
        "skip the screen-space oracle (no split of the error into the technique's and the screen's)");
    addOracleOptions(cmd, o.oracleLayers, o.oracleThickness, o.oracleGuard);
    cmd.add_option("--shard", o.shard,
                   "K/N: run the K-th of N equal parts of the work (scenes x views x configurations); join "
                   "the parts with `ssaolab bench merge`")->type_name("K/N")
        ->capture_default_str();
    addBudgetMsOption(cmd, o.budgetMs, {"answer: the most accurate configuration within ", "its AO + denoise time"});
    addBudgetRatioOption(cmd, o.budgetRatio,
                         {"answer: the most accurate configuration within ", "the plot's axis: 0.5 = half the baseline's time"});
    addMaxErrorOption(cmd, o.maxError);
    addObjectiveOption(cmd, o.objective,
                       {"what the front, the answers and 'fastest at most the baseline's error' rank by: ", "motion implies --motion"});
    cmd.add_flag("--motion", o.motion,
                 "also score every configuration in motion along a camera path from each view (a reference per "
                 "frame): motion RMSE, instability, ghosting columns");
    addMotionPathOptions(cmd, o.motionPath);
    addBenchEngineOptions(cmd, o.engines);
    addNoPlotFlag(cmd, o.plot);
    addQuietFlag(cmd, o.quiet);
}

namespace {

std::string hostName() {
    char b[256] = {};
    return ::gethostname(b, sizeof b - 1) == 0 ? std::string(b) : "unknown";
}

// What one shard measures of one scene: for each viewpoint holding any of its units, the
// reference (cached), the baseline (always: every row's time is divided by its own run's
// baseline on that view) and its configurations.
class SceneBench {
  public:
    SceneBench(const BenchOptions& o, HeadlessRunner& runner, Renderer& r, BenchRun& run, ReferenceVariant variant,
               BenchEngines& engines)
        : o_(o), runner_(runner), r_(r), run_(run), variant_(variant), engines_(engines) {}

    void run(size_t si, const std::string& spec, Scene& scene, const std::vector<WorkUnit>& units) {
        const size_t firstRow = run_.views.size();
        const float radius = o_.radiusScene * 2.0f * scene.bounds.radius();
        r_.setScene(scene);
        ReferenceProvider provider(scene);
        nlohmann::json facts = {{"name", scene.name},
                                {"spec", spec},
                                {"triangles", scene.triangleCount()},
                                {"diagonal", 2.0f * scene.bounds.radius()},
                                {"radius", radius},
                                {"viewpoints", nlohmann::json::array()}};
        const auto vps = viewpoints(startCamera(o_.camera, scene), o_.views);
        for (size_t vi = 0; vi < vps.size(); ++vi) {
            std::vector<size_t> configs;
            for (const WorkUnit& u : units)
                if (u.scene == si && u.view == vi) configs.push_back(u.config);
            if (!configs.empty()) facts["viewpoints"].push_back(view(scene, vps[vi].first, vps[vi].second, vi, radius, provider, configs));
        }
        run_.facts["scenes"].push_back(facts);
        if (const std::string w = radius_.line(scene.name); !w.empty()) printWarnings({w});
        if (!engines_.active()) return;
        engines_.runScene(spec, scene, radius, o_.quiet, run_);
        std::map<std::string, size_t> order; // the engines' rows among the others: viewpoint, then configuration
        for (size_t vi = 0; vi < vps.size(); ++vi)
            order[vps[vi].first] = vi;
        std::stable_sort(run_.views.begin() + long(firstRow), run_.views.end(), [&](const ViewResult& a, const ViewResult& b) {
            return order[a.viewpoint] != order[b.viewpoint] ? order[a.viewpoint] < order[b.viewpoint] : a.config < b.config;
        });
    }

  private:
    nlohmann::json view(const Scene& scene, const std::string& vname, const Camera& cam, size_t vi, float radius,
                        ReferenceProvider& provider, const std::vector<size_t>& configs) {
        const Sweep& sweep = run_.sweep;
        r_.setCamera(cam);
        r_.setSettings(withRadius(sweep.configs[sweep.baseline].settings, radius));
        r_.render(); // fits the clip planes: the reference traces the camera as rendered
        bool cached = false;
        ReferenceImage ref;
        {
            ProgressBar bar("  reference " + scene.name + " " + vname, !o_.quiet);
            ref = provider.get(r_.camera(), r_.width(), r_.height(), {radius, o_.referenceRays, variant_},
                               [&](double f) { bar.update(f); }, &cached);
        }
        // The screen-space oracle of the same view, R and rays: what the G-buffer alone decides; with
        // two-layer rows, also the oracle of a deep G-buffer, which those rows are split against.
        radius_.check(scene.name, vname, ref, r_.camera(), o_.radiusScene, 2.0 * scene.bounds.radius());
        std::optional<ReferenceImage> oracle, deep;
        screen_ = deepScreen_ = ErrorMetrics{};
        if (o_.oracle) oracle = traceOracle(provider, ref, radius, o_.oracleLayers, scene.name + " " + vname, screen_);
        if (o_.oracle && o_.oracleLayers == 1 && anyTwoLayerRow(configs))
            deep = traceOracle(provider, ref, radius, 2, scene.name + " " + vname + " (two layers)", deepScreen_);
        oracle_ = oracle ? &*oracle : nullptr;
        deepOracle_ = deep ? &*deep : nullptr;
        const PlaceMap places = placesOf(ref, r_.camera(), radius); // where each pixel is (error_places.h)
        places_ = &places;
        const ErrorMetrics screen = screen_;
        std::optional<MotionTruth> motion; // the path's references, when rows are scored in motion
        if (o_.motion) {
            ProgressBar bar("  motion references " + scene.name + " " + vname, !o_.quiet);
            motion = traceMotionTruth(provider, r_.bounds(), cam, r_.width(), r_.height(), o_.motionPath,
                                      {radius, o_.referenceRays, variant_}, [&](double f) { bar.update(f); });
        }
        motion_ = motion ? &*motion : nullptr;
        const std::string thumbs = thumbnailDir(o_.out, scene.name, vname);
        if (vi == 0) writeReferenceThumbnail(thumbs, ref);
        ProgressBar bar("  " + scene.name + " " + vname + ": " + std::to_string(configs.size()) + " configurations",
                        !o_.quiet);
        // The baseline first, whether or not this shard owns its row.
        const ViewResult base = one(sweep.baseline, scene.name, vname, radius, ref, vi == 0 ? thumbs : "");
        const bool ownsBaseline = std::find(configs.begin(), configs.end(), sweep.baseline) != configs.end();
        if (ownsBaseline) run_.views.push_back(base);
        EngineViewWork engineWork{vname, r_.camera(), {}, {}, screen, base.gpuMs, vi == 0 ? thumbs : "", {}};
        for (size_t k = 0; k < configs.size(); ++k) {
            if (configs[k] == sweep.baseline) continue;
            if (engines_.isEngine(configs[k])) { // measured with the scene's other engine rows, in one browser session
                engineWork.configs.push_back(configs[k]);
                continue;
            }
            ViewResult v = one(configs[k], scene.name, vname, radius, ref, vi == 0 ? thumbs : "");
            v.baselineMs = base.gpuMs;
            run_.views.push_back(v);
            bar.update(double(k + 1) / double(configs.size()));
        }
        nlohmann::json facts = {{"name", vname},
                                {"index", vi},
                                {"camera", cameraToJson(cam)},
                                {"reference_cached", cached},
                                {"reference_seconds", ref.seconds},
                                {"reference_ambiguous_pixels", ref.ambiguousPixels()},
                                {"reference_mrays_per_second", ref.raysPerSecond() * 1e-6}};
        if (!engineWork.configs.empty()) {
            engineWork.ref = std::move(ref);
            engineWork.oracle = std::move(oracle);
            engines_.addView(std::move(engineWork));
        }
        return facts;
    }

    ReferenceImage traceOracle(ReferenceProvider& provider, const ReferenceImage& ref, float radius, int layers,
                               const std::string& what, ErrorMetrics& screen) {
        ReferenceSettings os{radius, o_.referenceRays, variant_};
        os.visibility = ReferenceVisibility::Screen;
        os.layers = layers;
        os.thickness = float(o_.oracleThickness);
        os.guardBand = o_.oracleGuard;
        ProgressBar bar("  oracle " + what, !o_.quiet);
        ReferenceImage oracle = provider.get(r_.camera(), r_.width(), r_.height(), os, [&](double f) { bar.update(f); });
        screen = evaluate(Image{oracle.width, oracle.height, 1, oracle.ao}, ref).metrics;
        return oracle;
    }

    bool anyTwoLayerRow(const std::vector<size_t>& configs) const {
        for (size_t c : configs)
            if (!run_.sweep.configs[c].isEngine() && run_.sweep.configs[c].settings.gbuffer.secondLayer) return true;
        return false;
    }

    ViewResult one(size_t c, const std::string& scene, const std::string& vname, float radius, const ReferenceImage& ref,
                   const std::string& thumbs) {
        const BenchConfig& cfg = run_.sweep.configs[c];
        Measurement m(withRadius(cfg.settings, radius), o_.warmup, o_.frames);
        const bool deep = deepOracle_ && !cfg.isEngine() && cfg.settings.gbuffer.secondLayer;
        while (!m.step(r_, ref, deep ? deepOracle_ : oracle_)) {
        }
        runner_.checkGl("measuring " + cfg.label + " on " + scene + " " + vname);
        if (!thumbs.empty()) writeThumbnails(thumbs, c, m.evaluation(), ref);
        ViewResult v = m.result();
        v.places = errorByPlace(m.evaluation(), ref, *places_, deep ? deepOracle_ : oracle_);
        v.hasPlaces = true;
        if (v.hasSplit) v.screen = deep ? deepScreen_ : screen_;
        if (motion_) {
            const MotionMetrics mm = measureMotion(r_, withRadius(cfg.settings, radius), *motion_);
            runner_.checkGl("measuring " + cfg.label + " in motion on " + scene + " " + vname);
            v.hasMotion = true;
            v.motion = {mm.rmseMean, mm.rmseMax, mm.instability, mm.ghosting};
        }
        v.scene = scene;
        v.viewpoint = vname;
        v.config = c;
        v.baselineMs = v.gpuMs;
        return v;
    }

    const BenchOptions& o_;
    HeadlessRunner& runner_;
    Renderer& r_;
    BenchRun& run_;
    ReferenceVariant variant_;
    const ReferenceImage* oracle_ = nullptr; // of the view being measured
    const PlaceMap* places_ = nullptr;       // its places
    ErrorMetrics screen_;                    // its oracle against the truth
    const ReferenceImage* deepOracle_ = nullptr; // its two-layer oracle, for the two-layer rows
    ErrorMetrics deepScreen_;
    const MotionTruth* motion_ = nullptr;    // its camera path's truth (bench --motion)
    BenchEngines& engines_;                  // the web engines' rows (bench --engines)
    SceneRadiusWarnings radius_;             // R against what each view spans
};

} // namespace

int runBench(const BenchOptions& given) {
    BenchOptions o = given;
    const Objective objective = parseObjective(o.objective);
    o.motion = o.motion || objective == Objective::Motion; // a motion objective needs the motion columns
    // Everything that needs no GL first: bad input fails in milliseconds with one line.
    int w = 0, h = 0;
    parseSizeOption(o.size, w, h);
    if (o.motion) checkMotionBudget(o.motionPath, w, h, 1); // one view's path at a time
    if (!o.motion) printWarnings(unusedMotionOptions(o.motionPath, "--motion"));
    const ShardSpec shard = parseShard(o.shard);
    std::vector<std::string> specs = o.scenes.empty() ? std::vector<std::string>{"builtin:showcase"} : o.scenes;
    BenchEngines engines(o.engines, specs, w, h, o.frames); // a missing browser or a builtin scene: refused here
    makeOutputFolder(o.out);
    BenchRun run;
    run.sweep = loadSweep(o.sweep, o.presetDir, o.baseline);
    engines.appendTo(run.sweep);
    printWarnings(run.sweep.warnings);
    const ReferenceVariant variant = parseVariant(o.referenceVariant);
    std::vector<Scene> scenes = loadNamedScenes(specs);
    const std::vector<WorkUnit> units = shardUnits(scenes.size(), size_t(o.views), run.sweep.configs.size(), shard);

    HeadlessRunner runner({o.shaderDir, false});
    run.facts = runFacts(runner.glRenderer());
    run.facts["size"] = o.size;
    run.facts["frames"] = o.frames;
    run.facts["warmup"] = o.warmup;
    run.facts["views_per_scene"] = o.views;
    run.facts["reference"] = {{"definition", kReferenceDefinition},
                              {"variant", o.referenceVariant},
                              {"rays", o.referenceRays},
                              {"radius_scene", o.radiusScene}};
    if (o.oracle)
        run.facts["oracle"] = {{"layers", o.oracleLayers},
                               {"layers_two_layer_rows", 2}, // gbuffer.second_layer rows: a deep G-buffer's oracle
                               {"guard_band_px", o.oracleGuard},
                               {"thickness_r", std::isinf(o.oracleThickness) ? nlohmann::json("inf")
                                                                             : nlohmann::json(o.oracleThickness)}};
    if (o.motion)
        run.facts["motion"] = {{"frames", o.motionPath.frames}, {"orbit_deg", o.motionPath.orbitDeg},
                               {"dolly", o.motionPath.dolly}};
    run.facts["scene_specs"] = specs;
    run.facts["scenes"] = nlohmann::json::array();
    std::unique_ptr<Renderer> r = runner.makeRenderer(w, h);
    r->setWanted(std::set<std::string>{"ao.denoised"}); // what is judged: no composite, no albedo
    if (!o.quiet)
        std::printf("bench: %zu configurations x %zu scenes x %d views at %dx%d on %s%s\n", run.sweep.configs.size(),
                    scenes.size(), o.views, w, h, runner.glRenderer().c_str(),
                    shard.whole() ? "" : (" (shard " + shard.text() + ": " + std::to_string(units.size()) + " of " +
                                          std::to_string(scenes.size() * o.views * run.sweep.configs.size()) + " units)")
                                             .c_str());
    SceneBench bench(o, runner, *r, run, variant, engines);
    for (size_t si = 0; si < scenes.size(); ++si)
        bench.run(si, specs[si], scenes[si], units);
    run.shards = nlohmann::json::array({{{"shard", shard.text()},
                                         {"hostname", hostName()},
                                         {"cpu", run.facts["cpu"]},
                                         {"gl_renderer", run.facts["gl_renderer"]},
                                         {"date", run.facts["date"]},
                                         {"git_revision", run.facts["git_revision"]},
                                         {"rows", run.views.size()}}});
    std::string title;
    for (const auto& s : scenes)
        title += (title.empty() ? "" : ", ") + s.name;
    title += " | " + o.size + " | " + runner.glRenderer();
    return finishBench(run, o.out, title, o.plot, o.quiet, Question{o.budgetMs, o.maxError, o.budgetRatio, objective});
}

} // namespace ssao
