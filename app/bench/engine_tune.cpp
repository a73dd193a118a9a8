#include "bench/engine_tune.h"

#include "bench/engine_runner.h"
#include "bench/engine_snippet.h"
#include "bench/engine_table.h"
#include "bench/tune_guard.h"
#include "bench/viewpoints.h"
#include "cli_util.h"
#include "headless_runner.h"
#include "metrics/evaluate.h"
#include "progress_bar.h"
#include "reference/reference_cache.h"
#include "render_command.h"
#include "scene/view_fit.h"
#include "settings/preset.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/json_file.h"

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
                   "three-gtao), run for real in Chromium on the --scene glTF files; writes --out (JSON) and --snippet")
        ->type_name("NAME");
    cmd.add_option("--engine-modules", o.modules,
                   "the engines' npm packages (default: the build folder's peers/node_modules, from make engine-modules)")
        ->type_name(kInDir);
    cmd.add_option("--snippet", o.snippet, "with --engine: the settings as JavaScript for the engine's API (default: --out with .js)")
        ->type_name(kOutFile);
    cmd.add_option("--timing-frames", o.timingFrames, "with --engine: frames whose median times the defaults and the tuned settings")
        ->capture_default_str()
        ->check(cliRange(1, 1000));
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Which score a view counts in: fitted on; held out of a training scene; of a held-out scene.
enum class Role { Train, HeldOutView, HeldOutScene };

struct View {
    size_t scene;
    int index; // in its scene's runner
    std::string viewpoint;
    Role role;
    Camera camera; // fitted clip planes, scene frame
    ReferenceImage ref;
    std::map<std::string, double> base; // what the engine ran with at its make-peers settings here
};

struct Knob {
    const EngineParam* p;
    double lo, hi, value; // value: x the view's make-peers value when p->relative, else the value itself
};
using Candidate = std::vector<Knob>; // empty: the make-peers settings

struct Sample {
    size_t view;
    double mse, ms;
};

double meanOf(const std::vector<double>& v) {
    double s = 0;
    for (double x : v)
        s += x;
    return v.empty() ? kNaN : s / double(v.size());
}

class EngineTuner {
  public:
    EngineTuner(const TuneOptions& o, EngineTable table, int w, int h)
        : o_(o), table_(std::move(table)), tools_(locateEngineTools(o.engine.modules, table_)), w_(w), h_(h) {}

    // Scenes (glTF files: the browser loads them), their viewpoints and references, one runner each.
    void prepare() {
        std::vector<std::string> specs = o_.scenes;
        specs.insert(specs.end(), o_.heldOutScenes.begin(), o_.heldOutScenes.end());
        for (size_t si = 0; si < specs.size(); ++si) {
            scenes_.push_back(loadNamedScene(specs[si]));
            addViews(si, specs[si], si >= o_.scenes.size());
        }
    }

    // The make-peers settings on every view: what each ran with becomes its base.
    void measureDefaults() {
        const auto samples = measure({Candidate{}}, [](Role) { return true; }, 0, true);
        for (const Sample& s : samples[0])
            defaults_[s.view] = s.mse;
    }

    std::vector<Knob> chooseKnobs() const {
        std::vector<Knob> knobs;
        for (const EngineParam& p : table_.params) {
            const bool named = std::find(o_.knobs.begin(), o_.knobs.end(), p.name) != o_.knobs.end();
            if (p.role == EngineParam::Role::Shape && (o_.knobs.empty() || named))
                knobs.push_back({&p, p.searchLo, p.searchHi, p.relative ? 1.0 : views_[firstTrain()].base.at(p.name)});
        }
        for (const std::string& k : o_.knobs) {
            const EngineParam* p = table_.find(k);
            if (!p || p->role != EngineParam::Role::Shape)
                throw Error("--knob " + k + " is not a shape parameter of " + table_.engine + " (" + shapeNames() +
                            "; cost parameters are chosen by a budget, not fitted)");
        }
        return knobs;
    }

