// Whole program: the bench's answer to a user's question (--budget-ms, --budget-ratio, --max-error)
// in every place a user reads the run (stdout, answer.json, report.md, report.html), a budget in
// the plot's own unit (x the baseline's time), the still-camera caveat of temporal accumulation, and
// one configuration under two names measured once.
#include "cli_run.h"

#include "output/escape.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

using namespace ssaotest;

namespace {

const std::string kTiny = " --scene builtin:corner --size 64x36 --views 1 --frames 1 --warmup 0 --reference-rays 4 "
                          "--no-plot --quiet";

std::string freshOut(const std::string& name) {
    const std::string dir = outDir(name);
    std::filesystem::remove_all(dir);
    return dir;
}

const nlohmann::json* configNamed(const nlohmann::json& results, const std::string& label) {
    for (const auto& c : results["configurations"])
        if (c["label"] == label) return &c;
    return nullptr;
}

} // namespace

// `vbao defaults` and `ao.technique=vbao denoise.kind=none` are one configuration (vbao's auto
// denoiser is none): measured once, listed once, the second name kept as an alias.
TEST(CliBenchAnswer, TheAnswerOpensBothReportsAndOneConfigurationIsMeasuredOnce) {
    const std::string sweep = writeTemp("answer_report_sweep.json", R"({"name": "answer", "groups": [
        {"name": "k", "vary": {"kernel.samples": [4, 16]}},
        {"name": "vbao plain", "set": {"ao.technique": "vbao", "denoise.kind": "none"}}]})");
    const std::string out = freshOut("answer_report");
    CliRun r = ssaolab("bench" + kTiny + " --max-error 0.5 --sweep " + sweep + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(slurp(out + "/results.json"));
    // Measured once: the first name stays, the other is its alias.
    const nlohmann::json* vb = configNamed(j, "ao.technique=vbao denoise.kind=none");
    ASSERT_NE(vb, nullptr) << j["configurations"].dump();
    EXPECT_EQ(configNamed(j, "vbao defaults"), nullptr);
    EXPECT_EQ((*vb)["aliases"], nlohmann::json::array({"vbao defaults"}));
    EXPECT_EQ(j["configurations"].size(), 1u + 2u + 1u + 4u); // baseline, k, vbao plain, the other 4 techniques
    const std::string html = slurp(out + "/report.html"), md = slurp(out + "/report.md");
    EXPECT_NE(html.find("also: vbao defaults"), std::string::npos);

    // The answer, as stdout says it, opens both reports: the question, the row, its ratios, the command.
    const size_t colon = r.out.find("): ");
    ASSERT_NE(colon, std::string::npos) << r.out;
    const std::string label = r.out.substr(colon + 3, r.out.find(": ", colon + 3) - colon - 3);
    const nlohmann::json* row = configNamed(j, label);
    ASSERT_NE(row, nullptr) << label;
    const std::string command = "ssaolab render --preset " + out + "/answer.json --reference --reference-rays 4";
    char ratios[96];
    std::snprintf(ratios, sizeof ratios, "%.3gx the baseline's time", (*row)["time_ratio"].get<double>());
    for (const std::string* report : {&md, &html}) {
        const size_t at = report->find("at most RMSE 0.5");
        ASSERT_NE(at, std::string::npos) << *report;
        EXPECT_LT(at, report->find("Pareto front")) << "the answer comes first";
        EXPECT_NE(report->find(ratios), std::string::npos) << ratios;
        EXPECT_EQ(report->find("holds for a still camera"), std::string::npos);
    }
    // Each through its file's escaper (the output folder's name is the user's).
    EXPECT_NE(md.find(ssao::markdownCell(command)), std::string::npos) << md.substr(0, 800);
    EXPECT_NE(html.find(ssao::htmlText(command)), std::string::npos);
    EXPECT_NE(md.find("**" + ssao::markdownCell(label) + "**"), std::string::npos) << md.substr(0, 800);
    EXPECT_NE(html.find("<b>" + ssao::htmlText(label) + "</b>"), std::string::npos);
    EXPECT_EQ(r.out.find("holds for a still camera"), std::string::npos);
}

// The plot's axis is "x the baseline's time": a budget in that unit answers with the most accurate
// configuration at most that many times the baseline's time.
TEST(CliBenchAnswer, ABudgetIsAlsoARatioToTheBaseline) {
    const std::string sweep = writeTemp("answer_ratio_sweep.json", R"({"name": "ratio", "groups": [
        {"name": "k", "vary": {"kernel.samples": [4, 16]}}]})");
    const std::string out = freshOut("answer_ratio");
    CliRun r = ssaolab("bench" + kTiny + " --budget-ratio 0.8 --sweep " + sweep + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("answer (within 0.8x the baseline's time, on a still camera): "), std::string::npos) << r.out;
    const auto j = nlohmann::json::parse(slurp(out + "/results.json"));
    std::string best;
    double rmse = 1e300;
    for (const auto& c : j["configurations"])
        if (c["time_ratio"].get<double>() <= 0.8 && c["rmse"].get<double>() < rmse)
            rmse = c["rmse"].get<double>(), best = c["label"];
    if (best.empty())
        EXPECT_NE(r.out.find("answer: no configuration is within 0.8x the baseline's time"), std::string::npos) << r.out;
    else
        EXPECT_NE(r.out.find("): " + best + ": "), std::string::npos) << r.out;
    expectCleanFailure(ssaolab("bench --budget-ratio 0 --out " + out + "_x"), "--budget-ratio");
    expectCleanFailure(ssaolab("bench --budget-ratio -1 --out " + out + "_x"), "--budget-ratio");
    EXPECT_NE(ssaolab("bench --help").out.find("--budget-ratio"), std::string::npos);
    EXPECT_NE(ssaolab("bench merge --help").out.find("--budget-ratio"), std::string::npos);
}

// Temporal accumulation blends frames of an unmoving view: an answer that relies on it says so
// everywhere it is given, with the error a moving camera sees (its first frame's).
TEST(CliBenchAnswer, AnAnswerThatAccumulatesFramesHoldsForAStillCamera) {
    const std::string sweep = writeTemp("answer_still_sweep.json", R"({"name": "still",
        "base": {"set": {"temporal.enabled": true}}, "groups": []})");
    const std::string out = freshOut("answer_still");
    // Most accurate whatever its time: every configuration but the (seed) baseline accumulates.
    CliRun r = ssaolab("bench" + kTiny + " --budget-ratio 1000 --sweep " + sweep + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(slurp(out + "/results.json"));
    const size_t colon = r.out.find("): ");
    ASSERT_NE(colon, std::string::npos) << r.out;
    const nlohmann::json* row = configNamed(j, r.out.substr(colon + 3, r.out.find(": ", colon + 3) - colon - 3));
    ASSERT_NE(row, nullptr) << r.out;
    ASSERT_TRUE((*row)["settings"]["temporal"]["enabled"].get<bool>()) << r.out;
    EXPECT_NE(r.out.find("still camera"), std::string::npos) << r.out;
    const auto answer = nlohmann::json::parse(slurp(out + "/answer.json"));
    EXPECT_NE(answer["description"].get<std::string>().find("still camera"), std::string::npos);
    EXPECT_TRUE(answer["scores"]["still_camera_only"].get<bool>());
    EXPECT_NE(slurp(out + "/report.md").find("still camera"), std::string::npos);
    EXPECT_NE(slurp(out + "/report.html").find("still camera"), std::string::npos);
}
