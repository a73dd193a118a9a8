#include "commands/bench/bench_engines.h"

#include "engines/engine_settings_file.h"
#include "engines/engine_snippet.h"

#include "measure/thumbnails.h"
#include "cli/cli_util.h"
#include "cli/shared_options.h"
#include "metrics/evaluate.h"
#include "cli/progress_bar.h"
#include "scene/load/browser_assets.h"
#include "scene/scene.h"
#include "settings/params.h"
#include "settings/preset.h"
#include "util/error.h"
#include "util/json_file.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace ssao {

void addBenchEngineOptions(CLI::App& cmd, BenchEngineOptions& o) {
    cmd.add_option("--engines", o.names,
                   "web engines to add to the sweep, comma-separated (n8ao, pp-ssao, three-ssao, three-sao, three-gtao, babylon-ssao2, babylon-ssao, playcanvas-ssao, filament-ssao) or all: "
                   "each runs for real in Chromium on every view of every --scene glTF file at the bench's camera, "
                   "size and R, as the rows 'engine NAME (defaults)' (its defaults with every length set from R) "
                   "and 'engine NAME (as shipped)' (the package's defaults, but for the fixed rows that read the AO alone), "
                   "scored against the same reference; its time is the frame with the pass minus the frame without "
                   "in Chromium (median of --frames), not a GL timer query. A builtin scene is refused (three.js "
                   "loads glTF files); engines are not scored in motion and never chosen as a --budget answer")
        ->delimiter(',')
        ->type_name("NAME,...");
    cmd.add_option("--engine-settings", o.settings,
                   "with or without --engines: a `tune --engine` result (its --out JSON; repeatable) as the row "
                   "'engine NAME (tuned)': its settings, each relative one at the same multiple of the view's R")
        ->type_name(kInFile);
    addEngineModulesOption(cmd, o.modules);
}

namespace {

// A frame with the pass no slower than one without (the browser clock's resolution): not free.
constexpr double kMinEngineMs = 1e-3;

double engineMs(double ms) {
    return std::isfinite(ms) ? std::max(ms, kMinEngineMs) : ms;
}

nlohmann::json mapJson(const std::map<std::string, double>& m, const EngineTable& t) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, v] : m)
        j[name] = t.find(name) ? engineValueJson(*t.find(name), v) : nlohmann::json(v);
    return j;
}

} // namespace

BenchEngines::BenchEngines(const BenchEngineOptions& o, const std::vector<std::string>& sceneSpecs, int width,
                           int height, int frames)
    : width_(width), height_(height), frames_(frames) {
    std::vector<std::string> names = o.names;
    if (std::find(names.begin(), names.end(), "all") != names.end()) names = engineNames();
    for (const std::string& n : names) {
        const size_t t = tableOf(n);
        if (std::any_of(rows_.begin(), rows_.end(), [&](const Row& r) { return r.table == t; })) continue; // named twice
        Row r{t, {}, {}, {}};
        r.config.label = "engine " + tables_[t].engine + " (defaults)";
        r.config.keys = {{"engine", tables_[t].engine}};
        rows_.push_back(std::move(r));
        // Beside it, the engine as its package ships it: every row the harness sets from R at its
        // default, verbatim (the rows that read the AO alone stay set).
        Row shipped{t, {}, shippedValues(tables_[t]), {}};
        shipped.config.label = "engine " + tables_[t].engine + " (as shipped)";
        shipped.config.keys = {{"engine", tables_[t].engine}, {"shipped", true}};
        rows_.push_back(std::move(shipped));
    }
    std::vector<Row> tuned;
    for (const std::string& file : o.settings)
        addSettingsFile(file, tuned);
    for (Row& r : tuned) { // "(tuned)", or "(tuned: FILE)" where one engine has several
        const auto same = std::count_if(tuned.begin(), tuned.end(), [&](const Row& x) { return x.table == r.table; });
        const std::string file = r.config.keys["tuned"].get<std::string>();
        r.config.label = "engine " + tables_[r.table].engine + (same > 1 ? " (tuned: " + file + ")" : " (tuned)");
        rows_.push_back(std::move(r));
    }
    if (rows_.empty()) return;
    for (const std::string& spec : sceneSpecs)
        if (spec.rfind("builtin:", 0) == 0)
            throw Error("--engines runs web engines on glTF files (three.js loads the scene): " + spec +
                        " is built into ssaolab" + (sceneSpecs.size() == 1 && spec == "builtin:showcase" ? " (the default scene)" : "") +
                        "; name glTF scenes with --scene FILE.gltf");
    for (const EngineTable& t : tables_)
        tools_ = locateEngineTools(o.modules, t, "bench --engines");
    for (const std::string& spec : sceneSpecs) // what the browser would load, before any work (EngineRunner again)
        checkBrowserAssets(spec);
}