    double trainScore() const {
        std::vector<double> v;
        for (const View& view : views_)
            if (view.role == Role::Train) v.push_back(defaults_.at(&view - views_.data()));
        return meanOf(v);
    }

    // Coordinate search: each knob over a grid inside its bracket, which halves every round.
    void search(std::vector<Knob>& knobs, double best) {
        ProgressBar bar("  search " + std::to_string(knobs.size()) + " parameters of " + table_.title, !o_.quiet);
        const int total = o_.rounds * int(knobs.size());
        int done = 0;
        for (int round = 0; round < o_.rounds; ++round)
            for (Knob& k : knobs) {
                std::vector<Candidate> cands;
                for (int i = 0; i < o_.grid; ++i) {
                    cands.push_back(knobs);
                    cands.back()[size_t(&k - knobs.data())].value = gridValue(k, i);
                }
                const auto samples = measure(cands, [](Role r) { return r == Role::Train; }, 0, false);
                for (size_t c = 0; c < cands.size(); ++c) {
                    std::vector<double> mse;
                    for (const Sample& s : samples[c])
                        mse.push_back(s.mse);
                    if (const double m = meanOf(mse); m < best) best = m, k.value = cands[c][size_t(&k - knobs.data())].value;
                }
                shrink(k);
                bar.update(double(++done) / total);
            }
    }

    // Defaults and tuned on every view, timed: [0] the defaults' samples, [1] the tuned ones'.
    std::vector<std::vector<Sample>> finalMeasure(const std::vector<Knob>& tuned) {
        return measure({Candidate{}, tuned}, [](Role) { return true; }, o_.engine.timingFrames, false);
    }

    // The engine's value of each knob on a view.
    std::map<std::string, double> valuesFor(const Candidate& c, const View& v) const {
        std::map<std::string, double> out;
        for (const Knob& k : c) {
            const double x = k.p->relative ? v.base.at(k.p->name) * k.value : k.value;
            out[k.p->name] = exportedValue(k.p->type == EngineParam::Type::Integer ? std::round(x) : x);
        }
        return out;
    }

    const std::vector<View>& views() const { return views_; }
    const View& firstTrainView() const { return views_[firstTrain()]; }
    const std::vector<Scene>& scenes() const { return scenes_; }
    const EngineTable& table() const { return table_; }
    int sessions() const {
        int n = 0;
        for (const auto& r : runners_)
            n += r->sessions();
        return n;
    }
    std::string sceneSpec(size_t i) const { return specs_[i]; }

  private:
    void addViews(size_t si, const std::string& spec, bool heldOutScene) {
        const Scene& sc = scenes_.back();
        const float radius = o_.radiusScene * 2.0f * sc.bounds.radius();
        ReferenceProvider provider(sc);
        std::vector<EngineView> engineViews;
        int k = 0;
        for (const auto& [name, cam] : viewpoints(defaultCamera(sc), o_.views)) {
            const Camera c = effectiveCamera(cam, sc.bounds); // the clip planes ssaolab's renderer fits
            ProgressBar bar("  reference " + sc.name + " " + name, !o_.quiet);
            ReferenceImage ref = provider.get(c, w_, h_, {radius, o_.referenceRays}, [&](double f) { bar.update(f); });
            views_.push_back({si, k, name, heldOutScene ? Role::HeldOutScene : k % 2 == 0 ? Role::Train : Role::HeldOutView, c,
                              std::move(ref), {}});
            engineViews.push_back({cameraToJson(cameraToFile(c, sc)), radius});
            ++k;
        }
        specs_.push_back(spec);
        runners_.push_back(std::make_unique<EngineRunner>(tools_, table_, spec, w_, h_, std::move(engineViews)));
    }

