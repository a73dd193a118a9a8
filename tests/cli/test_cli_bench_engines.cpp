// `bench --engines`: the web engines as rows of a sweep, run for real in Chromium on each view at the
// bench's camera, size and R and scored in-process against the same reference: their rows in
// results.json, the CSV, report.md and report.html (with thumbnails), the same error the runner
// gives for that view, the same rows from shards merged, and one-line refusals before any work.
#include "engines/engine_runner.h"
#include "engines/engine_table.h"
#include "measure/viewpoints.h"
#include "cli_run.h"
#include "engine_test_util.h"
#include "cli/headless_runner.h"
#include "metrics/evaluate.h"
#include "reference/reference_cache.h"
#include "scene/view_fit.h"
#include "settings/preset.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>

using namespace ssaotest;
namespace fs = std::filesystem;

namespace {

// The runner's error for the same view within the noise of timing frames before the read-back.
constexpr double kSameViewTolerance = 0.003;

const char* kSweep = R"({"name": "engines", "groups": [{"name": "k", "vary": {"kernel.samples": [8]}}]})";

std::string benchArgs(const std::string& scene, const std::string& sweep) {
    return "bench --scene " + scene + " --size 96x54 --views 2 --frames 2 --warmup 0 --reference-rays 8 --no-plot --quiet "
           "--sweep " + sweep + " --engine-modules " + kModules;
}

// A `tune --engine` result as it writes one: aoRadius at 2 x the view's R, intensity 2.
std::string writeTuned(const std::string& name) {
    const nlohmann::json j = {{"engine", "n8ao"}, {"version", "2.1.0"},
                              {"settings", {{"aoRadius", 0.3}, {"intensity", 2.0}}},
                              {"search", {{"aoRadius", {{"x_make_peers_value", 2.0}}}, {"intensity", {{"value", 2.0}}}}},
                              {"cost_settings", {{"values", {{"aoSamples", 16}}}}}};
    return writeTemp(name, j.dump());
}

// results.json's rows of one configuration, by viewpoint.
std::map<std::string, nlohmann::json> rowsOf(const nlohmann::json& run, const std::string& label) {
    std::map<std::string, nlohmann::json> out;
    for (const auto& r : run["results"])
        if (r["label"] == label) out[r["viewpoint"].get<std::string>()] = r;
    return out;
}

} // namespace

