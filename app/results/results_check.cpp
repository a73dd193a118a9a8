#include "results/results_check.h"

#include "results/shard.h"
#include "cli/scene_options.h"
#include "util/number_text.h"
#include "util/error.h"
#include "util/json_file.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <tuple>

namespace ssao {

namespace {

// Field checks that name the file and the field.
struct Facts {
    std::string origin;
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw Error(origin + ": " + where + " " + what);
    }
    const nlohmann::json& at(const nlohmann::json& j, const char* key, const std::string& where) const {
        if (!j.is_object() || !j.contains(key)) fail(where, std::string("has no '") + key + "'");
        return j[key];
    }
    std::string text(const nlohmann::json& j, const char* key, const std::string& where) const {
        const auto& v = at(j, key, where);
        if (!v.is_string()) fail(where + "." + key, "is not a string");
        if (v.get_ref<const std::string&>().size() > kMaxResultText)
            fail(where + "." + key, "is longer than " + std::to_string(kMaxResultText) + " bytes");
        return v.get<std::string>();
    }
    long integer(const nlohmann::json& j, const char* key, const std::string& where, long lo, long hi) const {
        const auto& v = at(j, key, where);
        if (!v.is_number_integer()) fail(where + "." + key, "is not an integer");
        const long n = v.get<long>();
        if (n < lo || n > hi) fail(where + "." + key, std::to_string(n) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return n;
    }
    const nlohmann::json& list(const nlohmann::json& j, const char* key, const std::string& where, size_t most) const {
        const auto& v = at(j, key, where);
        if (!v.is_array()) fail(where + "." + key, "is not a list");
        if (v.size() > most) fail(where + "." + key, "holds more than " + std::to_string(most) + " entries");
        return v;
    }
    void optionalText(const nlohmann::json& j, const char* key, const std::string& where) const {
        if (j.is_object() && j.contains(key)) text(j, key, where);
    }
};

std::string num(double v) {
    return numberText(v, "%g", Missing::Spelled); // a message names the value it refuses
}

// A measured value: finite and within [lo, hi], or (when `missingOk`) NaN, written as null.
void range(const Facts& f, double v, const std::string& where, double lo, double hi, bool missingOk = false) {
    if (std::isnan(v) && missingOk) return;
    if (!std::isfinite(v)) f.fail(where, "is not a finite number");
    if (v < lo || v > hi) f.fail(where, num(v) + " is outside [" + num(lo) + ", " + num(hi) + "]");
}

void checkMetrics(const Facts& f, const ErrorMetrics& e, const std::string& w, bool full) {
    range(f, e.rmse, w + ".rmse", 0, 1); // AO and its reference lie in [0, 1]
    range(f, e.bias, w + ".bias", -1, 1);
    range(f, e.rmseEdge, w + ".rmse_edge", 0, 1, true);
    range(f, e.rmseInterior, w + ".rmse_interior", 0, 1, true);
    if (!full) return;
    range(f, e.mae, w + ".mae", 0, 1);
    range(f, e.p99Abs, w + ".p99_abs", 0, 1, true);
    range(f, e.maxAbs, w + ".max_abs", 0, 1, true);
    range(f, e.psnrGeometrySrgb, w + ".psnr_geometry_srgb", 0, 1000, true);
    range(f, e.psnrFullSrgb, w + ".psnr_full_srgb", 0, 1000, true);
    range(f, e.ssim, w + ".ssim", -1, 1, true);
    range(f, e.referenceNoise, w + ".reference_noise", 0, 1, true);
    if (e.pixels < 0 || e.geometryPixels < 0 || e.geometryPixels > e.pixels || e.nonFinite < 0 ||
        e.nonFinite > e.pixels || e.edgePixels < 0 || e.interiorPixels < 0 || e.excludedPixels < 0)
        f.fail(w, "has pixel counts no image holds");
}

void checkRow(const Facts& f, const ViewResult& v, const std::string& w) {
    range(f, v.gpuMs, w + ".gpu_ms", 0, 1e7);
    range(f, v.gpuMsMin, w + ".gpu_ms_min", 0, v.gpuMs);
    range(f, v.gpuMsMax, w + ".gpu_ms_max", v.gpuMs, 1e7);
    range(f, v.baselineMs, w + ".baseline_ms", 1e-9, 1e7, true);
    for (int k = 0; k < PassTimes::kParts; ++k)
        range(f, v.passMs.ms[k], w + ".pass_ms." + PassTimes::kNames[k], 0, 1e7, true);
    checkMetrics(f, v.error, w, true);
    range(f, v.rmseFirstFrame, w + ".rmse_first_frame", 0, 1, true);
    if (v.frames < 1) f.fail(w + ".frames", "is below 1");
    if (v.hasSplit) {
        checkMetrics(f, v.vsOracle, w + " (vs oracle)", false);
        checkMetrics(f, v.screen, w + " (screen)", false);
    }
    if (v.hasMotion) { // AO in [0, 1]: a change minus a change lies in [-2, 2]
        range(f, v.motion.rmseMean, w + ".motion_rmse_mean", 0, 1);
        range(f, v.motion.rmseMax, w + ".motion_rmse_max", 0, 1);
        range(f, v.motion.instability, w + ".motion_instability", 0, 2, true);
        range(f, v.motion.ghosting, w + ".motion_ghosting", -1, 1, true);
    }
}

// A web engine's row (bench --engines): a name as the tables spell them, its package, and the
// values it was given, each a finite number or a boolean (scale: a positive factor).
void checkEngine(const Facts& f, const BenchConfig& c, const std::string& where) {
    constexpr size_t kMaxName = 64, kMaxValues = 64;
    if (c.baseline) f.fail(where, "is an engine's row and the baseline: the baseline is one of ssaolab's presets");
    const std::string name = f.text(c.engine, "name", where + ".engine");
    if (name.empty() || name.size() > kMaxName ||
        name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-") != std::string::npos)
        f.fail(where + ".engine.name", "is not an engine's name (lower-case letters, digits and '-')");
    for (const char* k : {"title", "package", "version"})
        f.text(c.engine, k, where + ".engine");
    for (const char* k : {"values", "scale"}) {
        const nlohmann::json& m = f.at(c.engine, k, where + ".engine");
        if (!m.is_object() || m.size() > kMaxValues)
            f.fail(where + ".engine." + k, "is not an object of at most " + std::to_string(kMaxValues) + " values");
        const bool values = std::string(k) == "values";
        for (const auto& [key, v] : m.items()) {
            const bool number = v.is_number() && std::isfinite(v.get<double>());
            const bool ok = values ? number || v.is_boolean() : number && v.get<double>() > 0;
            if (key.empty() || key.size() > kMaxName || !ok)
                f.fail(where + ".engine." + k, "holds an entry that is not a parameter's finite value");
        }
    }
    if (!c.engine.contains("per_radius")) return;
    const nlohmann::json& pr = c.engine["per_radius"];
    if (!pr.is_object() || pr.size() > kMaxValues) f.fail(where + ".engine.per_radius", "is not an object of at most 64 entries");
    for (const auto& [key, v] : pr.items()) {
        const bool ok = v.is_object() && v.contains("factor") && v["factor"].is_number() && std::isfinite(v["factor"].get<double>()) &&
                        v.contains("exponent") && v["exponent"].is_number_integer() && std::abs(v["exponent"].get<int>()) == 1;
        if (key.empty() || key.size() > kMaxName || !ok)
            f.fail(where + ".engine.per_radius", "holds an entry that is not a finite factor with exponent 1 or -1");
    }
}

// The facts a run writes beside its rows; returns each scene's viewpoint names.
std::vector<std::set<std::string>> checkFacts(const Facts& f, const nlohmann::json& j) {
    int w = 0, h = 0;
    try {
        parseSizeOption(f.text(j, "size", "facts"), w, h);
    } catch (const Error& e) {
        f.fail("facts.size", e.what());
    }
    f.integer(j, "frames", "facts", 1, 1000000);
    f.integer(j, "warmup", "facts", 0, 1000000);
    const long views = f.integer(j, "views_per_scene", "facts", 1, long(kMaxResultViewpoints));
    const auto& ref = f.at(j, "reference", "facts");
    f.text(ref, "definition", "facts.reference");
    if (j.contains("motion")) f.integer(f.at(j, "motion", "facts"), "frames", "facts.motion", 2, 64);
    if (j.contains("objective")) {
        const std::string o = f.text(j, "objective", "facts");
        if (o != "still" && o != "motion") f.fail("facts.objective", "is neither \"still\" nor \"motion\"");
        if (o == "motion" && !j.contains("motion")) f.fail("facts.objective", "is \"motion\" without facts.motion");
    }
    for (const char* k : {"cpu", "gl_renderer", "date", "git_revision", "build_type", "hostname"})
        f.optionalText(j, k, "facts");
    const auto& scenes = f.list(j, "scenes", "facts", kMaxResultScenes);
    const auto& specs = f.list(j, "scene_specs", "facts", kMaxResultScenes);
    if (specs.size() != scenes.size()) f.fail("facts.scene_specs", "does not list one spec per scene");
    std::vector<std::set<std::string>> names;
    std::set<std::string> sceneNames;
    for (size_t s = 0; s < scenes.size(); ++s) {
        const std::string where = "facts.scenes[" + std::to_string(s) + "]";
        if (!specs[s].is_string()) f.fail("facts.scene_specs[" + std::to_string(s) + "]", "is not a string");
        if (!sceneNames.insert(f.text(scenes[s], "name", where)).second) f.fail(where + ".name", "names a scene twice");
        f.text(scenes[s], "spec", where);
        std::set<long> indices;
        names.emplace_back();
        for (const auto& vp : f.list(scenes[s], "viewpoints", where, kMaxResultViewpoints)) {
            const long index = f.integer(vp, "index", where + ".viewpoints", 0, views - 1);
            const std::string name = f.text(vp, "name", where + ".viewpoints");
            if (!vp.contains("camera") || !vp["camera"].is_object())
                f.fail(where + ".viewpoints '" + name + "'", "has no camera");
            if (!indices.insert(index).second || !names.back().insert(name).second)
                f.fail(where + ".viewpoints '" + name + "'", "is listed twice");
        }
    }
    return names;
}

} // namespace

BenchRun parseResultsText(const std::string& text, const std::string& origin) {
    BenchRun run;
    try {
        run = parseResults(parseJsonText(text, origin), origin);
    } catch (const nlohmann::json::exception& e) { // a type the field readers did not foresee
        std::string msg = e.what();
        const size_t bracket = msg.find("] ");
        throw Error(origin + ": " + (bracket == std::string::npos ? msg : msg.substr(bracket + 2)));
    }
    checkResults(run, origin);
    return run;
}

void checkResults(const BenchRun& run, const std::string& origin) {
    const Facts f{origin};
    const std::vector<std::set<std::string>> viewpoints = checkFacts(f, run.facts);
    std::map<std::string, size_t> sceneIndex;
    for (size_t s = 0; s < run.facts["scenes"].size(); ++s)
        sceneIndex[run.facts["scenes"][s]["name"].get<std::string>()] = s;
    for (size_t k = 0; k < run.shards.size(); ++k) {
        const std::string where = "shards[" + std::to_string(k) + "]";
        try {
            parseShard(f.text(run.shards[k], "shard", where));
        } catch (const Error& e) {
            f.fail(where + ".shard", e.what());
        }
        for (const char* key : {"hostname", "cpu", "gl_renderer", "date", "git_revision"})
            f.optionalText(run.shards[k], key, where);
    }
    for (size_t c = 0; c < run.sweep.configs.size(); ++c) {
        const BenchConfig& cfg = run.sweep.configs[c];
        if (cfg.label.size() > kMaxResultText)
            f.fail("configurations[" + std::to_string(c) + "].label", "is longer than " + std::to_string(kMaxResultText) + " bytes");
        if (cfg.aliases.size() > kMaxAliases)
            f.fail("configurations[" + std::to_string(c) + "].aliases", "holds more than " + std::to_string(kMaxAliases) + " labels");
        for (const std::string& a : cfg.aliases)
            if (a.size() > kMaxResultText)
                f.fail("configurations[" + std::to_string(c) + "].aliases", "holds a label longer than " +
                       std::to_string(kMaxResultText) + " bytes");
        if (cfg.isEngine()) checkEngine(f, cfg, "configurations[" + std::to_string(c) + "]");
    }
    if (run.views.size() > kMaxResultRows) f.fail("results", "holds more than " + std::to_string(kMaxResultRows) + " rows");
    std::set<std::tuple<std::string, std::string, size_t>> seen;
    for (size_t i = 0; i < run.views.size(); ++i) {
        const ViewResult& v = run.views[i];
        const std::string where = "results[" + std::to_string(i) + "]";
        const auto s = sceneIndex.find(v.scene);
        if (s == sceneIndex.end()) f.fail(where + ".scene", "names a scene the run did not measure");
        if (!viewpoints[s->second].count(v.viewpoint))
            f.fail(where + ".viewpoint", "names a viewpoint the run did not measure of its scene");
        if (!seen.emplace(v.scene, v.viewpoint, v.config).second)
            f.fail(where, "measures a scene, viewpoint and configuration that an earlier row measured");
        checkRow(f, v, where);
    }
}

} // namespace ssao
