// Whole program: bench, tune, skips and stress on small scenes.
#include "cli_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/wait.h>

#include <regex>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

using namespace ssaotest;

TEST(Cli, BenchWritesResultsTheFrontAndRatiosToTheBaseline) {
    const std::string out = outDir("bench");
    std::filesystem::remove_all(out);
    const std::string sweep = writeTemp("small_sweep.json", R"({
      "name": "small", "base": {"set": {"kernel.noise": "tex4x4"}},
      "groups": [{"name": "samples", "vary": {"kernel.samples": [4, 32]}},
                 {"name": "blur", "set": {"kernel.samples": 8}, "vary": {"denoise.kind": ["none", "gaussian"]}},
                 {"name": "temporal", "set": {"ao.technique": "gtao", "temporal.enabled": true, "temporal.frames": 4}}]})");
    CliRun r = ssaolab(
        "bench --scene " + std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf --sweep " + sweep +
        " --size 160x90 --views 2 --frames 2 --warmup 0 --reference-rays 16 --quiet --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* f :
         {"results.csv", "summary.csv", "results.json", "report.md", "pareto.png", "pareto.svg"})
        EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
    auto j = nlohmann::json::parse(slurp(out + "/results.json"));
    // baseline + 2 + 2 (+ every technique at its defaults, 64 samples: not a duplicate here).
    const auto& cfgs = j["configurations"];
    ASSERT_GE(cfgs.size(), 5u);
    EXPECT_EQ(cfgs[0]["label"], "learnopengl (baseline)");
    EXPECT_EQ(cfgs[0]["time_ratio"], 1.0);
    EXPECT_EQ(cfgs[0]["rmse_ratio"], 1.0);
    EXPECT_EQ(j["results"].size(), cfgs.size() * 2); // two views each
    for (const auto& v : j["results"]) {
        // Temporal accumulation blends its frames before it is judged; everything else is one frame.
        const bool temporal = v["label"].get<std::string>().find("temporal") != std::string::npos;
        EXPECT_EQ(v["frames"], temporal ? 4 : 1) << v["label"];
        if (!temporal) {
            EXPECT_EQ(v["rmse_first_frame"], v["rmse"]) << v["label"];
        }
    }
    int front = 0;
    for (const auto& c : cfgs) {
        EXPECT_GT(c["gpu_ms"].get<double>(), 0.0) << c["label"];
        EXPECT_LE(c["gpu_ms_min"].get<double>(), c["gpu_ms"].get<double>());
        EXPECT_GE(c["gpu_ms_max"].get<double>(), c["gpu_ms"].get<double>());
        EXPECT_GT(c["rmse"].get<double>(), 0.0);
        EXPECT_LT(c["rmse"].get<double>(), 0.6);
        EXPECT_EQ(c["nonfinite"], 0);
        front += c["pareto"].get<bool>();
    }
    EXPECT_GE(front, 1);
    // The front is consistent: no configuration is both faster and more accurate than a front member.
    for (const auto& a : cfgs) {
        if (!a["pareto"].get<bool>()) continue;
        for (const auto& b : cfgs) {
            EXPECT_FALSE(b["gpu_ms"].get<double>() < a["gpu_ms"].get<double>() &&
                         b["rmse"].get<double>() < a["rmse"].get<double>())
                << a["label"] << " is dominated by " << b["label"];
        }
    }
    for (const char* k : {"cpu", "gl_renderer", "build_type", "date", "git_revision"})
        EXPECT_TRUE(j.contains(k)) << k;
    const std::string md = slurp(out + "/report.md");
    EXPECT_NE(md.find("Pareto front"), std::string::npos);
    EXPECT_NE(md.find("learnopengl (baseline)"), std::string::npos);
    EXPECT_NE(slurp(out + "/results.csv").find("scene,viewpoint,label"), std::string::npos);
    // Bad sweeps: one clear line each.
    expectCleanFailure(ssaolab("bench --sweep " +
                               writeTemp("bad1.json", "{\"groups\": [{\"vary\": {\"kernel.nope\": [1]}}]}")),
                       "kernel.nope");
    expectCleanFailure(
        ssaolab("bench --sweep " + writeTemp("bad2.json", "{\"groups\": [{\"set\": {\"ao.radius\": 2}}]}")),
        "radius");
    expectCleanFailure(ssaolab("bench --sweep " + writeTemp("bad3.json", "{not json")), "not valid JSON");
    expectCleanFailure(ssaolab("bench --sweep /nonexistent.json"), "cannot open");
}