    // Every candidate on every view `want` keeps, one browser session per scene; recordBase: each
    // view's base becomes what the engine ran with.
    template <class Want>
    std::vector<std::vector<Sample>> measure(const std::vector<Candidate>& cands, Want want, int frames, bool recordBase) {
        std::vector<std::vector<Sample>> out(cands.size());
        for (size_t si = 0; si < runners_.size(); ++si) {
            std::vector<EngineJob> jobs;
            std::vector<std::pair<size_t, size_t>> of; // (candidate, view) of each job
            for (size_t c = 0; c < cands.size(); ++c)
                for (size_t v = 0; v < views_.size(); ++v)
                    if (views_[v].scene == si && want(views_[v].role)) {
                        jobs.push_back({views_[v].index, valuesFor(cands[c], views_[v]), frames});
                        of.emplace_back(c, v);
                    }
            if (jobs.empty()) continue;
            const std::vector<EngineResult> res = runners_[si]->run(jobs);
            for (size_t j = 0; j < jobs.size(); ++j) {
                View& view = views_[of[j].second];
                const ErrorMetrics e = evaluate(res[j].ao, view.ref).metrics;
                if (e.nonFinite > 0) throw Error(table_.title + " returned non-finite AO on " + scenes_[si].name);
                if (recordBase) view.base = res[j].values;
                out[of[j].first].push_back({of[j].second, e.rmse * e.rmse, res[j].aoMs});
            }
        }
        return out;
    }

    double gridValue(const Knob& k, int i) const {
        const double t = i / double(o_.grid - 1);
        return k.p->log ? std::exp(std::log(k.lo) + (std::log(k.hi) - std::log(k.lo)) * t) : k.lo + (k.hi - k.lo) * t;
    }

    void shrink(Knob& k) const {
        if (k.p->log) {
            const double half = (std::log(k.hi) - std::log(k.lo)) / 4.0, c = std::log(k.value);
            k.lo = std::max(k.p->searchLo, std::exp(c - half));
            k.hi = std::min(k.p->searchHi, std::exp(c + half));
        } else {
            const double half = (k.hi - k.lo) / 4.0;
            k.lo = std::max(k.p->searchLo, k.value - half);
            k.hi = std::min(k.p->searchHi, k.value + half);
        }
    }

    size_t firstTrain() const {
        for (size_t i = 0; i < views_.size(); ++i)
            if (views_[i].role == Role::Train) return i;
        throw Error("no training view");
    }

    std::string shapeNames() const {
        std::string s;
        for (const EngineParam& p : table_.params)
            if (p.role == EngineParam::Role::Shape) s += (s.empty() ? "shape parameters: " : ", ") + p.name;
        return s;
    }

    const TuneOptions& o_;
    EngineTable table_;
    EngineTools tools_;
    int w_, h_;
    std::vector<Scene> scenes_;
    std::vector<std::string> specs_;
    std::vector<View> views_;
    std::vector<std::unique_ptr<EngineRunner>> runners_;
    std::map<size_t, double> defaults_; // view -> MSE at the make-peers settings
};

struct Outcome {
    double train[2], heldViews[2], heldScenes[2], ms[2]; // [0] defaults, [1] tuned; MSE means, AO ms
    FitVerdict verdict;
};

// Scores per role and the held-out verdict from the final, timed measurement.
Outcome judge(const EngineTuner& t, const std::vector<std::vector<Sample>>& s) {
    Outcome o{};
    std::map<size_t, HeldOutScore> held; // by scene: MSE sums, then means
    for (int side = 0; side < 2; ++side) {
        std::vector<double> byRole[3], ms;
        for (const Sample& x : s[side]) {
            const View& v = t.views()[x.view];
            byRole[int(v.role)].push_back(x.mse);
            ms.push_back(x.ms);
            if (v.role == Role::Train) continue;
            HeldOutScore& h = held[v.scene];
            h.scene = t.scenes()[v.scene].name + (v.role == Role::HeldOutView ? " (held-out views)" : "");
            (side == 0 ? h.before : h.after) += x.mse;
            h.views += side == 0;
        }
        o.train[side] = meanOf(byRole[0]), o.heldViews[side] = meanOf(byRole[1]), o.heldScenes[side] = meanOf(byRole[2]);
        o.ms[side] = meanOf(ms);
    }
    std::vector<HeldOutScore> list;
    for (auto& [scene, h] : held) {
        h.before /= h.views, h.after /= h.views;
        list.push_back(h);
    }
    o.verdict = judgeFit(list);
    return o;
}

