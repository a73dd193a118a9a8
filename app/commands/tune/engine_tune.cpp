#include "commands/tune/engine_tune.h"

#include "measure/bench_run.h"
#include "commands/tune/engine_compare.h"
#include "engines/engine_runner.h"
#include "engines/engine_settings_file.h"
#include "commands/tune/engine_tune_page.h"
#include "commands/tune/engine_tuner.h"
#include "engines/engine_snippet.h"
#include "engines/engine_table.h"
#include "commands/tune/tune_guard.h"
#include "measure/viewpoints.h"
#include "cli/cli_util.h"
#include "cli/shared_options.h"
#include "cli/headless_runner.h"
#include "metrics/evaluate.h"
#include "cli/progress_bar.h"
#include "reference/reference_cache.h"
#include "cli/scene_options.h"
#include "scene/load/browser_assets.h"
#include "scene/view_fit.h"
#include "settings/preset.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/number_text.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>

namespace ssao {

void addEngineTuneOptions(CLI::App& cmd, EngineTuneOptions& o) {
    cmd.add_option("--engine", o.engine,
                   "tune a web engine's own AO settings instead of a technique (n8ao, three-ssao, three-sao, "
                   "three-gtao, pp-ssao, babylon-ssao2, babylon-ssao, playcanvas-ssao, filament-ssao), run for real in Chromium on the --scene glTF files; writes --out (JSON) and --snippet")
        ->type_name("NAME");
    addEngineModulesOption(cmd, o.modules);
    cmd.add_option("--snippet", o.snippet, "with --engine: the settings as JavaScript for the engine's API (default: --out with .js)")
        ->type_name(kOutFile);
    addBudgetMsOption(cmd, o.budgetMs,
                      {"with --engine: the sample counts, the largest that fit after the shape is fitted, within ",
                       "the training views' mean AO time; default: the engine's own counts"});
    addBudgetRatioOption(cmd, o.budgetRatio,
                         {"with --engine: the sample counts within ", "the baseline: the defaults, measured in the same run"});
    addTimingFramesOption(cmd, o.timingFrames, {"with --engine: ", "their median times the defaults and the tuned settings"});
}

namespace {

// The final measurement's sides (EngineTuner::finalMeasure); kRepeat times the shipped settings again.
constexpr int kFromR = 0, kTuned = 1, kShipped = 2, kSides = 3, kRepeat = 3;

// One scene's views of one role, per side; MSE and AO ms means.
struct SceneScore {
    size_t scene;
    TuneRole role;
    int views = 0;
    double mse[kSides] = {0, 0, 0}, ms[kSides] = {0, 0, 0};
};

struct Outcome {
    double train[kSides], heldViews[kSides], heldScenes[kSides], ms[kSides]; // per side: MSE means, AO ms
    double heldAll[kSides];  // MSE mean over every held-out view
    double heldOracle = NAN; // the screen-space oracle's MSE mean over the same views
    double timeNoise = 0;    // RMS over views of log(ms repeat / ms shipped): the timing's own spread
    FitVerdict verdict; // against the better baseline (tune_guard.h judgeAgainstBetter)
    int better = kShipped; // which baseline that is
    std::vector<SceneScore> perScene; // by scene, then role
    std::vector<std::string> shortTimings; // "SIDE on SCENE VIEW: N frames": timed jobs the harness ended early
};

// The final jobs timed on fewer frames than asked: theirs took the harness's cap (harness.js kTimedMs).
std::vector<std::string> shortTimings(const EngineTuner& t, const std::vector<std::vector<Sample>>& s, int frames) {
    static const char* names[] = {"lengths from R", "tuned", "as shipped", "as shipped (repeat)"};
    std::vector<std::string> out;
    for (size_t side = 0; side < s.size() && side < 4; ++side)
        for (const Sample& x : s[side])
            if (x.timedFrames > 0 && x.timedFrames < frames) {
                const TuneView& v = t.views()[x.view];
                out.push_back(std::string(names[side]) + " on " + t.scenes()[v.scene].name + " " + v.viewpoint + ": " +
                              std::to_string(x.timedFrames) + " frame(s) of " + numberText(x.ms / 1000.0, "%.*g", 3) + " s");
            }
    return out;
}

std::vector<SceneScore> perSceneScores(const EngineTuner& t, const std::vector<std::vector<Sample>>& s) {
    std::map<std::pair<size_t, int>, SceneScore> by;
    for (int side = 0; side < kSides; ++side)
        for (const Sample& x : s[side]) {
            const TuneView& v = t.views()[x.view];
            SceneScore& sc = by[{v.scene, int(v.role)}];
            sc.scene = v.scene, sc.role = v.role;
            sc.views += side == 0;
            sc.mse[side] += x.mse, sc.ms[side] += x.ms;
        }
    std::vector<SceneScore> out;
    for (auto& [key, sc] : by) {
        for (int side = 0; side < kSides; ++side)
            sc.mse[side] /= sc.views, sc.ms[side] /= sc.views;
        out.push_back(sc);
    }
    return out;
}

// Scores per role and the held-out verdict from the final, timed measurement.
Outcome judge(const EngineTuner& t, const std::vector<std::vector<Sample>>& s, int frames) {
    Outcome o{};
    std::map<size_t, HeldOutScore> held[2]; // by scene, against [0] the defaults from R, [1] as shipped
    for (int side = 0; side < kSides; ++side) {
        std::vector<double> byRole[3], ms, heldAll;
        for (const Sample& x : s[side]) {
            const TuneView& v = t.views()[x.view];
            byRole[int(v.role)].push_back(x.mse);
            ms.push_back(x.ms);
            if (v.role == TuneRole::Train) continue;
            heldAll.push_back(x.mse);
            for (int b = 0; b < 2; ++b) {
                HeldOutScore& h = held[b][v.scene];
                h.scene = t.scenes()[v.scene].name + (v.role == TuneRole::HeldOutView ? " (held-out views)" : "");
                if (side == kTuned) h.after += x.mse;
                if (side == (b == 0 ? kFromR : kShipped)) h.before += x.mse, ++h.views;
            }
        }
        o.train[side] = meanOf(byRole[0]), o.heldViews[side] = meanOf(byRole[1]), o.heldScenes[side] = meanOf(byRole[2]);
        o.ms[side] = meanOf(ms), o.heldAll[side] = meanOf(heldAll);
    }
    std::vector<double> oracle;
    for (const TuneView& v : t.views())
        if (v.role != TuneRole::Train) oracle.push_back(v.oracleMse);
    o.heldOracle = meanOf(oracle);
    std::vector<HeldOutScore> lists[2];
    for (int b = 0; b < 2; ++b)
        for (auto& [scene, h] : held[b]) {
            h.before /= h.views, h.after /= h.views;
            lists[b].push_back(h);
        }
    double noise = 0; // over the views where both timings took time (a tiny frame can time at or below 0)
    int timed = 0;
    std::map<size_t, double> first; // view -> the shipped settings' AO ms
    for (const Sample& x : s[kShipped])
        first[x.view] = x.ms;
    for (const Sample& x : s[kRepeat])
        if (x.ms > 0 && first[x.view] > 0) noise += std::pow(std::log(x.ms / first[x.view]), 2), ++timed;
    o.timeNoise = timed ? std::sqrt(noise / timed) : 0;
    o.verdict = judgeAgainstBetter(lists[1], lists[0]);
    o.better = o.verdict.baseline == "as shipped" ? kShipped : kFromR;
    o.perScene = perSceneScores(t, s);
    o.shortTimings = shortTimings(t, s, frames);
    return o;
}

nlohmann::json rmseJson(double mse) {
    return std::isfinite(mse) ? nlohmann::json(std::sqrt(mse)) : nlohmann::json();
}

nlohmann::json msJson(double ms) {
    return std::isfinite(ms) ? nlohmann::json(ms) : nlohmann::json();
}

const char* roleName(TuneRole r) {
    return r == TuneRole::Train ? "train" : r == TuneRole::HeldOutView ? "held-out views" : "held-out scene";
}

nlohmann::json perSceneJson(const EngineTuner& t, const Outcome& r) {
    nlohmann::json rows = nlohmann::json::array();
    for (const SceneScore& s : r.perScene)
        rows.push_back({{"scene", t.scenes()[s.scene].name}, {"role", roleName(s.role)}, {"views", s.views},
                        {"rmse", {{"shipped", rmseJson(s.mse[kShipped])}, {"defaults", rmseJson(s.mse[kFromR])},
                                  {"tuned", rmseJson(s.mse[kTuned])}}},
                        {"ao_ms", {{"shipped", msJson(s.ms[kShipped])}, {"defaults", msJson(s.ms[kFromR])},
                                   {"tuned", msJson(s.ms[kTuned])}}}});
    return rows;
}

nlohmann::json scoresJson(const TuneOptions& o, const Outcome& r) {
    auto side = [&](int s) {
        return nlohmann::json{{"train", rmseJson(r.train[s])}, {"held_out_views", rmseJson(r.heldViews[s])},
                              {"held_out_scenes", rmseJson(r.heldScenes[s])}, {"ao_ms", msJson(r.ms[s])}};
    };
    return {{"metric", "geometry RMSE against the ray-traced reference (visibility, R = " + std::to_string(o.radiusScene) +
                           " x diagonal, " + std::to_string(o.referenceRays) + " rays), " + o.size +
                           "; AO ms: median frame with the pass - frame without, of " + std::to_string(o.engine.timingFrames) +
                           " frames (fewer where they took 20 s in all: short_timings), mean over every view"},
            {"shipped", side(kShipped)},
            {"defaults", side(kFromR)},
            {"tuned", side(kTuned)},
            {"held_out", {{"shipped", rmseJson(r.heldAll[kShipped])}, {"defaults", rmseJson(r.heldAll[kFromR])},
                          {"tuned", r.verdict.after}, {"baseline", r.verdict.baseline},
                          {"screen_oracle", rmseJson(r.heldOracle)}}},
            {"held_out_rmse_ratio", r.verdict.before > 0 ? nlohmann::json(r.verdict.after / r.verdict.before) : nlohmann::json()},
            {"time_ratio", r.ms[kShipped] > 0 ? nlohmann::json(r.ms[kTuned] / r.ms[kShipped]) : nlohmann::json()},
            {"time_ratio_vs_defaults", r.ms[kFromR] > 0 ? nlohmann::json(r.ms[kTuned] / r.ms[kFromR]) : nlohmann::json()},
            {"time_noise", r.timeNoise},
            {"short_timings", r.shortTimings},
            {"overfit", r.verdict.overfit}};
}

// The tuned settings' AO time against the shipped, or "the same AO time" when the change is within
// the timing's own spread (the shipped settings timed twice; at least 2 %).
std::string timeText(const Outcome& r) {
    const double ratio = r.ms[kTuned] / r.ms[kShipped], noise = std::max(0.02, 2.0 * r.timeNoise);
    char b[160];
    if (!(r.ms[kShipped] > 0) || !(r.ms[kTuned] > 0) || !std::isfinite(ratio)) { // a tiny frame times at or below 0
        std::snprintf(b, sizeof b, "no AO time to compare (shipped %.1f ms, tuned %.1f ms: below the browser's clock)",
                      r.ms[kShipped], r.ms[kTuned]);
        return b;
    }
    if (std::abs(std::log(ratio)) <= noise)
        std::snprintf(b, sizeof b, "the shipped AO time within its timing's spread (x%.3f, %.1f -> %.1f ms; +-%.0f %%)", ratio,
                      r.ms[kShipped], r.ms[kTuned], 100.0 * noise);
    else
        std::snprintf(b, sizeof b, "at x%.3f the shipped AO time (%.1f -> %.1f ms; the timing's spread +-%.0f %%)", ratio,
                      r.ms[kShipped], r.ms[kTuned], 100.0 * noise);
    return b;
}

void printOutcome(const TuneOptions& o, const EngineTuner& t, const std::vector<Knob>& knobs, const Outcome& r, double seconds) {
    if (o.quiet) return;
    size_t n[3] = {0, 0, 0};
    for (const TuneView& v : t.views())
        ++n[int(v.role)];
    std::printf("tuned %s on %zu views (held out: %zu views of the same scenes, %zu views of %zu other scenes):",
                t.table().title.c_str(), n[0], n[1], n[2], o.heldOutScenes.size());
    const auto values = t.valuesFor(knobs, t.firstTrainView());
    for (const Knob& k : knobs)
        std::printf(k.p->relative ? " %s=%.4g (x%.3g)" : k.p->perRadius == 1 ? " %s=%.4g (%.3g R)" : k.p->perRadius ? " %s=%.4g (%.3g / R)" : " %s=%.4g", k.p->name.c_str(),
                    values.at(k.p->name), k.value);
    auto three = [](const double* m) {
        char b[96];
        std::snprintf(b, sizeof b, "%.4f / %.4f -> %.4f", std::sqrt(m[kShipped]), std::sqrt(m[kFromR]), std::sqrt(m[kTuned]));
        return std::string(b);
    };
    std::printf("\ngeometry RMSE, as shipped / lengths from R -> tuned: training %s, held-out views %s",
                three(r.train).c_str(), three(r.heldViews).c_str());
    if (n[2]) std::printf(", held-out scenes %s", three(r.heldScenes).c_str());
    std::printf("\nthe screen-space oracle (a perfect estimator on this G-buffer) on the held-out views: %.4f", std::sqrt(r.heldOracle));
    std::printf("\nheld-out RMSE x%.3f the engine %s (the better baseline), %s; tuning took %.0f s, %d batches in %d browser session(s)\n",
                r.verdict.after / r.verdict.before, r.verdict.baseline.c_str(), timeText(r).c_str(), seconds, t.batches(),
                t.sessions());
    for (const std::string& line : r.shortTimings)
        std::printf("timed on fewer frames than --timing-frames (they took 20 s in all): %s\n", line.c_str());
    if (t.hungJobs())
        std::printf("the browser hung on %d candidate setting(s) past its time limit: each was dropped from the search\n", t.hungJobs());
    std::fflush(stdout); // before any warning on stderr
}

std::string snippetPath(const TuneOptions& o) {
    if (!o.engine.snippet.empty()) return o.engine.snippet;
    return std::filesystem::path(o.out).replace_extension(".js").string();
}

std::string pagePath(const TuneOptions& o) {
    return std::filesystem::path(o.out).replace_extension(".html").string();
}

std::vector<std::vector<std::string>> settingRows(const EngineTuner& t, const std::vector<Knob>& knobs) {
    const TuneView& v = t.firstTrainView();
    const auto tuned = t.valuesFor(knobs, v);
    const KnobSet shipped = t.shippedKnobs();
    std::vector<std::vector<std::string>> rows;
    for (const EngineParam& p : t.table().params) {
        if (p.role == EngineParam::Role::Fixed || !v.base.count(p.name)) continue;
        const auto it = tuned.find(p.name);
        const bool fromR = std::any_of(shipped.begin(), shipped.end(), [&](const Knob& k) { return k.p == &p; });
        rows.push_back({p.name, engineValueJson(p, p.defaultValue).dump() + (fromR ? " (the package's)" : ""),
                        engineValueJson(p, exportedValue(v.base.at(p.name))).dump(),
                        it == tuned.end() ? "(defaults)" : engineValueJson(p, it->second).dump(),
                        p.role == EngineParam::Role::Shape ? "shape (fitted)" : "cost (the budget's)", p.unit});
    }
    return rows;
}

// The page's rows: each scene's roles, its shown view's images, and ssaolab's shipped presets
// measured there, the most accurate within the tuned engine's time chosen.
std::vector<PageRow> pageRows(const TuneOptions& o, const EngineTuner& t, const Outcome& r, const std::vector<std::vector<Sample>>& s) {
    std::unique_ptr<HeadlessRunner> runner;
    std::vector<PageRow> rows;
    for (const SceneScore& sc : r.perScene) {
        PageRow row{t.scenes()[sc.scene].name, roleName(sc.role), sc.views,
                    {"defaults", std::sqrt(sc.mse[kFromR]), sc.ms[kFromR], nullptr},
                    {"tuned", std::sqrt(sc.mse[kTuned]), sc.ms[kTuned], nullptr},
                    {"as shipped", std::sqrt(sc.mse[kShipped]), sc.ms[kShipped], nullptr}};
        for (int side = 0; side < kSides; ++side)
            for (const Sample& x : s[size_t(side)]) {
                const TuneView& v = t.views()[x.view];
                if (v.scene != sc.scene || v.role != sc.role || !v.shown || !x.eval) continue;
                row.shownView = v.viewpoint, row.ref = &v.ref;
                (side == kFromR ? row.defaults : side == kTuned ? row.tuned : row.shipped).eval = x.eval;
                if (side != kTuned) continue;
                if (!runner) runner = std::make_unique<HeadlessRunner>(HeadlessRunner::Options{o.shaderDir, false});
                ProgressBar bar("  ssaolab's presets on " + row.scene + " " + v.viewpoint, !o.quiet);
                const float radius = o.radiusScene * 2.0f * t.scenes()[sc.scene].bounds.radius();
                const auto points = measureShippedPresets(*runner, t.scenes()[sc.scene], v.camera, v.ref, radius, 1,
                                                          std::min(o.engine.timingFrames, 5));
                bar.update(1);
                if (const PresetPoint* best = mostAccurateWithin(points, x.ms))
                    row.hasSsaolab = true, row.ssaolab = {best->preset, best->rmse, best->ms, best->eval};
            }
        rows.push_back(std::move(row));
    }
    return rows;
}

// R of every scene, where it comes from and its unit: what "lengths from R" scaled.
std::string radiusLine(const TuneOptions& o, const EngineTuner& t) {
    std::string out = "R, the AO radius of the reference and of every length the harness sets from it: ";
    char b[160];
    for (size_t i = 0; i < t.scenes().size(); ++i) {
        const double diagonal = 2.0 * t.scenes()[i].bounds.radius();
        std::snprintf(b, sizeof b, "%s%.4g scene units on %s", i ? ", " : "", o.radiusScene * diagonal,
                      t.scenes()[i].name.c_str());
        out += b;
    }
    std::snprintf(b, sizeof b, " (--radius-scene %.4g x each scene's bounding-box diagonal; scene units are the glTF's, "
                               "metres by its convention).", o.radiusScene);
    return out + b;
}

void writePage(const TuneOptions& o, const EngineTuner& t, const std::vector<Knob>& knobs, const Outcome& r,
               const std::vector<std::vector<Sample>>& s, double seconds) {
    const EngineTable& tab = t.table();
    EnginePage p{tab.title, tab.package, tab.version, o.size, scoresJson(o, r)["metric"].get<std::string>(),
                 runFacts("Chromium (WebGL 2) for the engine; EGL for ssaolab"), settingRows(t, knobs),
                 r.verdict.before, r.verdict.after, r.ms[kShipped] > 0 ? r.ms[kTuned] / r.ms[kShipped] : NAN, r.verdict.baseline,
                 radiusLine(o, t),
                 seconds, pageRows(o, t, r, s)};
    writeFileAtomically(pagePath(o), engineTunePageHtml(p));
    if (!o.quiet) std::printf("saved %s\n", pagePath(o).c_str());
}

nlohmann::json costJson(const EngineTable& tab, const TuneView& v, const std::vector<Knob>& knobs, const std::vector<BudgetRung>& rungs) {
    nlohmann::json values = nlohmann::json::object(), ladder = nlohmann::json::array();
    for (const EngineParam& p : tab.params)
        if (p.role == EngineParam::Role::Cost && v.base.count(p.name)) values[p.name] = engineValueJson(p, v.base.at(p.name));
    for (const Knob& k : knobs)
        if (k.p->role == EngineParam::Role::Cost) values[k.p->name] = engineValueJson(*k.p, k.value);
    if (rungs.empty()) return {{"values", values}, {"note", "no budget given: the engine's defaults"}};
    for (const BudgetRung& r : rungs)
        ladder.push_back({{"factor", r.factor}, {"ao_ms", r.ms}, {"chosen", r.chosen}});
    return {{"values", values}, {"budget_ms", rungs.front().budget}, {"rungs", ladder},
            {"note", "the sample counts x factor whose training views' mean AO time fits the budget (the largest; the smallest when none fits)"}};
}

void save(const TuneOptions& o, const EngineTuner& t, const std::vector<Knob>& knobs, const std::vector<BudgetRung>& rungs,
          const Outcome& r, double seconds, int w, int h, const std::vector<std::string>& walls) {
    const EngineTable& tab = t.table();
    const TuneView& v = t.firstTrainView();
    const auto values = t.valuesFor(knobs, v);
    std::vector<std::pair<std::string, double>> ordered;
    nlohmann::json settings = nlohmann::json::object(), defaults = nlohmann::json::object(), search = nlohmann::json::object();
    for (const Knob& k : knobs) {
        ordered.emplace_back(k.p->name, values.at(k.p->name));
        settings[k.p->name] = engineValueJson(*k.p, values.at(k.p->name));
        defaults[k.p->name] = engineValueJson(*k.p, exportedValue(v.base.at(k.p->name)));
        if (k.p->role == EngineParam::Role::Shape)
            search[k.p->name] = k.p->relative    ? nlohmann::json{{"x_make_peers_value", exportedValue(k.value)}}
                                : k.p->perRadius ? nlohmann::json{{k.p->perRadius == 1 ? "x_R" : "x_1_over_R", exportedValue(k.value)}}
                                                 : nlohmann::json{{"value", exportedValue(k.value)}};
    }
    const Scene& sc = t.scenes()[v.scene];
    char head[400];
    std::snprintf(head, sizeof head, "fitted to the ray-traced reference on the scene and view below (%dx%d, R = %.4g scene units); held-out RMSE %.4f -> %.4f",
                  w, h, o.radiusScene * 2.0 * sc.bounds.radius(), r.verdict.before, r.verdict.after);
    const SnippetFacts facts{{"ssaolab tune --engine " + tab.engine + ": " + tab.title + " (" + tab.package + " " + tab.version + ")", head},
                             {{"scene", sc.name}, {"view", v.viewpoint}}};
    const std::string snippet = engineSnippet(tab, ordered, facts);
    const std::string js = snippetPath(o);
    std::error_code ec;
    const nlohmann::json out = {
        {"engine", tab.engine}, {"title", tab.title}, {"package", tab.package}, {"version", tab.version},
        {"settings", settings}, {"make_peers_settings", defaults}, {"search", search},
        {"cost_settings", costJson(tab, v, knobs, rungs)},
        {"view", {{"scene", std::filesystem::absolute(t.sceneSpec(v.scene), ec).string()}, {"viewpoint", v.viewpoint},
                  {"camera", cameraToJson(cameraToFile(v.camera, sc))}, {"size", {w, h}}, {"radius", o.radiusScene * 2.0 * sc.bounds.radius()}}},
        {"scores", scoresJson(o, r)}, {"per_scene", perSceneJson(t, r)}, {"tuning_seconds", seconds}, {"browser_sessions", t.sessions()}, {"browser_batches", t.batches()},
        {"hung_candidates", t.hungJobs()},
        {"at_range_edge", walls},
        {"snippet", std::filesystem::path(js).filename().string()}};
    parseTunedEngine(out, o.out); // what bench --engine-settings will accept, checked by the same reader
    writeFileAtomically(o.out, dumpJson(out) + "\n");
    writeFileAtomically(js, snippet);
    if (!o.quiet) std::printf("saved %s and %s\n", o.out.c_str(), js.c_str());
}

// Before the browser is looked for: what no engine run could do.
void refuseTechniqueOptions(const TuneOptions& o, const EngineTable& t) {
    if (o.scenes.empty()) throw Error("--engine needs --scene FILE.gltf (the engine loads the scene in the browser)");
    std::vector<std::string> specs = o.scenes;
    specs.insert(specs.end(), o.heldOutScenes.begin(), o.heldOutScenes.end());
    for (size_t i = 0; i < specs.size(); ++i) {
        if (specs[i].rfind("builtin:", 0) == 0)
            throw Error("--engine runs " + t.title + " on glTF files (three.js loads the scene): " + specs[i] + " is built into ssaolab");
        if (std::find(specs.begin(), specs.begin() + long(i), specs[i]) != specs.begin() + long(i))
            throw Error("--scene " + specs[i] + " is named twice: a scene trains or is held out, once");
    }
    if (!o.preset.empty()) throw Error("--preset starts a technique's tune; --engine starts from the engine's own defaults");
    if (!o.sets.empty()) throw Error("--set KEY=VALUE sets ssaolab's parameters; --engine tunes the engine's own");
    if (o.objective != "still") throw Error("--objective motion is not measured for --engine (a still frame per view)");
    if (o.engine.budgetMs > 0 && o.engine.budgetRatio > 0) throw Error("--budget-ms and --budget-ratio: give one budget");
    const bool scales = std::any_of(t.params.begin(), t.params.end(), [](const EngineParam& p) { return p.scalesWithBudget; });
    if ((o.engine.budgetMs > 0 || o.engine.budgetRatio > 0) && !scales)
        throw Error(t.title + " has no sample count a budget could scale (its cost parameters change the denoiser only): drop --budget-ms/--budget-ratio");
}

} // namespace

int runEngineTune(const TuneOptions& o) {
    const auto start = std::chrono::steady_clock::now();
    int w = 0, h = 0;
    parseSizeOption(o.size, w, h);
    EngineTable table = findEngine(o.engine.engine);
    refuseTechniqueOptions(o, table);
    for (const std::string& spec : o.scenes) // what the browser would load, before any work (EngineRunner again)
        checkBrowserAssets(spec);
    for (const std::string& spec : o.heldOutScenes)
        checkBrowserAssets(spec);
    checkOutputPath(o.out); // before minutes of tuning
    checkOutputPath(snippetPath(o));
    checkOutputPath(pagePath(o));
    EngineTuner t(o, std::move(table), w, h);
    t.prepare();
    t.measureDefaults();
    std::vector<Knob> knobs = t.chooseKnobs();
    const std::vector<std::string> walls = t.search(knobs, t.trainScore());
    const std::vector<BudgetRung> rungs = t.chooseCost(knobs);
    const std::vector<std::vector<Sample>> final = t.finalMeasure(knobs);
    const Outcome r = judge(t, final, o.engine.timingFrames);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    printOutcome(o, t, knobs, r, seconds);
    printWarnings(walls);
    if (r.verdict.overfit && !o.saveOverfit) throw Error(refusalText(r.verdict, o.out)); // nothing written
    save(o, t, knobs, rungs, r, seconds, w, h, walls);
    writePage(o, t, knobs, r, final, seconds);
    if (r.verdict.overfit)
        printWarnings({overfitSavedText(r.verdict, o.out)});
    else if (!r.verdict.worse.empty())
        printWarnings({worseScenesText(r.verdict)});
    return 0;
}

} // namespace ssao