size_t BenchEngines::tableOf(const std::string& engine) {
    for (size_t i = 0; i < tables_.size(); ++i)
        if (tables_[i].engine == engine) return i;
    tables_.push_back(findEngine(engine)); // an unknown name throws, listing the engines
    return tables_.size() - 1;
}

// `tune --engine`'s JSON (engines/engine_settings_file.h): its engine and version, the settings it
// fitted (relative ones as their factor, per-R ones resolved on each scene's R), the cost settings
// it chose.
void BenchEngines::addSettingsFile(const std::string& path, std::vector<Row>& tuned) {
    TunedEngine te = readTunedEngine(path);
    Row r{tableOf(te.table.engine), {}, std::move(te.values), std::move(te.scale), std::move(te.perRadius)};
    r.config.keys = {{"engine", te.table.engine}, {"tuned", std::filesystem::path(path).filename().string()}};
    tuned.push_back(std::move(r));
}

void BenchEngines::appendTo(Sweep& sweep) {
    first_ = sweep.configs.size();
    for (Row& r : rows_) {
        const EngineTable& t = tables_[r.table];
        r.config.group = "engines";
        r.config.settings = defaultSettings(); // not read: an engine row has no ssaolab settings
        r.config.engine = {{"name", t.engine}, {"title", t.title}, {"package", t.package}, {"version", t.version},
                           {"values", mapJson(r.values, t)}, {"scale", nlohmann::json(r.scale)}};
        for (const auto& [name, f] : r.perRadius)
            r.config.engine["per_radius"][name] = {{"factor", f.first}, {"exponent", f.second}};
        sweep.configs.push_back(r.config);
    }
}

void BenchEngines::runScene(const std::string& spec, const Scene& scene, float radius, bool quiet, BenchRun& run) {
    if (pending_.empty()) return;
    std::vector<EngineView> views;
    std::vector<EngineJob> jobs;
    std::vector<std::pair<size_t, size_t>> of; // (pending view, configuration) of each job
    for (size_t p = 0; p < pending_.size(); ++p) {
        views.push_back({cameraToJson(cameraToFile(pending_[p].camera, scene)), radius});
        for (size_t c : pending_[p].configs) {
            const Row& r = rows_[c - first_];
            std::map<std::string, double> values = r.values;
            for (const auto& [name, f] : r.perRadius) // per R of this scene, as tune applies it to a held-out scene
                values[name] = exportedValue(f.first * std::pow(double(radius), f.second));
            jobs.push_back({int(p), values, frames_, r.scale, &tables_[r.table]});
            of.emplace_back(p, c);
        }
    }
    ProgressBar bar("  " + scene.name + ": " + std::to_string(jobs.size()) + " engine rows in Chromium", !quiet);
    EngineRunner runner(tools_, tables_[0], spec, width_, height_, std::move(views));
    const std::vector<EngineResult> res = runner.run(jobs);
    for (size_t j = 0; j < jobs.size(); ++j) {
        const EngineViewWork& w = pending_[of[j].first];
        if (res[j].hung)
            throw Error("bench --engines: " + run.sweep.configs[of[j].second].label + " hung the browser on " + scene.name + " " +
                        w.viewpoint + " past its time limit (SSAOLAB_BROWSER_MAX_SECONDS)");
        const Evaluation e = evaluate(res[j].ao, w.ref);
        ViewResult v;
        v.scene = scene.name;
        v.viewpoint = w.viewpoint;
        v.config = of[j].second;
        v.error = e.metrics;
        v.rmseFirstFrame = e.metrics.rmse; // one still frame, no accumulation
        if (w.oracle) {
            v.vsOracle = evaluate(res[j].ao, *w.oracle).metrics;
            v.hasSplit = true;
            v.screen = w.screen;
        }
        v.gpuMs = engineMs(res[j].aoMs), v.gpuMsMin = engineMs(res[j].aoMsMin), v.gpuMsMax = engineMs(res[j].aoMsMax);
        v.baselineMs = w.baselineMs;
        if (!w.thumbs.empty()) writeThumbnails(w.thumbs, v.config, e, w.ref);
        run.views.push_back(v);
    }
    bar.update(1.0);
    pending_.clear();
}

} // namespace ssao
