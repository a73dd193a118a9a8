// bench --objective: the still frame's RMSE or the motion score decides the front, the answers and
// "fastest at most the baseline's error", and every answer names the objective it is for. A run
// whose still winner accumulates frames (temporal) and loses in motion must be answered differently.
#include "metrics/bench_summary.h"
#include "metrics/motion_metrics.h"
#include "results/bench_answer.h"
#include "results/bench_report.h"
#include "results/bench_results.h"
#include "results/report_html.h"
#include "results/results_check.h"
#include "settings/params.h"
#include "util/error.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace ssao;

namespace {
// Four rows on one view. Times 10 (baseline), 4, 6, 8 ms. Still RMSE: 0.20, 0.12, 0.10, 0.05 (the
// last accumulates frames: best still); per-frame RMSE in motion 0.21, 0.13, 0.09, 0.16 with
// instabilities 0.05, 0.03, 0.02, 0.08: in motion the third row is best, the temporal one third.
BenchRun motionRun(Objective o) {
    BenchRun run;
    run.sweep.name = "objective";
    run.facts = {{"size", "64x36"},
                 {"frames", 2},
                 {"warmup", 0},
                 {"views_per_scene", 1},
                 {"reference", {{"definition", "test"}, {"rays", 8}}},
                 {"motion", {{"frames", 4}, {"orbit_deg", 4.0}, {"dolly", 0.0}}},
                 {"scene_specs", {"builtin:s"}},
                 {"scenes",
                  {{{"name", "s"}, {"spec", "builtin:s"}, {"viewpoints", {{{"name", "camera"}, {"index", 0}, {"camera", nlohmann::json::object()}}}}}}}};
    const char* labels[] = {"learnopengl (baseline)", "cheap", "steady", "temporal"};
    const double ms[] = {10, 4, 6, 8}, rmse[] = {0.20, 0.12, 0.10, 0.05};
    const double moving[] = {0.21, 0.13, 0.09, 0.16}, instability[] = {0.05, 0.03, 0.02, 0.08};
    for (size_t c = 0; c < 4; ++c) {
        BenchConfig cfg;
        cfg.label = labels[c], cfg.group = "g", cfg.baseline = c == 0;
        cfg.settings = defaultSettings();
        cfg.settings.temporal.enabled = c == 3;
        run.sweep.configs.push_back(cfg);
        ViewResult v;
        v.scene = "s", v.viewpoint = "camera", v.config = c;
        v.gpuMs = v.gpuMsMin = v.gpuMsMax = ms[c];
        v.baselineMs = 10;
        v.error.rmse = rmse[c], v.error.psnrGeometrySrgb = v.error.psnrFullSrgb = 20;
        v.rmseFirstFrame = rmse[c];
        v.hasMotion = true;
        v.motion = {moving[c], moving[c] * 1.5, instability[c], NAN};
        run.views.push_back(v);
    }
    run.shards = nlohmann::json::array({{{"shard", "1/1"}, {"hostname", "h"}, {"rows", 4}}});
    run.facts["objective"] = objectiveKey(o);
    run.summary = summarize(run.views, 4, 0, o);
    return run;
}

std::vector<size_t> front(const BenchRun& run) {
    std::vector<size_t> out;
    for (const ConfigSummary& s : run.summary)
        if (s.pareto) out.push_back(s.config);
    return out;
}
} // namespace

TEST(BenchObjective, TheMotionScoreIsSummarisedWithItsRatio) {
    const BenchRun run = motionRun(Objective::Motion);
    EXPECT_NEAR(run.summary[2].motionScore, motionScore(0.09, 0.02), 1e-12);
    EXPECT_NEAR(run.summary[2].motionRatio, motionScore(0.09, 0.02) / motionScore(0.21, 0.05), 1e-12);
    EXPECT_EQ(objectiveError(run.summary[3], Objective::Still), 0.05);
    EXPECT_EQ(objectiveError(run.summary[3], Objective::Motion), run.summary[3].motionScore);
    EXPECT_EQ(parseObjective("motion"), Objective::Motion);
    EXPECT_THROW(parseObjective("Motion"), std::invalid_argument);
}

