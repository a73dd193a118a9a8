#include "results/bench_results.h"

#include "metrics/error_split.h"
#include "settings/params.h"
#include "util/error.h"
#include "results/results_check.h"
#include "util/files.h"
#include "util/json_file.h"

#include <cmath>
#include <filesystem>
#include <limits>

namespace ssao {

namespace {

nlohmann::json jnum(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json configFields(const BenchConfig& c, const ConfigSummary& s);
nlohmann::json viewFields(const ViewResult& v, const std::string& label);

void splitJson(nlohmann::json& j, const SplitSummary& t, const SplitSummary& sc) {
    j["rmse_vs_oracle"] = jnum(t.rmse), j["bias_vs_oracle"] = jnum(t.bias);
    j["rmse_edge_vs_oracle"] = jnum(t.rmseEdge), j["rmse_interior_vs_oracle"] = jnum(t.rmseInterior);
    j["rmse_screen"] = jnum(sc.rmse), j["bias_screen"] = jnum(sc.bias);
    j["rmse_edge_screen"] = jnum(sc.rmseEdge), j["rmse_interior_screen"] = jnum(sc.rmseInterior);
}

// bench --motion's columns (null without).
void motionJson(nlohmann::json& j, const MotionSummary& m, bool row) {
    j["motion_rmse_mean"] = jnum(m.rmseMean), j["motion_instability"] = jnum(m.instability);
    j["motion_ghosting"] = jnum(m.ghosting);
    if (row) j["motion_rmse_max"] = jnum(m.rmseMax);
}

// The split's shares of the squared error (metrics/error_split.h), from the three RMSEs of the
// same pixels: they sum to 1 where the RMSEs do not add (null without a split).
void sharesFields(nlohmann::json& j, double total, double technique, double screen) {
    const ErrorShares s = sharesOfMse(total * total, technique * technique, screen * screen);
    j["share_technique"] = jnum(s.technique), j["share_screen"] = jnum(s.screen);
    j["share_interaction"] = jnum(s.interaction);
}

nlohmann::json configJson(const BenchConfig& c, const ConfigSummary& s) {
    nlohmann::json j = configFields(c, s);
    if (c.isEngine()) j["settings"] = nullptr, j["engine"] = c.engine; // a web engine's row: its own settings
    splitJson(j, s.technique, s.screen);
    sharesFields(j, s.rmse, s.technique.rmse, s.screen.rmse);
    motionJson(j, s.motion, false);
    j["motion_score"] = jnum(s.motionScore), j["motion_score_ratio"] = jnum(s.motionRatio);
    return j;
}

// Where the time went (bench_summary.h PassTimes), ms.
nlohmann::json passJson(const PassTimes& t) {
    nlohmann::json j = nlohmann::json::object();
    for (int k = 0; k < PassTimes::kParts; ++k)
        j[PassTimes::kNames[k]] = jnum(t.ms[k]);
    return j;
}

nlohmann::json configFields(const BenchConfig& c, const ConfigSummary& s) {
    return {{"label", c.label},
            {"group", c.group},
            {"keys", c.keys},
            {"aliases", c.aliases},
            {"settings", toJson(c.settings)},
            {"baseline", c.baseline},
            {"pareto", s.pareto},
            {"views", s.views},
            {"gpu_ms", jnum(s.gpuMs)},
            {"gpu_ms_min", jnum(s.gpuMsMin)},
            {"gpu_ms_max", jnum(s.gpuMsMax)},
            {"pass_ms", passJson(s.passMs)},
            {"rmse", jnum(s.rmse)},
            {"mae", jnum(s.mae)},
            {"bias", jnum(s.bias)},
            {"psnr_geometry_srgb", jnum(s.psnrGeometrySrgb)},
            {"psnr_full_srgb", jnum(s.psnrFullSrgb)},
            {"rmse_edge", jnum(s.rmseEdge)},
            {"rmse_interior", jnum(s.rmseInterior)},
            {"ssim", jnum(s.ssim)},
            {"rmse_first_frame", jnum(s.rmseFirstFrame)},
            {"nonfinite", s.nonFinite},
            {"time_ratio", jnum(s.timeRatio)},
            {"rmse_ratio", jnum(s.rmseRatio)}};
}

nlohmann::json viewJson(const ViewResult& v, const std::string& label) {
    nlohmann::json j = viewFields(v, label);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const SplitSummary none{nan, nan, nan, nan};
    splitJson(j, v.hasSplit ? SplitSummary{v.vsOracle.rmse, v.vsOracle.bias, v.vsOracle.rmseEdge, v.vsOracle.rmseInterior} : none,
              v.hasSplit ? SplitSummary{v.screen.rmse, v.screen.bias, v.screen.rmseEdge, v.screen.rmseInterior} : none);
    sharesFields(j, v.error.rmse, v.hasSplit ? v.vsOracle.rmse : nan, v.hasSplit ? v.screen.rmse : nan);
    motionJson(j, v.hasMotion ? v.motion : MotionSummary{}, true);
    j["error_by_place"] = v.hasPlaces ? placeSumsJson(v.places) : nlohmann::json();
    return j;
}

nlohmann::json viewFields(const ViewResult& v, const std::string& label) {
    return {{"scene", v.scene},
            {"viewpoint", v.viewpoint},
            {"config", v.config},
            {"label", label},
            {"shard", v.shard},
            {"gpu_ms", jnum(v.gpuMs)},
            {"gpu_ms_min", jnum(v.gpuMsMin)},
            {"gpu_ms_max", jnum(v.gpuMsMax)},
            {"pass_ms", passJson(v.passMs)},
            {"baseline_ms", jnum(v.baselineMs)},
            {"time_ratio", jnum(v.timeRatio)},
            {"rmse", jnum(v.error.rmse)},
            {"mae", jnum(v.error.mae)},
            {"bias", jnum(v.error.bias)},
            {"p99_abs", jnum(v.error.p99Abs)},
            {"max_abs", jnum(v.error.maxAbs)},
            {"psnr_geometry_srgb", jnum(v.error.psnrGeometrySrgb)},
            {"psnr_full_srgb", jnum(v.error.psnrFullSrgb)},
            {"rmse_edge", jnum(v.error.rmseEdge)},
            {"rmse_interior", jnum(v.error.rmseInterior)},
            {"ssim", jnum(v.error.ssim)},
            {"frames", v.frames},
            {"rmse_first_frame", jnum(v.rmseFirstFrame)},
            {"nonfinite", v.error.nonFinite},
            {"pixels", v.error.pixels},
            {"geometry_pixels", v.error.geometryPixels},
            {"edge_pixels", v.error.edgePixels},
            {"interior_pixels", v.error.interiorPixels},
            {"excluded_pixels", v.error.excludedPixels},
            {"reference_noise", jnum(v.error.referenceNoise)}};
}

// Field readers that name the file and the field (nlohmann's own errors name neither).
class Reader {
  public:
    explicit Reader(std::string origin) : origin_(std::move(origin)) {}
    const nlohmann::json& at(const nlohmann::json& j, const char* key, const std::string& where) const {
        if (!j.is_object() || !j.contains(key)) fail(where + ": missing '" + key + "'");
        return j[key];
    }
    double number(const nlohmann::json& j, const char* key, const std::string& where) const {
        const auto& v = at(j, key, where);
        if (v.is_null()) return std::numeric_limits<double>::quiet_NaN(); // written for NaN
        if (!v.is_number()) fail(where + ": '" + key + "' is not a number");
        return v.get<double>();
    }
    long integer(const nlohmann::json& j, const char* key, const std::string& where) const {
        const auto& v = at(j, key, where);
        if (!v.is_number_integer()) fail(where + ": '" + key + "' is not an integer");
        return v.get<long>();
    }
    std::string text(const nlohmann::json& j, const char* key, const std::string& where) const {
        const auto& v = at(j, key, where);
        if (!v.is_string()) fail(where + ": '" + key + "' is not a string");
        return v.get<std::string>();
    }
    [[noreturn]] void fail(const std::string& what) const { throw Error(origin_ + ": " + what); }

  private:
    std::string origin_;
};

BenchConfig readConfig(const Reader& rd, const nlohmann::json& j, const std::string& where) {
    BenchConfig c;
    c.label = rd.text(j, "label", where);
    c.group = rd.text(j, "group", where);
    c.keys = rd.at(j, "keys", where);
    if (j.contains("aliases")) { // the same configuration's other labels (absent before they were kept)
        const auto& a = j["aliases"];
        if (!a.is_array()) rd.fail(where + ": 'aliases' is not a list");
        for (size_t i = 0; i < a.size(); ++i)
            if (!a[i].is_string()) rd.fail(where + ": 'aliases' holds something other than a label");
            else c.aliases.push_back(a[i].get<std::string>());
    }
    const auto& b = rd.at(j, "baseline", where);
    if (!b.is_boolean()) rd.fail(where + ": 'baseline' is not true or false");
    c.baseline = b.get<bool>();
    c.settings = defaultSettings();
    if (j.contains("engine") && !j["engine"].is_null()) { // a web engine's row (results_check.h checks it)
        if (!j["engine"].is_object()) rd.fail(where + ": 'engine' is not an object");
        if (!rd.at(j, "settings", where).is_null()) rd.fail(where + ": an engine's row has ssaolab 'settings'");
        c.engine = j["engine"];
        return c;
    }
    try {
        applyJson(c.settings, rd.at(j, "settings", where), where + ".settings");
        validateSettings(c.settings);
    } catch (const Error& e) {
        rd.fail(e.what());
    }
    return c;
}

ViewResult readView(const Reader& rd, const nlohmann::json& j, const std::string& where, size_t configs,
                    size_t shards) {
    ViewResult v;
    v.scene = rd.text(j, "scene", where);
    v.viewpoint = rd.text(j, "viewpoint", where);
    const long config = rd.integer(j, "config", where), shard = rd.integer(j, "shard", where);
    if (config < 0 || size_t(config) >= configs) rd.fail(where + ": 'config' " + std::to_string(config) + " is not a configuration");
    if (shard < 0 || size_t(shard) >= std::max<size_t>(shards, 1)) rd.fail(where + ": 'shard' " + std::to_string(shard) + " is not a shard");
    v.config = size_t(config), v.shard = int(shard);
    v.gpuMs = rd.number(j, "gpu_ms", where);
    v.gpuMsMin = rd.number(j, "gpu_ms_min", where);
    v.gpuMsMax = rd.number(j, "gpu_ms_max", where);
    v.baselineMs = rd.number(j, "baseline_ms", where);
    if (j.contains("pass_ms")) { // runs before the per-pass breakdown have none
        const nlohmann::json& t = j["pass_ms"];
        for (int k = 0; k < PassTimes::kParts; ++k)
            v.passMs.ms[k] = rd.number(t, PassTimes::kNames[k], where + ".pass_ms");
    }
    ErrorMetrics& e = v.error;
    e.rmse = rd.number(j, "rmse", where);
    e.mae = rd.number(j, "mae", where);
    e.bias = rd.number(j, "bias", where);
    e.p99Abs = rd.number(j, "p99_abs", where);
    e.maxAbs = rd.number(j, "max_abs", where);
    e.psnrGeometrySrgb = rd.number(j, "psnr_geometry_srgb", where);
    e.psnrFullSrgb = rd.number(j, "psnr_full_srgb", where);
    e.rmseEdge = rd.number(j, "rmse_edge", where);
    e.rmseInterior = rd.number(j, "rmse_interior", where);
    e.ssim = rd.number(j, "ssim", where);
    e.referenceNoise = rd.number(j, "reference_noise", where);
    e.nonFinite = rd.integer(j, "nonfinite", where);
    e.pixels = rd.integer(j, "pixels", where);
    e.geometryPixels = rd.integer(j, "geometry_pixels", where);
    e.edgePixels = rd.integer(j, "edge_pixels", where);
    e.interiorPixels = rd.integer(j, "interior_pixels", where);
    e.excludedPixels = rd.integer(j, "excluded_pixels", where);
    v.frames = int(rd.integer(j, "frames", where));
    v.rmseFirstFrame = rd.number(j, "rmse_first_frame", where);
    // The split, when the run traced the oracle (its RMSE is null without one).
    if (j.contains("rmse_vs_oracle") && !j["rmse_vs_oracle"].is_null()) {
        v.hasSplit = true;
        v.vsOracle.rmse = rd.number(j, "rmse_vs_oracle", where);
        v.vsOracle.bias = rd.number(j, "bias_vs_oracle", where);
        v.vsOracle.rmseEdge = rd.number(j, "rmse_edge_vs_oracle", where);
        v.vsOracle.rmseInterior = rd.number(j, "rmse_interior_vs_oracle", where);
        v.screen.rmse = rd.number(j, "rmse_screen", where);
        v.screen.bias = rd.number(j, "bias_screen", where);
        v.screen.rmseEdge = rd.number(j, "rmse_edge_screen", where);
        v.screen.rmseInterior = rd.number(j, "rmse_interior_screen", where);
    }
    // The error by place, when the run kept it (null for engine rows; absent in older runs).
    if (j.contains("error_by_place") && !j["error_by_place"].is_null()) {
        try {
            v.places = placeSumsFromJson(j["error_by_place"]);
        } catch (const std::invalid_argument& e) {
            rd.fail(where + ".error_by_place: " + e.what());
        }
        v.hasPlaces = true;
    }
    // Error in motion, when the run scored it (bench --motion; null without).
    if (j.contains("motion_rmse_mean") && !j["motion_rmse_mean"].is_null()) {
        v.hasMotion = true;
        v.motion.rmseMean = rd.number(j, "motion_rmse_mean", where);
        v.motion.rmseMax = rd.number(j, "motion_rmse_max", where);
        v.motion.instability = rd.number(j, "motion_instability", where);
        v.motion.ghosting = rd.number(j, "motion_ghosting", where);
    }
    return v;
}

} // namespace

Objective runObjective(const BenchRun& run) {
    return run.facts.is_object() && run.facts.value("objective", "") == "motion" ? Objective::Motion : Objective::Still;
}

nlohmann::json resultsJson(const BenchRun& run) {
    nlohmann::json j = run.facts;
    j["sweep"] = {{"name", run.sweep.name}, {"description", run.sweep.description}};
    j["shards"] = run.shards;
    j["configurations"] = nlohmann::json::array();
    for (const auto& s : run.summary)
        j["configurations"].push_back(configJson(run.sweep.configs[s.config], s));
    j["results"] = nlohmann::json::array();
    for (const auto& v : run.views)
        j["results"].push_back(viewJson(v, run.sweep.configs[v.config].label));
    return j;
}

BenchRun readResults(const std::string& dir) {
    // A shard folder is foreign: results.json is read inside it, never through a link out of it.
    const std::string path = (std::filesystem::path(dir) / "results.json").string();
    return parseResultsText(readFileInside(dir, "results.json", "bench results"), path);
}

BenchRun parseResults(const nlohmann::json& j, const std::string& path) {
    const Reader rd(path);
    if (!j.is_object()) rd.fail("the top level is not an object");
    BenchRun run;
    run.facts = j;
    for (const char* k : {"sweep", "shards", "configurations", "results"})
        run.facts.erase(k);
    const auto& sweep = rd.at(j, "sweep", "top level");
    run.sweep.name = rd.text(sweep, "name", "sweep");
    run.sweep.description = rd.text(sweep, "description", "sweep");
    const auto& configs = rd.at(j, "configurations", "top level");
    if (!configs.is_array() || configs.empty()) rd.fail("'configurations' is not a non-empty list");
    for (size_t i = 0; i < configs.size(); ++i) {
        run.sweep.configs.push_back(readConfig(rd, configs[i], "configurations[" + std::to_string(i) + "]"));
        if (run.sweep.configs.back().baseline) run.sweep.baseline = i;
    }
    if (!run.sweep.configs[run.sweep.baseline].baseline) rd.fail("no configuration is the baseline");
    run.shards = rd.at(j, "shards", "top level");
    if (!run.shards.is_array()) rd.fail("'shards' is not a list");
    const auto& rows = rd.at(j, "results", "top level");
    if (!rows.is_array()) rd.fail("'results' is not a list");
    for (size_t i = 0; i < rows.size(); ++i)
        run.views.push_back(readView(rd, rows[i], "results[" + std::to_string(i) + "]", run.sweep.configs.size(),
                                     run.shards.size()));
    return run;
}

} // namespace ssao