nlohmann::json rmseJson(double mse) {
    return std::isfinite(mse) ? nlohmann::json(std::sqrt(mse)) : nlohmann::json();
}

nlohmann::json scoresJson(const TuneOptions& o, const Outcome& r) {
    auto side = [&](int s) {
        return nlohmann::json{{"train", rmseJson(r.train[s])}, {"held_out_views", rmseJson(r.heldViews[s])},
                              {"held_out_scenes", rmseJson(r.heldScenes[s])}, {"ao_ms", std::isfinite(r.ms[s]) ? nlohmann::json(r.ms[s]) : nlohmann::json()}};
    };
    return {{"metric", "geometry RMSE against the ray-traced reference (visibility, R = " + std::to_string(o.radiusScene) +
                           " x diagonal, " + std::to_string(o.referenceRays) + " rays), " + o.size +
                           "; AO ms: median frame with the pass - frame without, of " + std::to_string(o.engine.timingFrames) +
                           " frames, mean over every view"},
            {"defaults", side(0)},
            {"tuned", side(1)},
            {"held_out", {{"defaults", r.verdict.before}, {"tuned", r.verdict.after}}},
            {"held_out_rmse_ratio", r.verdict.before > 0 ? nlohmann::json(r.verdict.after / r.verdict.before) : nlohmann::json()},
            {"time_ratio", r.ms[0] > 0 ? nlohmann::json(r.ms[1] / r.ms[0]) : nlohmann::json()},
            {"overfit", r.verdict.overfit}};
}

void printOutcome(const TuneOptions& o, const EngineTuner& t, const std::vector<Knob>& knobs, const Outcome& r, double seconds) {
    if (o.quiet) return;
    size_t n[3] = {0, 0, 0};
    for (const View& v : t.views())
        ++n[int(v.role)];
    std::printf("tuned %s on %zu views (held out: %zu views of the same scenes, %zu views of %zu other scenes):",
                t.table().title.c_str(), n[0], n[1], n[2], o.heldOutScenes.size());
    const auto values = t.valuesFor(knobs, t.firstTrainView());
    for (const Knob& k : knobs)
        std::printf(k.p->relative ? " %s=%.4g (x%.3g)" : " %s=%.4g", k.p->name.c_str(), values.at(k.p->name), k.value);
    std::printf("\ngeometry RMSE, defaults -> tuned: training %.4f -> %.4f, held-out views %.4f -> %.4f",
                std::sqrt(r.train[0]), std::sqrt(r.train[1]), std::sqrt(r.heldViews[0]), std::sqrt(r.heldViews[1]));
    if (n[2]) std::printf(", held-out scenes %.4f -> %.4f", std::sqrt(r.heldScenes[0]), std::sqrt(r.heldScenes[1]));
    std::printf("\nheld-out RMSE x%.3f at x%.3f the AO time (%.1f -> %.1f ms); tuning took %.0f s in %d browser sessions\n",
                r.verdict.after / r.verdict.before, r.ms[1] / r.ms[0], r.ms[0], r.ms[1], seconds, t.sessions());
    std::fflush(stdout); // before any warning on stderr
}

std::string snippetPath(const TuneOptions& o) {
    if (!o.engine.snippet.empty()) return o.engine.snippet;
    return std::filesystem::path(o.out).replace_extension(".js").string();
}