TEST(BenchObjective, TheFrontFollowsTheObjective) {
    // Still: every row is on the front (each faster one is more wrong). In motion the temporal row
    // is slower and more wrong than "steady": off the front.
    EXPECT_EQ(front(motionRun(Objective::Still)), (std::vector<size_t>{1, 2, 3}));
    EXPECT_EQ(front(motionRun(Objective::Motion)), (std::vector<size_t>{1, 2}));
}

TEST(BenchObjective, AMotionAnswerDiffersFromTheStillOneAndSaysSo) {
    const BenchRun still = motionRun(Objective::Still), moving = motionRun(Objective::Motion);
    EXPECT_EQ(answer(still, Question{0, 0, 1.0, Objective::Still}), 3u);   // the temporal row: lowest still RMSE
    EXPECT_EQ(answer(moving, Question{0, 0, 1.0, Objective::Motion}), 2u); // "steady": lowest motion score
    EXPECT_EQ(answer(moving, Question{0, 0.1, 0, Objective::Motion}), 2u); // fastest at most score 0.1
    EXPECT_EQ(answer(moving, Question{0, 0.1, 0, Objective::Still}), 2u);  // fastest at most RMSE 0.1
    EXPECT_EQ(answer(moving, Question{0, 0.06, 0, Objective::Motion}), std::string::npos);
    EXPECT_EQ(fastestAtMostBaselineError(moving), 1u);

    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/objective_answer";
    std::filesystem::create_directories(dir);
    AnswerContext ctx{"builtin:s", 64, 36, Camera{}, 8, dir + "/answer.json"};
    const Answer a = answerQuestion(moving, Question{0, 0, 1.0, Objective::Motion}, ctx, 0.5f);
    EXPECT_NE(a.line.find("(within 1x the baseline's time, in motion): steady"), std::string::npos) << a.line;
    EXPECT_NE(a.line.find("motion score 0.09"), std::string::npos) << a.line;
    EXPECT_EQ(a.line.find("RMSE 0.1 "), std::string::npos) << a.line;
    const Answer s = answerQuestion(still, Question{0, 0, 1.0, Objective::Still}, ctx, 0.5f);
    EXPECT_NE(s.line.find("on a still camera): temporal"), std::string::npos) << s.line;
    EXPECT_NE(s.line.find("holds for a still camera"), std::string::npos) << s.line;
    const std::string md = answerMarkdown(moving, a), html = answerHtml(moving, a);
    EXPECT_NE(md.find("in motion"), std::string::npos) << md;
    EXPECT_NE(md.find("(motion score "), std::string::npos) << md;
    EXPECT_NE(html.find("in motion"), std::string::npos) << html;

    // The reports: the objective named, the winners' difference in one line, the front by the score.
    const std::string report = benchMarkdown(moving, "pareto.png", &a);
    EXPECT_NE(report.find("Objective: **the motion score**"), std::string::npos);
    EXPECT_NE(report.find("is not the lowest in motion"), std::string::npos);
    EXPECT_NE(report.find("### Pareto front in motion (motion score)"), std::string::npos);
    EXPECT_NE(report.find("Fastest configuration at most as wrong as the baseline in motion: **cheap**"), std::string::npos);
    const std::string page = benchHtml(moving, dir, &a);
    EXPECT_NE(page.find("Objective: <b>the motion score</b>"), std::string::npos);
    EXPECT_LT(page.find("all scenes, in motion"), page.find("all scenes, still camera")) << "the objective's plot first";
}

TEST(BenchObjective, ResultsRecordTheObjectiveAndRefuseOneTheyCannotHold) {
    const BenchRun run = motionRun(Objective::Motion);
    nlohmann::json j = resultsJson(run);
    EXPECT_EQ(j["objective"], "motion");
    EXPECT_EQ(runObjective(parseResultsText(j.dump(), "r.json")), Objective::Motion);
    j["objective"] = "fastest";
    EXPECT_NE(ssaotest::errorOf([&] { parseResultsText(j.dump(), "r.json"); }).find("facts.objective"), std::string::npos);
    j["objective"] = "motion";
    j.erase("motion");
    for (auto& v : j["results"])
        for (const char* k : {"motion_rmse_mean", "motion_rmse_max", "motion_instability", "motion_ghosting"}) v[k] = nullptr;
    EXPECT_NE(ssaotest::errorOf([&] { parseResultsText(j.dump(), "r.json"); }).find("without facts.motion"),
              std::string::npos);
}