TEST(Cli, TuneFitsTheReferenceAndSavesAPresetThatRenders) {
    const std::string preset = std::string(SSAOLAB_TEST_TMP) + "/tuned.json";
    std::filesystem::remove(preset);
    CliRun r = ssaolab("tune --scene builtin:showcase --size 160x90 --views 2 --rounds 1 --grid 3 "
                       "--reference-rays 16 --out " +
                       preset);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("held-out"), std::string::npos) << r.out;
    // The search starts from the defaults and keeps the best, so training error never rises.
    double before = 0, after = 0;
    ASSERT_EQ(
        std::sscanf(r.out.substr(r.out.find("training")).c_str(), "training %lf -> %lf", &before, &after), 2)
        << r.out;
    EXPECT_LE(after, before);
    auto j = nlohmann::json::parse(slurp(preset));
    EXPECT_EQ(j["ao"]["radius_mode"], "scene");
    EXPECT_NE(j["description"].get<std::string>().find("held-out"), std::string::npos);
    CliRun again = ssaolab("render --preset " + preset + " --size 160x90 --timing-frames 1 --quiet --out " +
                           outDir("tuned"));
    EXPECT_EQ(again.exitCode, 0) << again.err;
    expectCleanFailure(ssaolab("tune --technique nope"), "nope");
}

TEST(Cli, SkipsMeasuresEverySkipAgainstTheSameFrameWithoutIt) {
    // `ssaolab skips` at a small size: a row per skip and dependency, exact skips change nothing,
    // the dirty rows re-run only the passes downstream of the change, and skips.md is written.
    const std::string out = outDir("skips");
    CliRun r = ssaolab("skips --quiet --size 96x54 --frames 1 --reference-rays 16 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(slurp(out + "/skips.json"), nullptr, false);
    ASSERT_FALSE(j.is_discarded());
    std::map<std::string, int> count;
    for (const auto& row : j["rows"]) {
        const std::string skip = row["skip"];
        ++count[skip];
        EXPECT_GT(row["without_ms"].get<double>(), 0.0) << row.dump();
        if (skip != "adaptive") {
            EXPECT_EQ(row["error_change"].get<double>(), 0.0) << row.dump();
        }
        if (skip == "dirty") {
            const auto ran = row["extra"]["passes_run"];
            const std::string v = row["variant"];
            if (v.rfind("camera", 0) == 0) {
                EXPECT_EQ(ran.size(), 4u);
            }
            if (v.rfind("AO setting", 0) == 0) {
                EXPECT_EQ(ran, nlohmann::json({"ao", "denoise", "composite"}));
            }
            if (v.rfind("denoise", 0) == 0) {
                EXPECT_EQ(ran, nlohmann::json({"denoise", "composite"}));
            }
            if (v.rfind("composite", 0) == 0) {
                EXPECT_EQ(ran, nlohmann::json({"composite"}));
            }
            if (v.rfind("view switch", 0) == 0) {
                EXPECT_TRUE(ran.empty());
                EXPECT_EQ(row["with_ms"].get<double>(), 0.0); // idle: no GPU work at all
            }
        }
    }
    EXPECT_EQ(count["dirty"], 5);
    EXPECT_EQ(count["sky"], 5);
    EXPECT_EQ(count["adaptive"], 24); // 4 techniques x 3 views x 2 px/sample
    EXPECT_EQ(count["cull"], 2);
    EXPECT_EQ(count["targets"], 6);
    EXPECT_NE(slurp(out + "/skips.md").find("#### Frustum culling"), std::string::npos);
}

TEST(CliStress, EveryTechniqueStaysFiniteInRangeAndInvariantUnderScaleAndTranslation) {
    // `ssaolab stress` at a small size: no NaN/inf or out-of-range value in any case, scale and
    // translation (to 1e7 units, positions relative to the scene's double-precision origin) within
    // RMSE 0.02 of the benign render, and the depth-range guard
    // refuses far/near 1e9 in a standard depth buffer with its one-line message.
    const std::string out = outDir("stress");
    CliRun r = ssaolab("stress --quiet --size 128x72 --tolerance 0.02 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    std::ifstream in(out + "/stress.json");
    const auto j = nlohmann::json::parse(in, nullptr, false);
    ASSERT_FALSE(j.is_discarded());
    std::set<std::string> techs;
    int refusedDepth = 0, invariant = 0;
    for (const auto& row : j["rows"]) {
        techs.insert(row["technique"].get<std::string>());
        EXPECT_EQ(row["nonfinite"].get<long>(), 0) << row.dump();
        EXPECT_EQ(row["outside"].get<long>(), 0) << row.dump();
        if (row["status"] == "refused" && row["message"].get<std::string>().find("far/near") != std::string::npos)
            ++refusedDepth;
        if (row["invariant"].get<bool>() && row["status"] == "ok") {
            ++invariant;
            EXPECT_LE(row["rmse"].get<double>(), 0.02) << row.dump();
        }
    }
    EXPECT_EQ(techs.size(), 5u);
    EXPECT_GE(refusedDepth, 5);   // far 1e5 x diag and the 1e9 pair, for every technique
    // 6 scales + 5 translations + 12 reversed-depth planes enclosing the scene + the infinite far
    // plane + degenerate triangles + normals scaled by 1e-6 and 1e6, per technique: reversed-Z
    // float depth draws what the fitted planes draw at every ratio up to 1e11.
    EXPECT_EQ(invariant, 5 * 27);
    std::ifstream md(out + "/stability.md");
    EXPECT_TRUE(md.good());
}