void save(const TuneOptions& o, const EngineTuner& t, const std::vector<Knob>& knobs, const Outcome& r, double seconds, int w, int h) {
    const EngineTable& tab = t.table();
    const View& v = t.firstTrainView();
    const auto values = t.valuesFor(knobs, v);
    std::vector<std::pair<std::string, double>> ordered;
    nlohmann::json settings = nlohmann::json::object(), defaults = nlohmann::json::object(), search = nlohmann::json::object(),
                   cost = nlohmann::json::object();
    for (const Knob& k : knobs) {
        ordered.emplace_back(k.p->name, values.at(k.p->name));
        settings[k.p->name] = engineValueJson(*k.p, values.at(k.p->name));
        defaults[k.p->name] = engineValueJson(*k.p, exportedValue(v.base.at(k.p->name)));
        search[k.p->name] = k.p->relative ? nlohmann::json{{"x_make_peers_value", exportedValue(k.value)}} : nlohmann::json{{"value", exportedValue(k.value)}};
    }
    for (const EngineParam& p : tab.params)
        if (p.role == EngineParam::Role::Cost && v.base.count(p.name)) cost[p.name] = engineValueJson(p, v.base.at(p.name));
    const Scene& sc = t.scenes()[v.scene];
    char head[400];
    std::snprintf(head, sizeof head, "fitted to the ray-traced reference on %s (view '%s', %dx%d, R = %.4g scene units); held-out RMSE %.4f -> %.4f",
                  sc.name.c_str(), v.viewpoint.c_str(), w, h, o.radiusScene * 2.0 * sc.bounds.radius(), r.verdict.before, r.verdict.after);
    const std::string snippet = engineSnippet(tab, ordered, {"ssaolab tune --engine " + tab.engine + ": " + tab.title + " (" + tab.package + " " + tab.version + ")", head});
    const std::string js = snippetPath(o);
    std::error_code ec;
    const nlohmann::json out = {
        {"engine", tab.engine}, {"title", tab.title}, {"package", tab.package}, {"version", tab.version},
        {"settings", settings}, {"make_peers_settings", defaults}, {"search", search},
        {"cost_settings", {{"values", cost}, {"note", "no budget given: the engine's defaults"}}},
        {"view", {{"scene", std::filesystem::absolute(t.sceneSpec(v.scene), ec).string()}, {"viewpoint", v.viewpoint},
                  {"camera", cameraToJson(cameraToFile(v.camera, sc))}, {"size", {w, h}}, {"radius", o.radiusScene * 2.0 * sc.bounds.radius()}}},
        {"scores", scoresJson(o, r)}, {"tuning_seconds", seconds}, {"browser_sessions", t.sessions()},
        {"snippet", std::filesystem::path(js).filename().string()}};
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
}

} // namespace

int runEngineTune(const TuneOptions& o) {
    const auto start = std::chrono::steady_clock::now();
    int w = 0, h = 0;
    parseSizeOption(o.size, w, h);
    EngineTable table = findEngine(o.engine.engine);
    refuseTechniqueOptions(o, table);
    checkOutputPath(o.out); // before minutes of tuning
    checkOutputPath(snippetPath(o));
    EngineTuner t(o, std::move(table), w, h);
    t.prepare();
    t.measureDefaults();
    std::vector<Knob> knobs = t.chooseKnobs();
    t.search(knobs, t.trainScore());
    const Outcome r = judge(t, t.finalMeasure(knobs));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    printOutcome(o, t, knobs, r, seconds);
    if (r.verdict.overfit && !o.saveOverfit) throw Error(refusalText(r.verdict, o.out)); // nothing written
    save(o, t, knobs, r, seconds, w, h);
    if (r.verdict.overfit)
        printWarnings({overfitSavedText(r.verdict, o.out)});
    else if (!r.verdict.worse.empty())
        printWarnings({worseScenesText(r.verdict)});
    return 0;
}

} // namespace ssao
