// Error in motion, whole program: `render --motion`, `bench --motion` (its columns, and `bench
// merge` checking them), `bench --objective motion` and `tune --objective motion`, at tiny sizes with
// few-ray references.
#include "cli_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

using namespace ssaotest;
namespace fs = std::filesystem;

namespace {
const std::string kTiny = "--scene builtin:showcase --size 64x36 --reference-rays 4 ";

nlohmann::json metrics(const std::string& dir) {
    return nlohmann::json::parse(slurp(dir + "/metrics.json"));
}
} // namespace

TEST(CliMotion, RenderScoresThePathFrameByFrameAndItsFirstFrameIsTheStillOne) {
    for (const std::string set : {"", "--set ao.technique=gtao --set temporal.enabled=true --set temporal.frames=4 "}) {
        const std::string out = outDir("motion_render");
        fs::remove_all(out);
        CliRun r = ssaolab("render " + kTiny + set + "--timing-frames 1 --reference --motion --motion-frames 5 --out " + out);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.out.find("motion (5 frames"), std::string::npos) << r.out;
        const nlohmann::json m = metrics(out);
        ASSERT_TRUE(m.contains("motion")) << m.dump();
        const nlohmann::json& mo = m["motion"];
        EXPECT_EQ(mo["path"]["frames"], 5);
        ASSERT_EQ(mo["rmse_frames"].size(), 5u);
        // The path starts at the view, rendered as a still frame: the same RMSE as --reference's.
        EXPECT_NEAR(mo["rmse_frames"][0].get<double>(), m["error"]["rmse"].get<double>(), 1e-9) << set;
        EXPECT_GT(mo["rmse_mean"].get<double>(), 0.0);
        EXPECT_LT(mo["rmse_mean"].get<double>(), 1.0);
        EXPECT_GE(mo["rmse_max"].get<double>(), mo["rmse_mean"].get<double>() - 1e-12);
        EXPECT_GT(mo["pairs"].get<long>(), 0);
        EXPECT_GT(mo["instability"].get<double>(), 0.0);
        EXPECT_GE(mo["instability_floor"].get<double>(), 0.0);
        // The objective is the motion score squared: (mean per-frame RMSE)^2 + instability^2.
        const double mean = mo["rmse_mean"].get<double>(), inst = mo["instability"].get<double>();
        EXPECT_NEAR(mo["objective"].get<double>(), mean * mean + inst * inst, 1e-12);
        // A second run reads every frame's reference from the cache and gives the same numbers.
        CliRun again = ssaolab("render " + kTiny + set + "--timing-frames 1 --quiet --motion --motion-frames 5 --out " + out);
        ASSERT_EQ(again.exitCode, 0) << again.err;
        EXPECT_EQ(again.out, "");
        const nlohmann::json m2 = metrics(out)["motion"];
        EXPECT_EQ(m2["reference"]["cached_frames"], 5);
        EXPECT_EQ(m2["rmse_frames"], mo["rmse_frames"]);
        EXPECT_EQ(m2["instability"], mo["instability"]);
    }
}

TEST(CliMotion, AStillCameraPathHasNoInstabilityAndNoDisocclusion) {
    const std::string out = outDir("motion_still");
    fs::remove_all(out);
    for (const std::string set : {"", "--set temporal.enabled=true --set temporal.frames=3 "}) {
        CliRun r = ssaolab("render " + kTiny + set +
                           "--timing-frames 1 --quiet --motion --motion-frames 4 --motion-orbit 0 --motion-dolly 0 --out " + out);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const nlohmann::json mo = metrics(out)["motion"];
        EXPECT_EQ(mo["instability"], 0.0) << set;
        EXPECT_EQ(mo["disoccluded_pixels"], 0) << set;
        EXPECT_TRUE(mo["ghosting"].is_null()) << set;
        EXPECT_EQ(mo["rmse_max"], mo["rmse_mean"]) << set;
    }
    expectCleanFailure(ssaolab("render --motion --motion-frames 1 --out " + out), "--motion-frames");
    expectCleanFailure(ssaolab("render --motion --motion-dolly 2 --out " + out), "--motion-dolly");
}

