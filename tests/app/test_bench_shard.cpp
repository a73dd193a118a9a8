// Splitting and answering a benchmark, pure: shards partition the work, results.json reads back
// what it wrote, the answer to a budget is the right row, report.html embeds what it names.
#include "results/bench_answer.h"
#include "results/bench_results.h"
#include "results/report_html.h"
#include "results/shard.h"
#include "settings/params.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/json_file.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <set>

using namespace ssao;

TEST(BenchShard, ShardsPartitionTheWorkContiguouslyAndEvenly) {
    for (int n : {1, 2, 3, 7, 50}) {
        std::set<std::tuple<size_t, size_t, size_t>> all;
        size_t smallest = SIZE_MAX, largest = 0;
        for (int k = 1; k <= n; ++k) {
            const auto u = shardUnits(3, 2, 8, ShardSpec{k, n});
            smallest = std::min(smallest, u.size()), largest = std::max(largest, u.size());
            for (size_t i = 0; i < u.size(); ++i) {
                EXPECT_TRUE(all.insert({u[i].scene, u[i].view, u[i].config}).second) << "unit in two shards";
                if (i) { // contiguous in scene, view, configuration order
                    const size_t a = (u[i - 1].scene * 2 + u[i - 1].view) * 8 + u[i - 1].config;
                    EXPECT_EQ((u[i].scene * 2 + u[i].view) * 8 + u[i].config, a + 1);
                }
            }
        }
        EXPECT_EQ(all.size(), 3u * 2u * 8u) << n << " shards";
        EXPECT_LE(largest - smallest, 1u) << n << " shards";
    }
}

TEST(BenchShard, AShardSpecIsKOfN) {
    EXPECT_EQ(parseShard("2/4").index, 2);
    EXPECT_EQ(parseShard("2/4").count, 4);
    EXPECT_TRUE(parseShard("1/1").whole());
    for (const char* bad : {"0/4", "5/4", "4", "a/b", "1/0", "-1/2", "1/99999999", "", "1/2/3"})
        EXPECT_THROW(parseShard(bad), Error) << bad;
}

namespace {
BenchRun smallRun() {
    BenchRun run;
    run.sweep.name = "t";
    run.facts = {{"size", "64x36"},
                 {"frames", 2},
                 {"warmup", 0},
                 {"views_per_scene", 1},
                 {"reference", {{"definition", "test"}, {"rays", 8}}},
                 {"scene_specs", {"builtin:s"}},
                 {"scenes",
                  {{{"name", "s"}, {"spec", "builtin:s"}, {"viewpoints", {{{"name", "camera"}, {"index", 0}, {"camera", nlohmann::json::object()}}}}}}}};
    for (int i = 0; i < 3; ++i) {
        BenchConfig c;
        c.label = i == 0 ? "learnopengl (baseline)" : "kernel.samples=" + std::to_string(8 << i);
        c.group = "g";
        c.settings = defaultSettings();
        c.settings.kernel.samples = 8 << i;
        c.keys = {{"kernel.samples", 8 << i}};
        c.baseline = i == 0;
        run.sweep.configs.push_back(c);
    }
    // Times 10, 5, 20 ms; RMSE 0.2, 0.15, 0.05.
    const double ms[] = {10, 5, 20}, rmse[] = {0.2, 0.15, 0.05};
    for (size_t c = 0; c < 3; ++c) {
        ViewResult v;
        v.scene = "s", v.viewpoint = "camera", v.config = c;
        v.gpuMs = v.gpuMsMin = v.gpuMsMax = ms[c];
        v.baselineMs = 10;
        v.error.rmse = rmse[c], v.error.psnrGeometrySrgb = v.error.psnrFullSrgb = 20;
        v.error.rmseInterior = NAN;
        run.views.push_back(v);
    }
    run.shards = nlohmann::json::array({{{"shard", "1/1"}, {"hostname", "h"}, {"rows", 3}}});
    run.summary = summarize(run.views, 3, 0);
    return run;
}
} // namespace

TEST(BenchShard, ResultsJsonReadsBackWhatItWrote) {
    const BenchRun run = smallRun();
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/results_roundtrip";
    std::filesystem::create_directories(dir);
    writeFileAtomically(dir + "/results.json", dumpJson(resultsJson(run)));
    BenchRun back = readResults(dir);
    ASSERT_EQ(back.sweep.configs.size(), 3u);
    EXPECT_EQ(back.sweep.baseline, 0u);
    EXPECT_EQ(back.sweep.configs[2].settings, run.sweep.configs[2].settings);
    ASSERT_EQ(back.views.size(), 3u);
    EXPECT_EQ(back.views[1].error.rmse, 0.15);
    EXPECT_TRUE(std::isnan(back.views[1].error.rmseInterior)); // NaN written as null, read as NaN
    EXPECT_EQ(back.views[1].baselineMs, 10);
    back.summary = summarize(back.views, 3, 0);
    EXPECT_EQ(back.summary[1].timeRatio, 0.5);
    // A file that lies: one line naming the field.
    nlohmann::json j = resultsJson(run);
    j["results"][1]["config"] = 7;
    writeFileAtomically(dir + "/results.json", dumpJson(j));
    try {
        readResults(dir);
        ADD_FAILURE() << "accepted a row of configuration 7";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("results[1]: 'config' 7"), std::string::npos) << e.what();
    }
}

