// Benchmark bookkeeping: medians, the Pareto front, and per-configuration summaries with ratios to
// the baseline (known inputs → known outputs).
#include "metrics/bench_summary.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ssao;

TEST(BenchSummary, MedianOfOddEvenAndEmpty) {
    EXPECT_EQ(median({3, 1, 2}), 2);
    EXPECT_EQ(median({4, 1, 3, 2}), 2.5);
    EXPECT_TRUE(std::isnan(median({})));
}

TEST(BenchSummary, ParetoFrontKeepsOnlyUndominatedPoints) {
    // (time, error): a (1, 0.5) b (2, 0.3) c (3, 0.35) dominated by b, d (4, 0.1), e (2, 0.3) tie with b,
    // f NaN error never on the front.
    const std::vector<double> t = {1, 2, 3, 4, 2, 5}, e = {0.5, 0.3, 0.35, 0.1, 0.3, NAN};
    const std::vector<bool> f = paretoFront(t, e);
    EXPECT_EQ(f, (std::vector<bool>{true, true, false, true, true, false}));
}

TEST(BenchSummary, SummariesAverageViewsAndRatioToTheBaseline) {
    auto view = [](size_t c, double ms, double rmse, double psnr) {
        ViewResult v;
        v.config = c;
        v.gpuMs = ms, v.gpuMsMin = ms - 1, v.gpuMsMax = ms + 1;
        v.error.rmse = rmse, v.error.mae = rmse / 2, v.error.bias = -rmse;
        v.error.psnrGeometrySrgb = psnr, v.error.psnrFullSrgb = psnr + 10;
        v.error.rmseEdge = rmse * 2, v.error.rmseInterior = NAN; // no interior in these views
        v.error.ssim = 0.9;
        return v;
    };
    // Config 0 (baseline): views with RMSE 0.1 and 0.3 → sqrt((0.01 + 0.09) / 2) = sqrt(0.05).
    // Config 1: twice as fast, RMSE 0.1 in both views.
    const std::vector<ViewResult> views = {view(0, 10, 0.1, 20), view(0, 20, 0.3, 30), view(1, 5, 0.1, 20),
                                           view(1, 10, 0.1, 20)};
    const auto s = summarize(views, 3, 0);
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0].views, 2);
    EXPECT_DOUBLE_EQ(s[0].gpuMs, 15.0);
    EXPECT_DOUBLE_EQ(s[0].gpuMsMin, 9.0);
    EXPECT_DOUBLE_EQ(s[0].gpuMsMax, 21.0);
    EXPECT_NEAR(s[0].rmse, std::sqrt(0.05), 1e-12);
    EXPECT_NEAR(s[0].bias, -0.2, 1e-12);
    // PSNR of the mean MSE: MSEs 1e-2 and 1e-3 → mean 5.5e-3 → 22.596 dB (not the mean of the PSNRs).
    EXPECT_NEAR(s[0].psnrGeometrySrgb, 10 * std::log10(1 / 5.5e-3), 1e-9);
    EXPECT_NEAR(s[0].rmseEdge, std::sqrt((0.04 + 0.36) / 2), 1e-12);
    EXPECT_TRUE(std::isnan(s[0].rmseInterior));
    EXPECT_DOUBLE_EQ(s[0].timeRatio, 1.0);
    EXPECT_DOUBLE_EQ(s[1].timeRatio, 7.5 / 15.0);
    EXPECT_NEAR(s[1].rmseRatio, 0.1 / std::sqrt(0.05), 1e-12);
    EXPECT_TRUE(s[1].pareto);  // faster and more accurate
    EXPECT_FALSE(s[0].pareto); // dominated by config 1
    EXPECT_EQ(s[2].views, 0);  // never measured: NaN, not on the front
    EXPECT_TRUE(std::isnan(s[2].rmse));
    EXPECT_FALSE(s[2].pareto);
}