TEST(CliMotion, BenchAddsMotionColumnsThatMergeKeepsAndChecks) {
    const std::string out = outDir("motion_bench"), merged = outDir("motion_bench_merged");
    fs::remove_all(out), fs::remove_all(merged);
    const std::string sweep = writeTemp("motion_sweep.json", R"({"name": "motion", "groups": [
        {"name": "temporal", "set": {"ao.technique": "gtao", "temporal.enabled": true, "temporal.frames": 4}}]})");
    CliRun r = ssaolab("bench " + kTiny + "--views 2 --frames 1 --warmup 0 --no-plot --quiet --motion --motion-frames 4 "
                       "--sweep " + sweep + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(slurp(out + "/results.json"));
    EXPECT_EQ(j["motion"]["frames"], 4);
    ASSERT_GE(j["results"].size(), 2u);
    for (const auto& v : j["results"]) {
        EXPECT_GT(v["motion_rmse_mean"].get<double>(), 0.0) << v["label"];
        EXPECT_GE(v["motion_rmse_max"].get<double>(), v["motion_rmse_mean"].get<double>() - 1e-12);
        EXPECT_GE(v["motion_instability"].get<double>(), 0.0) << v["label"];
    }
    for (const auto& c : j["configurations"]) EXPECT_TRUE(c["motion_rmse_mean"].is_number()) << c["label"];
    EXPECT_NE(slurp(out + "/summary.csv").find("motion_rmse_mean,motion_instability,motion_ghosting"), std::string::npos);
    EXPECT_NE(slurp(out + "/results.csv").find("motion_instability"), std::string::npos);
    EXPECT_NE(slurp(out + "/report.md").find("### In motion"), std::string::npos);
    EXPECT_NE(slurp(out + "/report.html").find(">instability</th>"), std::string::npos);

    CliRun m = ssaolab("bench merge " + out + " --no-plot --quiet --out " + merged);
    ASSERT_EQ(m.exitCode, 0) << m.err;
    const nlohmann::json jm = nlohmann::json::parse(slurp(merged + "/results.json"));
    EXPECT_EQ(jm["results"][0]["motion_instability"], j["results"][0]["motion_instability"]);
    EXPECT_EQ(jm["configurations"][1]["motion_rmse_mean"], j["configurations"][1]["motion_rmse_mean"]);
    // A shard's motion numbers are foreign input: out of range is refused, naming the field.
    nlohmann::json bad = j;
    bad["results"][0]["motion_instability"] = 5.0;
    std::ofstream(out + "/results.json") << bad.dump();
    expectCleanFailure(ssaolab("bench merge " + out + " --no-plot --quiet --out " + merged), "motion_instability");

    // Without --motion: no motion facts, null columns, no motion section.
    fs::remove_all(out);
    CliRun still = ssaolab("bench " + kTiny + "--views 2 --frames 1 --warmup 0 --no-plot --quiet --sweep " + sweep + " --out " + out);
    ASSERT_EQ(still.exitCode, 0) << still.err;
    const nlohmann::json js = nlohmann::json::parse(slurp(out + "/results.json"));
    EXPECT_FALSE(js.contains("motion"));
    EXPECT_TRUE(js["results"][0]["motion_rmse_mean"].is_null());
    EXPECT_EQ(slurp(out + "/report.md").find("### In motion"), std::string::npos);
    // Scoring in motion leaves the still numbers as they were, row for row.
    ASSERT_EQ(js["results"].size(), j["results"].size());
    for (size_t i = 0; i < j["results"].size(); ++i)
        EXPECT_EQ(js["results"][i]["rmse"], j["results"][i]["rmse"]) << j["results"][i]["label"];
}