TEST(BenchShard, AResultsFileThatLiesIsRefusedNamingTheField) {
    // A shard's folder comes from another machine: impossible metrics, unknown views, repeated rows
    // and wrongly-typed facts are each one error naming the file and the field, never merged.
    const BenchRun run = smallRun();
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/results_lies";
    std::filesystem::create_directories(dir);
    const struct {
        const char* name;
        std::function<void(nlohmann::json&)> lie;
        const char* expect;
    } cases[] = {
        {"negative RMSE", [](nlohmann::json& j) { j["results"][1]["rmse"] = -0.1; }, "results[1].rmse"},
        {"NaN RMSE", [](nlohmann::json& j) { j["results"][1]["rmse"] = nullptr; }, "results[1].rmse is not a finite number"},
        {"AO outside [0, 1]", [](nlohmann::json& j) { j["results"][0]["max_abs"] = 1.5; }, "results[0].max_abs"},
        {"bias past 1", [](nlohmann::json& j) { j["results"][0]["bias"] = -3; }, "results[0].bias"},
        {"min above median", [](nlohmann::json& j) { j["results"][2]["gpu_ms_min"] = 99.0; }, "results[2].gpu_ms_min"},
        {"unknown view", [](nlohmann::json& j) { j["results"][1]["viewpoint"] = "orbit 9"; }, "results[1].viewpoint"},
        {"unknown scene", [](nlohmann::json& j) { j["results"][1]["scene"] = "other"; }, "results[1].scene"},
        {"repeated row", [](nlohmann::json& j) { j["results"][2]["config"] = 1; }, "results[2] measures"},
        {"size a number", [](nlohmann::json& j) { j["size"] = 64; }, "facts.size is not a string"},
        {"scene name a list", [](nlohmann::json& j) { j["scenes"][0]["name"] = {1}; }, "facts.scenes[0].name is not a string"},
        {"views a string", [](nlohmann::json& j) { j["views_per_scene"] = "1"; }, "facts.views_per_scene is not an integer"},
        {"view index past the count", [](nlohmann::json& j) { j["scenes"][0]["viewpoints"][0]["index"] = 5; }, "outside [0, 0]"},
        {"a huge label", [](nlohmann::json& j) { j["configurations"][1]["label"] = std::string(5000, 'x'); }, "longer than 4096 bytes"},
        {"a bad shard", [](nlohmann::json& j) { j["shards"][0]["shard"] = "3/2"; }, "shards[0].shard"},
        {"no reference definition", [](nlohmann::json& j) { j["reference"].erase("definition"); }, "facts.reference has no 'definition'"},
        {"pixels a string", [](nlohmann::json& j) { j["results"][0]["pixels"] = "many"; }, "'pixels' is not an integer"},
        {"not an object", [](nlohmann::json& j) { j = nlohmann::json::array(); }, "the top level is not an object"},
    };
    for (const auto& c : cases) {
        nlohmann::json j = resultsJson(run);
        c.lie(j);
        writeFileAtomically(dir + "/results.json", dumpJson(j));
        const std::string e = ssaotest::errorOf([&] { readResults(dir); });
        EXPECT_NE(e.find("results.json"), std::string::npos) << c.name << ": " << e;
        EXPECT_NE(e.find(c.expect), std::string::npos) << c.name << ": " << e;
        EXPECT_EQ(e.find("json.exception"), std::string::npos) << c.name << ": " << e;
    }
}

TEST(BenchShard, TheAnswerIsTheRowTheQuestionAsksFor) {
    const BenchRun run = smallRun();
    EXPECT_EQ(answer(run, Question{12, 0}), 1u);   // within 12 ms: 5 ms (0.15) beats 10 ms (0.2)
    EXPECT_EQ(answer(run, Question{25, 0}), 2u);   // within 25 ms: the most accurate
    EXPECT_EQ(answer(run, Question{0, 0.16}), 1u); // at most 0.16: the fastest such
    EXPECT_EQ(answer(run, Question{0, 0.1}), 2u);
    EXPECT_EQ(answer(run, Question{4, 0}), std::string::npos); // nothing that fast
    EXPECT_EQ(answer(run, Question{12, 0.1}), std::string::npos);
}

TEST(BenchShard, AssignmentsReproduceTheSettings) {
    Settings s = defaultSettings();
    applyAssignment(s, "ao.technique=gtao");
    applyAssignment(s, "gtao.quality=low");
    applyAssignment(s, "ao.radius_mode=world");
    applyAssignment(s, "ao.radius=0.0346410162");
    applyAssignment(s, "denoise.kind=none");
    Settings back = defaultSettings();
    for (const auto& a : assignments(s))
        applyAssignment(back, a);
    EXPECT_EQ(toEffectiveJson(back), toEffectiveJson(s));
    EXPECT_EQ(back.ao.radius, s.ao.radius); // 9 digits: the float survives
}

TEST(BenchShard, Base64IsRfc4648) {
    EXPECT_EQ(base64(""), "");
    EXPECT_EQ(base64("f"), "Zg==");
    EXPECT_EQ(base64("fo"), "Zm8=");
    EXPECT_EQ(base64("foo"), "Zm9v");
    EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
    EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(BenchShard, TheHtmlReportIsOfflineAndNamesEveryPoint) {
    const BenchRun run = smallRun();
    const std::string html = benchHtml(run, std::string(SSAOLAB_TEST_TMP) + "/no_thumbs");
    EXPECT_EQ(html.find("http://"), std::string::npos); // no network: nothing fetched from anywhere
    EXPECT_EQ(html.find("https://"), std::string::npos);
    EXPECT_EQ(html.find("<script src"), std::string::npos);
    for (const auto& c : run.sweep.configs) // every point has a hover text naming it
        EXPECT_NE(html.find("<title>" + c.label), std::string::npos) << c.label;
    EXPECT_NE(html.find("class=\"sortable\""), std::string::npos);
    EXPECT_NE(html.find("not measured by these runs"), std::string::npos); // missing thumbnails say so
}
