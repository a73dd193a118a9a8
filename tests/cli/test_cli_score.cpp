// `render --reference --score FILE`: an AO image made elsewhere (the web peers of make peers,
// another engine) judged by the same metric code and reference as ssaolab's own frame.
#include "cli_run.h"

#include <nlohmann/json.hpp>

#include <fstream>

using namespace ssaotest;

namespace {
const std::string kView = "render --scene builtin:corner --size 96x54 --timing-frames 1 --reference --reference-rays 32 --quiet";

void writePgm(const std::string& path, int w, int h, unsigned char value) {
    std::ofstream f(path, std::ios::binary);
    f << "P5\n" << w << " " << h << "\n255\n";
    f << std::string(size_t(w) * h, char(value));
}
} // namespace

TEST(CliScore, AnImageIsJudgedAsTheFrameItselfWouldBe) {
    const std::string a = outDir("score_a"), b = outDir("score_b");
    ASSERT_EQ(ssaolab(kView + " --out " + a).exitCode, 0);
    const auto own = nlohmann::json::parse(slurp(a + "/metrics.json"));
    const std::string white = std::string(SSAOLAB_TEST_TMP) + "/score_white.pgm";
    writePgm(white, 96, 54, 255);
    const CliRun r = ssaolab(kView + " --out " + b + " --score " + a + "/ao.denoised.png --score " + white);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto m = nlohmann::json::parse(slurp(b + "/metrics.json"));
    ASSERT_EQ(m["scored"].size(), 2u);
    // The frame's own AO, as an 8-bit PNG: its error again, to within the PNG's rounding (1/510).
    const auto& self = m["scored"][0]["error"];
    EXPECT_NEAR(self["rmse"].get<double>(), own["error"]["rmse"].get<double>(), 0.003);
    EXPECT_NEAR(self["bias"].get<double>(), own["error"]["bias"].get<double>(), 0.003);
    EXPECT_NEAR(m["scored"][0]["technique"]["rmse"].get<double>(), own["error_split"]["technique"]["rmse"].get<double>(), 0.003);
    // An image of no occlusion: too bright wherever the corner occludes, by exactly 1 - reference.
    const auto& open = m["scored"][1]["error"];
    EXPECT_GT(open["bias"].get<double>(), 0.01);
    EXPECT_GE(open["rmse"].get<double>(), open["bias"].get<double>() - 1e-9); // RMS >= mean
    EXPECT_EQ(open["pixels"], own["error"]["pixels"]);
}

TEST(CliScore, BadImagesGiveOneClearLine) {
    const std::string small = std::string(SSAOLAB_TEST_TMP) + "/score_small.pgm";
    writePgm(small, 32, 18, 128);
    expectCleanFailure(ssaolab(kView + " --out " + outDir("score_c") + " --score " + small), "32x18, the render is 96x54");
    const std::string junk = std::string(SSAOLAB_TEST_TMP) + "/score_junk.png";
    std::ofstream(junk) << "not an image";
    expectCleanFailure(ssaolab(kView + " --out " + outDir("score_d") + " --score " + junk), "cannot read");
    expectCleanFailure(ssaolab("render --scene builtin:corner --size 96x54 --quiet --out " + outDir("score_e") +
                               " --score " + small),
                       "add --reference");
}
