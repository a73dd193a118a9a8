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
         {"results.csv", "summary.csv", "results.json", "report.md", "report.html", "pareto.png", "pareto.svg"})
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
    // The front is consistent: no configuration is both faster (against the baseline on the same
    // views) and more accurate than a front member.
    for (const auto& a : cfgs) {
        if (!a["pareto"].get<bool>()) continue;
        for (const auto& b : cfgs) {
            EXPECT_FALSE(b["time_ratio"].get<double>() < a["time_ratio"].get<double>() &&
                         b["rmse"].get<double>() < a["rmse"].get<double>())
                << a["label"] << " is dominated by " << b["label"];
        }
    }
    // Labels name each key with its group ("kernel.samples=4", not "samples=4").
    std::set<std::string> labels;
    for (const auto& c : cfgs)
        labels.insert(c["label"].get<std::string>());
    EXPECT_TRUE(labels.count("kernel.noise=tex4x4 kernel.samples=4")) << *labels.begin();
    EXPECT_TRUE(labels.count("denoise.kind=gaussian kernel.noise=tex4x4 kernel.samples=8"));
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
    expectCleanFailure(ssaolab("bench --sweep /nonexistent.json"), "sweep /nonexistent.json: no such file");
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
        std::sscanf(r.out.substr(r.out.find("training ")).c_str(), "training %lf -> %lf", &before, &after), 2)
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

