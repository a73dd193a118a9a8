// Golden images of the seed presets on the showcase scene, compared with a tolerance.
// The goldens are the CLI's own ao.denoised.png for each preset (`make goldens` regenerates them; look at
// them before committing). This test only compares: it never writes and never skips.
#include "gl_fixture.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace ssao;
using namespace ssaotest;

namespace {
class Golden : public GlTest, public ::testing::WithParamInterface<const char*> {};
} // namespace

TEST_P(Golden, SeedPresetOnShowcaseMatchesGolden) {
    const std::string name = GetParam();
    Rendered r = render("builtin:showcase", preset(name), 320, 180);
    const std::string path = std::string(SSAOLAB_ASSET_DIR) + "/golden/showcase_" + name + "_ao.png";
    ASSERT_TRUE(std::filesystem::exists(path)) << "missing golden " << path;
    Image golden = readPng(path);
    ASSERT_EQ(golden.width, r.ao.width);
    ASSERT_EQ(golden.height, r.ao.height);
    // Geometry pixels only: the sky's AO is trivially 1 (and the PNG view paints it dark grey).
    double sum = 0;
    long big = 0, n = 0;
    for (size_t i = 0; i < r.ao.data.size(); ++i) {
        if (r.position.data[i * 4 + 3] == 0.0f) continue;
        double d = std::abs(std::clamp(r.ao.data[i], 0.0f, 1.0f) - golden.data[i * size_t(golden.channels)]);
        sum += d;
        big += d > 0.05;
        ++n;
    }
    ASSERT_GT(n, 1000);
    const double mean = sum / double(n);
    EXPECT_LT(mean, 0.004) << name;
    EXPECT_LT(double(big) / double(n), 0.005) << name;
}

INSTANTIATE_TEST_SUITE_P(Seeds, Golden,
                         ::testing::Values("learnopengl", "seed000", "crytek-sphere", "seed001", "seed003",
                                           "seed003-separable"),
                         [](const auto& info) {
                             std::string n = info.param;
                             for (auto& c : n)
                                 if (c == '-') c = '_';
                             return n;
                         });