TEST(CliBenchEngines, AnEngineIsARowScoredAgainstTheSameReferenceInEveryReport) {
    NEED_MODULES();
    const std::string scene = writeCornerGltf("bench_engines.gltf"), out = outDir("bench_engines");
    fs::remove_all(out);
    const CliRun r = ssaolab(benchArgs(scene, writeTemp("bench_engines_sweep.json", kSweep)) + " --engines n8ao --engine-settings " +
                             writeTuned("bench_engines_tuned.json") + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    const nlohmann::json j = nlohmann::json::parse(slurp(out + "/results.json"));
    for (const std::string label : {"engine n8ao (defaults)", "engine n8ao (as shipped)", "engine n8ao (tuned)"}) {
        const auto rows = rowsOf(j, label);
        ASSERT_EQ(rows.size(), 2u) << label << ": one row per view";
        for (const auto& [vp, row] : rows) {
            EXPECT_TRUE(row["rmse"].is_number()) << label << " " << vp;
            EXPECT_GE(row["rmse"].get<double>(), 0.0);
            EXPECT_LE(row["rmse"].get<double>(), 1.0);
            EXPECT_GT(row["gpu_ms"].get<double>(), 0.0) << label << " " << vp;
            EXPECT_LE(row["gpu_ms_min"].get<double>(), row["gpu_ms"].get<double>());
            EXPECT_GE(row["gpu_ms_max"].get<double>(), row["gpu_ms"].get<double>());
            EXPECT_GT(row["time_ratio"].get<double>(), 0.0);
            EXPECT_TRUE(row["rmse_vs_oracle"].is_number()) << "the oracle split, as every row has it";
        }
    }
    bool found = false;
    for (const auto& c : j["configurations"])
        if (c["label"] == "engine n8ao (defaults)") {
            found = true;
            EXPECT_EQ(c["engine"]["name"], "n8ao");
            EXPECT_EQ(c["engine"]["version"], "2.1.0");
            EXPECT_TRUE(c["settings"].is_null());
            EXPECT_TRUE(c["rmse"].is_number());
        }
    EXPECT_TRUE(found);
    // The engine as its package ships it: the lengths the harness sets from R at the table's defaults.
    for (const auto& c : j["configurations"]) {
        if (c["label"] == "engine n8ao (as shipped)") {
            EXPECT_EQ(c["engine"]["values"]["aoRadius"], 5.0) << c.dump();
        }
    }
    EXPECT_NE(slurp(out + "/results.csv").find(",engine n8ao (defaults),n8ao,"), std::string::npos) << slurp(out + "/results.csv");
    EXPECT_NE(slurp(out + "/summary.csv").find("engine n8ao (tuned)"), std::string::npos);
    const std::string md = slurp(out + "/report.md");
    EXPECT_NE(md.find("| engine n8ao (defaults) |"), std::string::npos) << md;
    EXPECT_NE(md.find("### Web engines"), std::string::npos);
    const std::string html = slurp(out + "/report.html");
    EXPECT_NE(html.find("engine n8ao (defaults) AO\""), std::string::npos) << "its AO thumbnail";
    EXPECT_NE(html.find("engine n8ao (tuned) error\""), std::string::npos) << "its error thumbnail";
    EXPECT_EQ(html.find("not measured by these runs"), std::string::npos);

    // The same view through the runner alone: the same error.
    const ssao::Scene sc = ssao::loadNamedScene(scene);
    const auto vps = ssao::viewpoints(ssao::defaultCamera(sc), 2);
    const ssao::Camera cam = ssao::effectiveCamera(vps[0].second, sc.bounds);
    const float radius = 0.05f * 2.0f * sc.bounds.radius();
    const ssao::EngineTable t = ssao::findEngine("n8ao");
    ssao::EngineRunner runner(ssao::locateEngineTools(kModules, t), t, scene, 96, 54,
                              {{ssao::cameraToJson(ssao::cameraToFile(cam, sc)), radius}});
    const auto res = runner.run({{0, {}, 0}, {0, {{"aoRadius", 2.0 * radius}, {"intensity", 2.0}}, 0}});
    ssao::ReferenceProvider provider(sc, std::string(SSAOLAB_TEST_TMP) + "/cache");
    const ssao::ReferenceImage ref = provider.get(cam, 96, 54, {radius, 8});
    EXPECT_NEAR(rowsOf(j, "engine n8ao (defaults)")[vps[0].first]["rmse"].get<double>(),
                ssao::evaluate(res[0].ao, ref).metrics.rmse, kSameViewTolerance);
    EXPECT_NEAR(rowsOf(j, "engine n8ao (tuned)")[vps[0].first]["rmse"].get<double>(),
                ssao::evaluate(res[1].ao, ref).metrics.rmse, kSameViewTolerance);
}

TEST(CliBenchEngines, ShardsMergedGiveTheUnshardedRowsAndALyingRowIsRefused) {
    NEED_MODULES();
    const std::string scene = writeCornerGltf("bench_engines_shard.gltf");
    const std::string sweep = writeTemp("bench_engines_shard_sweep.json", kSweep);
    const std::string whole = outDir("bench_engines_whole"), s1 = outDir("bench_engines_s1"), s2 = outDir("bench_engines_s2");
    const std::string merged = outDir("bench_engines_merged");
    for (const auto& d : {whole, s1, s2, merged})
        fs::remove_all(d);
    const std::string args = benchArgs(scene, sweep) + " --engines n8ao";
    ASSERT_EQ(ssaolab(args + " --out " + whole).exitCode, 0);
    ASSERT_EQ(ssaolab(args + " --shard 1/2 --out " + s1).exitCode, 0);
    ASSERT_EQ(ssaolab(args + " --shard 2/2 --out " + s2).exitCode, 0);
    const CliRun m = ssaolab("bench merge " + s1 + " " + s2 + " --no-plot --quiet --out " + merged);
    ASSERT_EQ(m.exitCode, 0) << m.err;
    const auto a = nlohmann::json::parse(slurp(whole + "/results.json"));
    const auto b = nlohmann::json::parse(slurp(merged + "/results.json"));
    const auto p1 = nlohmann::json::parse(slurp(s1 + "/results.json")), p2 = nlohmann::json::parse(slurp(s2 + "/results.json"));
    // Each engine row in exactly one shard: the one that owns its (scene, view) unit.
    EXPECT_EQ(rowsOf(p1, "engine n8ao (defaults)").size() + rowsOf(p2, "engine n8ao (defaults)").size(), 2u);
    const auto ra = rowsOf(a, "engine n8ao (defaults)"), rb = rowsOf(b, "engine n8ao (defaults)");
    ASSERT_EQ(ra.size(), 2u);
    ASSERT_EQ(rb.size(), 2u);
    for (const auto& [vp, row] : ra)
        for (const char* f : {"rmse", "bias", "mae", "ssim", "rmse_edge", "rmse_vs_oracle"})
            EXPECT_EQ(rb.at(vp)[f], row[f]) << vp << " " << f;
    std::vector<std::string> oa, ob; // the same rows in the same order
    for (const auto& x : a["results"])
        oa.push_back(x["viewpoint"].get<std::string>() + "|" + x["label"].get<std::string>());
    for (const auto& x : b["results"])
        ob.push_back(x["viewpoint"].get<std::string>() + "|" + x["label"].get<std::string>());
    EXPECT_EQ(oa, ob);
    EXPECT_NE(slurp(merged + "/report.html").find("engine n8ao (defaults) AO\""), std::string::npos);

    // A shard whose engine row lies is refused by the merge, naming the field.
    auto lie = [&](const std::string& tag, const std::function<void(nlohmann::json&)>& edit, const std::string& needle) {
        const std::string d = outDir("bench_engines_lie_" + tag);
        fs::remove_all(d);
        fs::copy(s2, d, fs::copy_options::recursive);
        nlohmann::json j = nlohmann::json::parse(slurp(d + "/results.json"));
        for (auto& c : j["configurations"])
            if (c.contains("engine") && c["engine"].is_object()) edit(c);
        std::ofstream(d + "/results.json") << j.dump();
        expectCleanFailure(ssaolab("bench merge " + s1 + " " + d + " --no-plot --quiet --out " + d + "_m"), needle);
    };
    lie("name", [](nlohmann::json& c) { c["engine"]["name"] = "../n8ao"; }, "engine.name is not an engine's name");
    lie("value", [](nlohmann::json& c) { c["engine"]["values"]["aoRadius"] = "big"; }, "engine.values holds an entry");
    lie("settings", [](nlohmann::json& c) { c["settings"] = nlohmann::json::object(); }, "an engine's row has ssaolab 'settings'");
    lie("baseline", [](nlohmann::json& c) { c["baseline"] = true; }, "is an engine's row and the baseline");
}

TEST(CliBenchEngines, BuiltinScenesAndMissingToolsAreRefusedInOneLineBeforeAnyWork) {
    const std::string scene = writeCornerGltf("bench_engines_refusal.gltf"), out = outDir("bench_engines_refusal");
    fs::remove_all(out);
    const std::string small = " --size 64x36 --views 1 --frames 1 --reference-rays 4 --no-plot --out " + out;
    expectCleanFailure(ssaolab("bench --scene builtin:corner --engines n8ao" + small),
                       "--engines runs web engines on glTF files (three.js loads the scene): builtin:corner is built into ssaolab");
    expectCleanFailure(ssaolab("bench --engines all" + small), "builtin:showcase is built into ssaolab (the default scene)");
    expectCleanFailure(ssaolab("bench --scene " + scene + " --engines n8a0" + small), "did you mean n8ao");
    expectCleanFailure(ssaolab("bench --scene " + scene + " --engines n8ao" + small, "PATH=/nonexistent"),
                       "bench --engines n8ao runs N8AO (N8AOPass) in Chromium: node (Node.js) is not on PATH");
    if (nodeRuns())
        expectCleanFailure(ssaolab("bench --scene " + scene + " --engines n8ao --engine-modules /nonexistent" + small),
                           "the npm package n8ao is not installed in /nonexistent");
    const std::string bad = writeTemp("bench_engines_bad_tuned.json", R"({"engine": "n8ao", "version": "1.0.0", "settings": {}})");
    expectCleanFailure(ssaolab("bench --scene " + scene + " --engine-settings " + bad + small), "tuned n8ao 1.0.0");
    EXPECT_FALSE(fs::exists(out)) << "refused before any work";
}