// A tuned preset reproduces tune's number with `render --preset` alone: it carries the scene, the
// size, the first training view's camera and the R it was judged against; by default only the
// technique's own rows are fitted (no power, no radius multiplier, no stray ao.radius), and a
// held-out scene is scored, never fitted on.
TEST(CliTune, APresetReproducesTunesNumbersWithRenderAloneAndHeldOutScenesAreScored) {
    const std::string dir = outDir("tune_repro");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    for (const bool multiplier : {false, true}) {
        const std::string preset = dir + (multiplier ? "/m.json" : "/t.json");
        CliRun r = ssaolab("tune --technique gtao --scene builtin:corner --held-out-scene builtin:showcase --size 160x90 "
                           "--views 2 --rounds 1 --reference-rays 16 --out " + preset + (multiplier ? " --grid 4" : " --grid 3") +
                           (multiplier ? " --knob radius_multiplier" : ""));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const size_t at = r.out.find("alone: RMSE ");
        ASSERT_NE(at, std::string::npos) << r.out;
        const double tuned = std::stod(r.out.substr(at + 12));
        EXPECT_NE(r.out.find("held-out scenes"), std::string::npos) << r.out;
        const auto j = nlohmann::json::parse(slurp(preset));
        EXPECT_EQ(j["scene"], "builtin:corner");
        EXPECT_EQ(j["size"], nlohmann::json::array({160, 90}));
        EXPECT_TRUE(j.contains("camera"));
        EXPECT_EQ(j["ao"]["power"].get<double>(), 1.0); // never fitted unless asked
        EXPECT_EQ(j["ao"]["radius"].get<double>(), 0.5); // the default, not 1 x the multiplier
        EXPECT_EQ(j["scores"]["training_scenes"], nlohmann::json::array({"builtin:corner"}));
        EXPECT_EQ(j["scores"]["held_out_scenes"], nlohmann::json::array({"builtin:showcase"}));
        EXPECT_EQ(j["scores"]["views"]["held_out_scenes"].get<int>(), 2);
        EXPECT_TRUE(j["scores"]["tuned"]["held_out_scenes"].is_number());
        if (multiplier) {
            // GTAO at its defaults wants a longer radius on the corner (grid 0.5, 1.33, 2.17, 3).
            ASSERT_GT(j["ao"]["radius_scene"].get<double>(), 0.06) << r.out;
            ASSERT_TRUE(j.contains("reference_radius_scene")) << r.out;
            EXPECT_DOUBLE_EQ(j["reference_radius_scene"].get<double>(), double(0.05f));
        } else {
            EXPECT_FALSE(j.contains("reference_radius_scene"));
            EXPECT_FALSE(r.out.find("R x") != std::string::npos);
        }
        const std::string out = dir + (multiplier ? "/render_m" : "/render_t");
        CliRun again = ssaolab("render --preset " + preset + " --reference --reference-rays 16 --quiet --out " + out);
        ASSERT_EQ(again.exitCode, 0) << again.err;
        const auto m = nlohmann::json::parse(slurp(out + "/metrics.json"));
        EXPECT_NEAR(m["error"]["rmse"].get<double>(), tuned, 5e-7) << (multiplier ? "multiplier" : "rows only");
        EXPECT_NEAR(m["error"]["reference"]["radius"].get<double>(), m["radius"]["world_at_centre"].get<double>() /
                    (multiplier ? j["ao"]["radius_scene"].get<double>() / 0.05 : 1.0), 1e-4);
    }
    expectCleanFailure(ssaolab("tune --scene builtin:corner --held-out-scene builtin:corner --out " + dir + "/x.json"),
                       "one or the other");
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
        if (skip == "deinterleave") { // not exact (taps on a 4-pixel grid): both errors measured
            EXPECT_GT(row["extra"]["rmse_with"].get<double>(), 0.0) << row.dump();
            EXPECT_GT(row["extra"]["rmse_without"].get<double>(), 0.0) << row.dump();
        } else if (skip != "adaptive") {
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
    EXPECT_EQ(count["deinterleave"], 3); // HBAO, GTAO, bitmask at the camera
    EXPECT_EQ(count["occluded"], 2);
    EXPECT_EQ(count["cull"], 2);
    EXPECT_EQ(count["targets"], 6);
    EXPECT_EQ(count["layer"], 2); // the one-pass second layer, exact on a still frame (above)
    EXPECT_NE(slurp(out + "/skips.md").find("#### Frustum culling"), std::string::npos);
    EXPECT_NE(slurp(out + "/skips.md").find("#### Draws the scene hides"), std::string::npos);
    EXPECT_NE(slurp(out + "/skips.md").find("#### Deinterleaved sampling"), std::string::npos);
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

namespace {
const char* kShardSweep = R"({"name": "shards", "groups": [{"name": "k", "vary": {"kernel.samples": [4, 256]}}]})";
std::string benchArgs(const std::string& sweep) {
    return "bench --scene builtin:corner --scene " + std::string(SSAOLAB_SCENES_DIR) +
           "/CornellBox/cornellBox.gltf --size 160x90 --views 2 --frames 3 --warmup 1 --reference-rays 16 --no-plot "
           "--quiet --sweep " + sweep;
}
std::map<std::string, nlohmann::json> rowsByKey(const nlohmann::json& j) {
    std::map<std::string, nlohmann::json> m;
    for (const auto& r : j["results"])
        m[r["scene"].get<std::string>() + "|" + r["viewpoint"].get<std::string>() + "|" + r["label"].get<std::string>()] = r;
    return m;
}
} // namespace

TEST(CliBench, TwoShardsMergedGiveOneRunsErrorsAndFront) {
    const std::string sweep = writeTemp("shard_sweep.json", kShardSweep);
    const std::string whole = outDir("shard_whole"), s1 = outDir("shard_1"), s2 = outDir("shard_2"), merged = outDir("shard_merged");
    for (const auto& d : {whole, s1, s2, merged})
        std::filesystem::remove_all(d);
    ASSERT_EQ(ssaolab(benchArgs(sweep) + " --out " + whole).exitCode, 0);
    ASSERT_EQ(ssaolab(benchArgs(sweep) + " --shard 1/2 --out " + s1).exitCode, 0);
    ASSERT_EQ(ssaolab(benchArgs(sweep) + " --shard 2/2 --out " + s2).exitCode, 0);
    const auto a = nlohmann::json::parse(slurp(whole + "/results.json"));
    const auto p1 = nlohmann::json::parse(slurp(s1 + "/results.json"));
    const auto p2 = nlohmann::json::parse(slurp(s2 + "/results.json"));
    // Each shard did about half the units: 2 scenes x 2 views x 8 configurations = 32.
    EXPECT_EQ(p1["results"].size() + p2["results"].size(), a["results"].size());
    EXPECT_EQ(p1["results"].size(), 16u);
    CliRun r = ssaolab("bench merge " + s1 + " " + s2 + " --no-plot --out " + merged);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto m = nlohmann::json::parse(slurp(merged + "/results.json"));
    const auto ra = rowsByKey(a), rm = rowsByKey(m);
    ASSERT_EQ(ra.size(), rm.size());
    for (const auto& [k, row] : ra) {
        ASSERT_TRUE(rm.count(k)) << k;
        for (const char* f : {"rmse", "bias", "mae", "p99_abs", "ssim", "rmse_edge", "psnr_full_srgb"})
            EXPECT_EQ(rm.at(k)[f], row[f]) << k << " " << f; // identical, not close
        EXPECT_GT(rm.at(k)["time_ratio"].get<double>(), 0.0) << k;
        // The error by place travels through the merge, and its five places add up to the row.
        EXPECT_EQ(rm.at(k)["error_by_place"], row["error_by_place"]) << k;
        const nlohmann::json& p = row["error_by_place"];
        double sq = 0;
        long px = 0;
        for (const char* place : {"border", "silhouette", "crease", "convex", "open"})
            sq += p[place][1].get<double>(), px += p[place][0].get<long>();
        EXPECT_EQ(px, p["all"][0].get<long>()) << k;
        EXPECT_NEAR(sq, p["all"][1].get<double>(), 1e-9 * (1.0 + sq)) << k;
        EXPECT_NEAR(std::sqrt(sq / double(px)), row["rmse"].get<double>(), 1e-6) << k; // the row's own RMSE
    }
    // The same rows in the same order.
    std::vector<std::string> oa, om;
    for (const auto& x : a["results"])
        oa.push_back(x["scene"].get<std::string>() + x["viewpoint"].get<std::string>() + x["label"].get<std::string>());
    for (const auto& x : m["results"])
        om.push_back(x["scene"].get<std::string>() + x["viewpoint"].get<std::string>() + x["label"].get<std::string>());
    EXPECT_EQ(oa, om);
    // Times are measured, so which near-tied configuration is on the front may differ between two
    // runs; what must hold is that each run's front is the Pareto front of its own (time ratio,
    // RMSE) and that the errors per configuration are the same. The most accurate configuration is
    // on both fronts: its error does not depend on timing.
    auto checkFront = [](const nlohmann::json& run) {
        const auto& cs = run["configurations"];
        for (const auto& c : cs) {
            bool dominated = false;
            for (const auto& d : cs)
                if (&d != &c && d["time_ratio"].get<double>() <= c["time_ratio"].get<double>() &&
                    d["rmse"].get<double>() <= c["rmse"].get<double>() &&
                    (d["time_ratio"].get<double>() < c["time_ratio"].get<double>() ||
                     d["rmse"].get<double>() < c["rmse"].get<double>()))
                    dominated = true;
            EXPECT_EQ(c["pareto"].get<bool>(), !dominated) << c.dump();
        }
    };
    checkFront(a);
    checkFront(m);
    ASSERT_EQ(a["configurations"].size(), m["configurations"].size());
    size_t best = 0;
    for (size_t i = 0; i < a["configurations"].size(); ++i) {
        EXPECT_EQ(a["configurations"][i]["label"], m["configurations"][i]["label"]);
        EXPECT_EQ(a["configurations"][i]["rmse"], m["configurations"][i]["rmse"]) << i;
        if (a["configurations"][i]["rmse"].get<double>() < a["configurations"][best]["rmse"].get<double>()) best = i;
    }
    EXPECT_TRUE(a["configurations"][best]["pareto"].get<bool>());
    EXPECT_TRUE(m["configurations"][best]["pareto"].get<bool>());
    // The merged report names the shards and what each measured; its page embeds both shards' thumbnails.
    EXPECT_EQ(m["shards"].size(), 2u);
    const std::string md = slurp(merged + "/report.md");
    EXPECT_NE(md.find("Merged from 2 shards"), std::string::npos);
    EXPECT_NE(md.find("| 2/2 |"), std::string::npos);
    const std::string html = slurp(merged + "/report.html");
    EXPECT_EQ(html.find("not measured by these runs"), std::string::npos);
    // Merging what is not one benchmark: one line each.
    expectCleanFailure(ssaolab("bench merge " + s1 + " --out " + merged + "_x"), "shard(s) 2/2 missing");
    expectCleanFailure(ssaolab("bench merge " + s1 + " " + s1 + " --out " + merged + "_x"), "is also in");
    expectCleanFailure(ssaolab("bench merge " + s1 + " " + whole + " --out " + merged + "_x"), "another split");
    expectCleanFailure(ssaolab("bench --shard 3/2"), "K/N");
    // A shard whose error by place was tampered with: refused, naming the row and the field.
    nlohmann::json bad = p1;
    bad["results"][0]["error_by_place"]["border"] = {1, -1.0, 0.0, 0.0};
    const std::string badDir = outDir("shard_bad");
    std::filesystem::remove_all(badDir);
    std::filesystem::copy(s1, badDir, std::filesystem::copy_options::recursive);
    { std::ofstream(badDir + "/results.json") << bad.dump(); }
    expectCleanFailure(ssaolab("bench merge " + badDir + " " + s2 + " --out " + merged + "_y"), "error_by_place: 'border' is negative");
    EXPECT_NE(md.find("### Where the error lives"), std::string::npos);
}

TEST(CliBench, ABudgetGetsOneLineAPresetAndTheSameNumbersFromRender) {
    const std::string sweep = writeTemp("answer_sweep.json", kShardSweep);
    const std::string out = outDir("answer");
    std::filesystem::remove_all(out);
    CliRun r = ssaolab("bench --scene " + std::string(SSAOLAB_SCENES_DIR) +
                       "/CornellBox/cornellBox.gltf --size 160x90 --views 1 --frames 2 --warmup 0 --reference-rays 16 "
                       "--no-plot --quiet --baseline gtao-low --max-error 0.5 --sweep " + sweep + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out; // --quiet: the answer alone
    EXPECT_NE(r.out.find("answer (at most RMSE 0.5, on a still camera): "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--set ao.radius_mode=world --set ao.radius="), std::string::npos) << r.out;
    const auto j = nlohmann::json::parse(slurp(out + "/results.json"));
    EXPECT_EQ(j["configurations"][0]["label"], "gtao-low (baseline)"); // --baseline: any preset
    // The fastest configuration at most 0.5 wrong is the one the line names...
    std::string fastest;
    double best = 1e300;
    for (const auto& c : j["configurations"])
        if (c["rmse"].get<double>() <= 0.5 && c["time_ratio"].get<double>() < best)
            best = c["time_ratio"].get<double>(), fastest = c["label"];
    EXPECT_NE(r.out.find("): " + fastest + ": "), std::string::npos) << r.out;
    // ...and its preset renders the same numbers (scene, size, camera and R in the preset).
    const std::string rout = outDir("answer_render");
    std::filesystem::remove_all(rout);
    CliRun rr = ssaolab("render --preset " + out + "/answer.json --reference --reference-rays 16 --quiet --out " + rout);
    ASSERT_EQ(rr.exitCode, 0) << rr.err;
    const auto metrics = nlohmann::json::parse(slurp(rout + "/metrics.json"));
    for (const auto& c : j["configurations"])
        if (c["label"] == fastest) {
            EXPECT_EQ(metrics["error"]["rmse"], c["rmse"]);
            EXPECT_EQ(metrics["error"]["bias"], c["bias"]);
        }
    // A question nothing meets is answered too.
    r = ssaolab("bench --scene builtin:corner --size 64x36 --views 1 --frames 1 --warmup 0 --reference-rays 4 --no-plot "
                "--quiet --budget-ms 0.000001 --sweep " + sweep + " --out " + out + "_none");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("answer: no configuration is within"), std::string::npos) << r.out;
}

// Two files named scene.gltf in different folders are two scenes, each with its own rows, named by
// the shortest part of their paths that tells them apart; one file named twice is one scene.
TEST(CliBench, TwoScenesOfOneFileNameKeepTheirOwnRows) {
    namespace fs = std::filesystem;
    const fs::path t = fs::path(SSAOLAB_TEST_TMP) / "same_stem";
    fs::remove_all(t);
    const fs::path src = fs::path(SSAOLAB_SCENES_DIR) / "CornellBox";
    for (const char* d : {"a", "b"}) {
        fs::create_directories(t / d);
        fs::copy_file(src / "cornellBox.gltf", t / d / "scene.gltf");
        fs::copy_file(src / "cornellBox.bin", t / d / "cornellBox.bin");
    }
    const std::string sweep = writeTemp("stem_sweep.json", R"({"name": "stems", "groups": [{"name": "k", "vary": {"kernel.samples": [8]}}]})");
    const std::string out = (t / "out").string();
    CliRun r = ssaolab("bench --scene " + (t / "a/scene.gltf").string() + " --scene " + (t / "b/scene.gltf").string() +
                       " --scene " + (t / "b/../a/scene.gltf").string() +
                       " --size 160x90 --views 1 --frames 2 --warmup 0 --reference-rays 8 --no-plot --quiet --sweep " +
                       sweep + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(slurp(out + "/results.json"));
    std::vector<std::string> names;
    for (const auto& s : j["scenes"])
        names.push_back(s["name"]);
    EXPECT_EQ(names, (std::vector<std::string>{"a/scene.gltf", "b/scene.gltf"}));
    std::map<std::string, size_t> rows;
    for (const auto& v : j["results"])
        ++rows[v["scene"].get<std::string>()];
    const size_t configs = j["configurations"].size();
    EXPECT_EQ(rows["a/scene.gltf"], configs);
    EXPECT_EQ(rows["b/scene.gltf"], configs);
    EXPECT_EQ(rows.size(), 2u);
    const std::string html = slurp(out + "/report.html");
    size_t plots = 0;
    for (size_t p = html.find("<svg class=\"plot\""); p != std::string::npos; p = html.find("<svg class=\"plot\"", p + 1))
        ++plots;
    EXPECT_EQ(plots, 3u); // all scenes, then one per scene
    EXPECT_EQ(html.find("not measured by these runs"), std::string::npos); // each scene its own thumbnails
    // A file alone with its stem is still named by it; a built-in scene keeps builtin:NAME.
    r = ssaolab("bench --scene " + (t / "a/scene.gltf").string() +
                " --scene builtin:corner --size 64x36 --views 1 --frames 1 --warmup 0 --reference-rays 4 --no-plot "
                "--quiet --sweep " + sweep + " --out " + out + "_one");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    names.clear();
    const auto one = nlohmann::json::parse(slurp(out + "_one/results.json"));
    for (const auto& s : one["scenes"])
        names.push_back(s["name"]);
    EXPECT_EQ(names, (std::vector<std::string>{"scene", "builtin:corner"}));
}

TEST(CliBench, TwoLayerRowsAreSplitAgainstATwoLayerOracleAndCountTheirLayer) {
    // builtin:hidden: a wall the first layer hides behind a plate. The two-layer rows' screen is the
    // deep oracle's, smaller than the one-layer screen; the report says how much of it they closed.
    const std::string sweep = writeTemp("layers_sweep.json", R"({"name": "layers", "groups": [{"name": "two",
        "preset": "vbao-high", "set": {"gbuffer.second_layer": true},
        "vary": {"gbuffer.second_layer_build": ["peel", "previous"]}}]})");
    const std::string out = outDir("bench_layers");
    const CliRun r = ssaolab("bench --scene builtin:hidden --size 160x90 --views 1 --frames 2 --warmup 0 "
                             "--reference-rays 16 --no-plot --quiet --sweep " + sweep + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(slurp(out + "/results.json"));
    double oneLayer = NAN;
    std::vector<nlohmann::json> two;
    for (const auto& v : j["results"]) {
        const std::string label = v["label"];
        if (label == "learnopengl (baseline)") oneLayer = v["rmse_screen"].get<double>();
        if (label.find("second_layer_build") != std::string::npos) two.push_back(v);
    }
    ASSERT_EQ(two.size(), 2u);
    for (const auto& v : two) {
        EXPECT_LT(v["rmse_screen"].get<double>(), 0.5 * oneLayer) << v["label"]; // the hidden wall is seen
        const auto& layers = v["pass_ms"]["layers"];
        ASSERT_TRUE(layers.is_number()) << v["label"]; // the layer's time, either build
        EXPECT_GE(layers.get<double>(), 0.0) << v["label"];
    }
    EXPECT_EQ(j["oracle"]["layers_two_layer_rows"], 2);
    const std::string md = slurp(out + "/report.md");
    const std::regex closed(R"(second\\_layer\\_build=[a-z]+ [^\n]*\| \d+ % \|)");
    EXPECT_EQ(std::distance(std::sregex_iterator(md.begin(), md.end(), closed), std::sregex_iterator()), 2) << md;
}
