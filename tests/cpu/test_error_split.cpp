// The additive error split (metrics/error_split.h): the technique's, the screen's and their
// interaction's shares of the total squared error sum to 1, on random images and on a known case,
// and the parts are the squares of the RMSEs the metrics report for the same pixels.
#include "metrics/error_metrics.h"
#include "metrics/error_split.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace ssao;

namespace {
struct Frame {
    int w = 37, h = 23;
    std::vector<float> ao, oracle, truth, geometry, exclude;
    SplitImages images() const {
        return {w, h, ao.data(), oracle.data(), truth.data(), geometry.data(), exclude.data()};
    }
};

Frame randomFrame(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    Frame f;
    const size_t n = size_t(f.w) * f.h;
    for (size_t i = 0; i < n; ++i) {
        f.truth.push_back(u(rng));
        f.oracle.push_back(std::clamp(f.truth.back() + 0.3f * (u(rng) - 0.6f), 0.0f, 1.0f));
        f.ao.push_back(u(rng) < 0.01f ? NAN : std::clamp(f.oracle.back() + 0.4f * (u(rng) - 0.4f), 0.0f, 1.0f));
        f.geometry.push_back(u(rng) < 0.8f ? 1.0f : 0.0f);
        f.exclude.push_back(u(rng) < 0.05f ? 1.0f : 0.0f);
    }
    return f;
}

ErrorMetrics metricsOf(const Frame& f, const std::vector<float>& test, const std::vector<float>& ref) {
    MetricsInput in;
    in.width = f.w, in.height = f.h;
    in.test = test.data(), in.reference = ref.data();
    in.geometry = f.geometry.data(), in.exclude = f.exclude.data();
    return computeErrorMetrics(in);
}
} // namespace

TEST(ErrorSplit, ThePartsSumToTheTotalOnRandomImages) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const Frame f = randomFrame(seed);
        const ErrorShares s = errorShares(f.images());
        ASSERT_GT(s.pixels, 500);
        EXPECT_NEAR(s.mseTechnique + s.mseScreen + 2.0 * s.meanCross, s.mseTotal, 1e-12 * s.mseTotal) << seed;
        EXPECT_NEAR(s.technique + s.screen + s.interaction, 1.0, 1e-12) << seed;
        // The parts are the squares of the RMSEs every report shows, over the same pixels.
        const ErrorMetrics total = metricsOf(f, f.ao, f.truth), technique = metricsOf(f, f.ao, f.oracle),
                           screen = metricsOf(f, f.oracle, f.truth);
        EXPECT_EQ(s.pixels, total.geometryPixels);
        EXPECT_NEAR(s.mseTotal, total.rmse * total.rmse, 1e-12);
        EXPECT_NEAR(s.mseTechnique, technique.rmse * technique.rmse, 1e-12);
        EXPECT_NEAR(s.mseScreen, screen.rmse * screen.rmse, 1e-12);
        // From the three RMSEs alone (a benchmark row), the same shares.
        const ErrorShares r = sharesOfMse(total.rmse * total.rmse, technique.rmse * technique.rmse,
                                          screen.rmse * screen.rmse);
        EXPECT_NEAR(r.technique, s.technique, 1e-9);
        EXPECT_NEAR(r.screen, s.screen, 1e-9);
        EXPECT_NEAR(r.interaction, s.interaction, 1e-9);
        EXPECT_DOUBLE_EQ(r.technique + r.screen + r.interaction, 1.0);
    }
}

TEST(ErrorSplit, AKnownCaseWhereTheTechniqueCancelsTheScreen) {
    // Truth 0.5, oracle 0.7 (the screen 0.2 too bright), AO 0.6: the technique's error (-0.1)
    // cancels half the screen's. e = 0.1: technique 0.01 / 0.01 = 1, screen 0.04 / 0.01 = 4,
    // interaction 2 (-0.1)(0.2) / 0.01 = -4.
    Frame f;
    f.w = 4, f.h = 2;
    f.truth.assign(8, 0.5f), f.oracle.assign(8, 0.7f), f.ao.assign(8, 0.6f);
    f.geometry.assign(8, 1.0f), f.exclude.assign(8, 0.0f);
    f.geometry[7] = 0.0f, f.ao[7] = 0.0f; // sky: not counted
    const ErrorShares s = errorShares(f.images());
    EXPECT_EQ(s.pixels, 7);
    EXPECT_NEAR(s.technique, 1.0, 1e-5);
    EXPECT_NEAR(s.screen, 4.0, 1e-5);
    EXPECT_NEAR(s.interaction, -4.0, 1e-5);
    // The user's AlphaBlendModeTest view: technique 0.2289 and screen 0.2431 RMSE for a total of 0.0885.
    const ErrorShares u = sharesOfMse(0.0885 * 0.0885, 0.2289 * 0.2289, 0.2431 * 0.2431);
    EXPECT_NEAR(u.technique, 6.69, 0.01);
    EXPECT_NEAR(u.screen, 7.55, 0.01);
    EXPECT_NEAR(u.interaction, -13.24, 0.01);
    // Errors that do not overlap add: an AO right where the oracle is, the screen all the error.
    f.ao = f.oracle;
    const ErrorShares o = errorShares(f.images());
    EXPECT_DOUBLE_EQ(o.technique, 0.0);
    EXPECT_DOUBLE_EQ(o.screen, 1.0);
    EXPECT_DOUBLE_EQ(o.interaction, 0.0);
}

TEST(ErrorSplit, NoErrorHasNoSharesAndMissingImagesAreRefused) {
    Frame f;
    f.w = 2, f.h = 1;
    f.truth = f.oracle = f.ao = {0.3f, 0.4f};
    f.geometry = {1.0f, 1.0f}, f.exclude = {0.0f, 0.0f};
    const ErrorShares s = errorShares(f.images());
    EXPECT_EQ(s.mseTotal, 0.0);
    EXPECT_TRUE(std::isnan(s.technique) && std::isnan(s.screen) && std::isnan(s.interaction));
    EXPECT_TRUE(sharesJson(s)["technique"].is_null());
    SplitImages bad = f.images();
    bad.oracle = nullptr;
    EXPECT_THROW(errorShares(bad), std::invalid_argument);
    EXPECT_EQ(errorShares(SplitImages{}).pixels, 0);
}
