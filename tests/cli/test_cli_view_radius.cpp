// Two things a new user misread, through the whole program: a close-up of a scene whose scene-mode
// radius is wider than the view gets one warning naming the world radius that matches the view
// (metrics/radius_check.h); and the error split's shares of the squared error (metrics/error_split.h)
// are in metrics.json and the summary line, summing to 1 where the two RMSEs do not add up.
#include "cli_run.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <regex>

using namespace ssaotest;

namespace {
// 0.4 units from the showcase's red sphere: the view spans about half a unit, the scene radius 0.86.
const char* kCloseUp = "--camera -1.5,0.8,-0.8,-1.5,0.8,-2";

long warningLines(const std::string& err) {
    long n = 0;
    for (size_t at = 0; (at = err.find("ssaolab: warning: ", at)) != std::string::npos; ++at)
        ++n;
    return n;
}
} // namespace

TEST(CliViewRadius, ACloseUpWarnsOnceWithTheWorldRadiusThatMatchesTheView) {
    const CliRun close = ssaolab(std::string("render --scene builtin:showcase --size 64x36 --timing-frames 1 --quiet ") +
                                 kCloseUp + " --out " + outDir("view_radius_close"));
    ASSERT_EQ(close.exitCode, 0) << close.err;
    std::printf("%s", close.err.c_str());
    EXPECT_EQ(warningLines(close.err), 1) << close.err;
    const std::regex hint("ssaolab: warning: the AO radius ([0-9.]+) units \\(ao.radius_mode=scene[^\\n]*"
                          "\\(([0-9.]+) units across[^\\n]*--set ao.radius=([0-9.e-]+) \\(world units\\)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(close.err, m, hint)) << close.err;
    const double radius = std::stod(m[1]), extent = std::stod(m[2]), suggested = std::stod(m[3]);
    EXPECT_NEAR(radius, 0.05 * std::sqrt(12.0 * 12 + 3 * 3 + 12 * 12), 0.01) << "5 % of the diagonal";
    EXPECT_LT(extent, 1.0);
    EXPECT_GT(radius, 0.6 * extent);
    EXPECT_NEAR(suggested, 0.05 * extent, 0.002);

    // Following it: no warning (a world radius is the user's own); the showcase's own view: none either.
    const CliRun world = ssaolab(std::string("render --scene builtin:showcase --size 64x36 --timing-frames 1 --quiet ") +
                                 kCloseUp + " --set ao.radius=" + std::string(m[3]) + " --out " +
                                 outDir("view_radius_world"));
    ASSERT_EQ(world.exitCode, 0) << world.err;
    EXPECT_EQ(world.err.find("the AO radius"), std::string::npos) << world.err;
    const CliRun framed = ssaolab("render --scene builtin:showcase --size 64x36 --timing-frames 1 --quiet --out " +
                                  outDir("view_radius_framed"));
    ASSERT_EQ(framed.exitCode, 0) << framed.err;
    EXPECT_EQ(framed.err.find("the AO radius"), std::string::npos) << framed.err;
}

TEST(CliViewRadius, TheSplitsSharesAddUpInMetricsAndTheSummary) {
    const std::string out = outDir("split_shares");
    const CliRun r = ssaolab("render --scene builtin:showcase --size 64x36 --timing-frames 1 --reference "
                             "--reference-rays 8 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("shares of the squared error: technique "), std::string::npos) << r.out;
    const nlohmann::json m = nlohmann::json::parse(slurp(out + "/metrics.json"));
    const nlohmann::json& sp = m["error_split"];
    const double t = sp["shares"]["technique"], s = sp["shares"]["screen"], i = sp["shares"]["interaction"];
    EXPECT_NEAR(t + s + i, 1.0, 1e-9);
    const double total = m["error"]["rmse"], rt = sp["technique"]["rmse"], rs = sp["screen"]["rmse"];
    EXPECT_NEAR(t, rt * rt / (total * total), 1e-6);
    EXPECT_NEAR(s, rs * rs / (total * total), 1e-6);
    EXPECT_NE(sp["shares"]["how_to_read"].get<std::string>().find("negative interaction"), std::string::npos);
}

TEST(CliViewRadius, AFrameThatReadsTheSecondLayerIsSplitAgainstATwoLayerOracle) {
    // As bench splits its two-layer rows: a one-layer oracle would charge the technique for what its
    // own second layer sees ("technique 1.17 + screen 0.64 + interaction -0.81").
    for (const std::string layers : {"false", "true"}) {
        const std::string out = outDir("split_layers_" + layers);
        const CliRun r = ssaolab("render --scene builtin:hidden --size 64x36 --timing-frames 1 --reference "
                                 "--reference-rays 8 --quiet --set ao.technique=vbao --set gbuffer.second_layer=" +
                                 layers + " --out " + out);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const nlohmann::json m = nlohmann::json::parse(slurp(out + "/metrics.json"));
        EXPECT_EQ(m["error_split"]["oracle"]["layers"].get<int>(), layers == "true" ? 2 : 1);
    }
}

// bench and tune take R as --radius-scene x the diagonal: the same check on every view's reference,
// one warning per scene naming the --radius-scene that fits the view; --camera sets the first view
// as render takes it; a framed view warns nothing.
TEST(CliViewRadius, BenchAndTuneWarnOnceAScenePerViewAndOfferTheRadiusScene) {
    const std::string sweep = writeTemp("view_radius_sweep.json", R"({"name": "r", "groups": [{"name": "g", "set": {"ao.technique": "gtao"}}]})");
    const std::regex hint("ssaolab: warning: builtin:showcase: R = ([0-9.]+) units[^\\n]*view '[^']+' spans "
                          "\\(([0-9.]+) units across[^\\n]*--radius-scene ([0-9.e-]+) gives the view 5% of its extent");
    for (const std::string& cmd :
         {"bench --views 2 --frames 1 --warmup 0 --no-plot --quiet --sweep " + sweep + " --out " + outDir("view_radius_bench"),
          "tune --technique gtao --views 2 --rounds 1 --grid 3 --knob gtao.falloff_range --save-overfit --quiet --out " +
              outDir("view_radius_tune") + ".json"}) {
        const std::string base = cmd + " --scene builtin:showcase --size 64x36 --reference-rays 4 ";
        const CliRun close = ssaolab(base + kCloseUp);
        ASSERT_EQ(close.exitCode, 0) << cmd << "\n" << close.err;
        EXPECT_EQ(close.err.find("gives the view"), close.err.rfind("gives the view")) << "once: " << cmd << "\n" << close.err;
        std::smatch m;
        ASSERT_TRUE(std::regex_search(close.err, m, hint)) << cmd << "\n" << close.err;
        const double radius = std::stod(m[1]), extent = std::stod(m[2]), fraction = std::stod(m[3]);
        EXPECT_GT(radius, 0.6 * extent) << cmd;
        EXPECT_LT(fraction, 0.05) << cmd;
        EXPECT_GT(fraction, 0.0) << cmd;
        const CliRun framed = ssaolab(base);
        ASSERT_EQ(framed.exitCode, 0) << cmd << "\n" << framed.err;
        EXPECT_EQ(framed.err.find("--radius-scene"), std::string::npos) << cmd << "\n" << framed.err;
    }
    expectCleanFailure(ssaolab("bench --scene builtin:showcase --camera 1,2 --out " + outDir("view_radius_bad")), "--camera");
}