TEST(CliMotion, TuneMinimisesTheMotionObjective) {
    const std::string preset = std::string(SSAOLAB_TEST_TMP) + "/tuned_motion.json";
    fs::remove(preset);
    CliRun r = ssaolab("tune " + kTiny + "--technique gtao --views 2 --rounds 1 --grid 3 --knob gtao.falloff_range "
                       "--objective motion --motion-frames 4 --save-overfit --out " + preset);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const size_t at = r.out.find("motion score");
    ASSERT_NE(at, std::string::npos) << r.out;
    double before = 0, after = 0;
    ASSERT_EQ(std::sscanf(r.out.substr(r.out.find("training ", at)).c_str(), "training %lf -> %lf", &before, &after), 2)
        << r.out;
    EXPECT_LE(after, before);
    const nlohmann::json p = nlohmann::json::parse(slurp(preset));
    EXPECT_NE(p["scores"]["metric"].get<std::string>().find("motion score"), std::string::npos) << p["scores"];
    expectCleanFailure(ssaolab("tune --objective sideways"), "--objective");
}

TEST(CliMotion, PathOptionsWithoutAPathSayTheyDoNothing) {
    const CliRun r = ssaolab("render --motion-frames 4 --motion-orbit 8 --size 64x36 --timing-frames 1 --quiet --out " +
                             outDir("motion_unused"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("ssaolab: warning: --motion-frames 4 does nothing without --motion"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("ssaolab: warning: --motion-orbit does nothing without --motion"), std::string::npos) << r.err;
    const CliRun quiet = ssaolab("render --size 64x36 --timing-frames 1 --quiet --out " + outDir("motion_unused_none"));
    EXPECT_EQ(quiet.err.find("does nothing"), std::string::npos) << quiet.err;
}

TEST(CliMotion, AStillPathPrintsNoNanAndGhostingNoPixelBacksAsNotAvailable) {
    const CliRun r = ssaolab("render " + kTiny + "--timing-frames 1 --motion --motion-frames 3 --motion-orbit 0 "
                             "--motion-dolly 0 --out " + outDir("motion_still_line"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("ghosting n/a (0 pixels)"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
}

TEST(CliMotion, AMotionAnswerThatDiffersFromTheStillOneIsSaid) {
    // A long memory in motion: the best still frame (the bitmask, 64 accumulated frames) lags behind a
    // wide orbit, where a single frame of the same technique (its defaults, in every sweep) does not.
    const std::string out = outDir("motion_answer");
    fs::remove_all(out);
    const std::string sweep = writeTemp("motion_answer_sweep.json", R"({"name": "answer", "groups": [
        {"name": "long memory", "set": {"ao.technique": "vbao", "temporal.enabled": true, "temporal.frames": 64,
                                        "temporal.moving_frames": 64, "temporal.plane_tolerance": 16}}]})");
    const CliRun r = ssaolab("bench " + kTiny + "--views 1 --frames 1 --warmup 0 --no-plot --motion --motion-frames 4 "
                             "--motion-orbit 30 --sweep " + sweep + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string longMemory = "ao.technique=vbao temporal.enabled=true temporal.frames=64";
    EXPECT_NE(r.out.find("lowest error on a still camera: " + longMemory), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("lowest error in motion: "), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("lowest error in motion: " + longMemory), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("is not the lowest in motion"), std::string::npos) << r.out;
    const std::string md = slurp(out + "/report.md");
    EXPECT_NE(md.find("Lowest error on a still camera: **"), std::string::npos);
    EXPECT_NE(md.find("Lowest error in motion (motion score): **"), std::string::npos);
    EXPECT_NE(md.find("is not the lowest in motion"), std::string::npos);
    EXPECT_NE(md.find("| configuration | x baseline time | still RMSE |"), std::string::npos);
    const std::string html = slurp(out + "/report.html");
    EXPECT_NE(html.find("Lowest error in motion (motion score): <b>"), std::string::npos);
    EXPECT_NE(html.find("is not the lowest in motion"), std::string::npos);
    EXPECT_NE(html.find("all scenes, in motion"), std::string::npos); // the motion front's own plot
    EXPECT_NE(html.find("motion score: sqrt(RMSE^2 + instability^2)"), std::string::npos);
}

// bench --objective motion: the answer, the front and the plot rank by the motion score, and say so;
// merge re-ranks the same rows under either objective; a still run cannot be ranked in motion.
TEST(CliMotion, TheMotionObjectiveDecidesTheAnswerAndTheFront) {
    const std::string out = outDir("objective_bench"), merged = outDir("objective_merged");
    fs::remove_all(out), fs::remove_all(merged);
    const std::string sweep = writeTemp("objective_sweep.json", R"({"name": "objective", "groups": [
        {"name": "gtao", "set": {"ao.technique": "gtao"}},
        {"name": "gtao temporal", "set": {"ao.technique": "gtao", "temporal.enabled": true, "temporal.frames": 8}}]})");
    CliRun r = ssaolab("bench " + kTiny + "--views 1 --frames 1 --warmup 0 --motion-frames 4 "
                       "--objective motion --budget-ratio 100 --sweep " + sweep + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(out + "/pareto.png")) << "the plot of time against the motion score: " << r.err;
    EXPECT_EQ(r.err.find("plot_pareto: warning"), std::string::npos) << r.err;
    const nlohmann::json j = nlohmann::json::parse(slurp(out + "/results.json"));
    EXPECT_EQ(j["objective"], "motion");
    ASSERT_TRUE(j.contains("motion")) << "--objective motion implies --motion";
    // The answer is the row of lowest motion score (any time is within 100x), named as a motion answer.
    std::string best;
    double score = INFINITY;
    for (const auto& c : j["configurations"])
        if (c["motion_score"].get<double>() < score) score = c["motion_score"].get<double>(), best = c["label"];
    EXPECT_NE(r.out.find("answer (within 100x the baseline's time, in motion): " + best + ":"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("on the Pareto front of time against the motion score"), std::string::npos) << r.out;
    for (const auto& c : j["configurations"]) { // the front: no row both faster and lower in score
        bool dominated = false;
        for (const auto& d : j["configurations"])
            dominated = dominated || (d["time_ratio"] <= c["time_ratio"] && d["motion_score"] <= c["motion_score"] &&
                                      (d["time_ratio"] < c["time_ratio"] || d["motion_score"] < c["motion_score"]));
        EXPECT_EQ(c["pareto"].get<bool>(), !dominated) << c["label"];
    }
    EXPECT_NE(slurp(out + "/report.md").find("### Pareto front in motion (motion score)"), std::string::npos);
    EXPECT_NE(slurp(out + "/summary.csv").find("motion_score,motion_score_ratio"), std::string::npos);

    CliRun m = ssaolab("bench merge " + out + " --no-plot --quiet --objective still --budget-ratio 100 --out " + merged);
    ASSERT_EQ(m.exitCode, 0) << m.err;
    EXPECT_NE(m.out.find("on a still camera): "), std::string::npos) << m.out;
    EXPECT_EQ(nlohmann::json::parse(slurp(merged + "/results.json"))["objective"], "still");

    fs::remove_all(out);
    ASSERT_EQ(ssaolab("bench " + kTiny + "--views 1 --frames 1 --warmup 0 --no-plot --quiet --sweep " + sweep +
                      " --out " + out).exitCode, 0);
    expectCleanFailure(ssaolab("bench merge " + out + " --no-plot --quiet --objective motion --out " + merged),
                       "not scored in motion");
    expectCleanFailure(ssaolab("bench " + kTiny + "--objective fastest --out " + out), "--objective");
}
