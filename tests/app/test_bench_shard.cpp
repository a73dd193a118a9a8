// Splitting and answering a benchmark, pure: shards partition the work, results.json reads back
// what it wrote, the answer to a budget is the right row, report.html embeds what it names.
#include "bench/bench_answer.h"
#include "bench/bench_results.h"
#include "bench/report_html.h"
#include "bench/shard.h"
#include "settings/params.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/json_file.h"

#include <gtest/gtest.h>

#include <filesystem>
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
    run.facts = {{"scenes", {{{"name", "s"}, {"viewpoints", {{{"name", "camera"}, {"index", 0}}}}}}}};
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
