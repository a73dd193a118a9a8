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
    std::vector<ViewResult> views = {view(0, 10, 0.1, 20), view(0, 20, 0.3, 30), view(1, 5, 0.1, 20),
                                     view(1, 10, 0.1, 20)};
    views[0].viewpoint = views[2].viewpoint = "a";
    views[1].viewpoint = views[3].viewpoint = "b";
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
    EXPECT_DOUBLE_EQ(s[1].timeRatio, 0.5); // 5/10 and 10/20: each row against its own view's baseline
    EXPECT_DOUBLE_EQ(views[3].timeRatio, 0.5);
    EXPECT_NEAR(s[1].rmseRatio, 0.1 / std::sqrt(0.05), 1e-12);
    EXPECT_TRUE(s[1].pareto);  // faster and more accurate
    EXPECT_FALSE(s[0].pareto); // dominated by config 1
    EXPECT_EQ(s[2].views, 0);  // never measured: NaN, not on the front
    EXPECT_TRUE(std::isnan(s[2].rmse));
    EXPECT_FALSE(s[2].pareto);
    EXPECT_EQ(s[0].unsureTimeViews, 0); // every frame within 1 ms of its median
}

TEST(BenchSummary, AViewWhoseFramesVariedPastTwiceTheMedianMarksItsTimeUnsure) {
    // One view's median of 20.2 ms with a slowest frame of 77.8 ms.
    ViewResult steady, spread;
    steady.config = spread.config = 0;
    steady.gpuMs = 10, steady.gpuMsMin = 9, steady.gpuMsMax = 19.9;
    spread.gpuMs = 20.2, spread.gpuMsMin = 19, spread.gpuMsMax = 77.8;
    steady.viewpoint = "a", spread.viewpoint = "b";
    std::vector<ViewResult> one = {steady}, two = {steady, spread};
    EXPECT_EQ(summarize(one, 1, 0)[0].unsureTimeViews, 0);
    EXPECT_EQ(summarize(two, 1, 0)[0].unsureTimeViews, 1);
}

TEST(BenchSummary, RowsFromTwoMachinesAreRankedByTheirOwnBaselines) {
    // Shard 1 ran on a machine twice as fast as shard 2: config 1 (shard 1) takes 4 ms against its
    // baseline's 8, config 2 (shard 2) 12 ms against its baseline's 16. In milliseconds config 2
    // would look 3x slower; against their own baselines they are 0.5 and 0.75.
    auto row = [](size_t c, double ms, double base, double rmse, int shard) {
        ViewResult v;
        v.scene = "s", v.viewpoint = "camera", v.config = c, v.shard = shard;
        v.gpuMs = v.gpuMsMin = v.gpuMsMax = ms;
        v.baselineMs = base;
        v.error.rmse = rmse;
        v.error.psnrGeometrySrgb = v.error.psnrFullSrgb = 20;
        return v;
    };
    std::vector<ViewResult> views = {row(0, 8, NAN, 0.2, 1), row(1, 4, 8, 0.3, 1), row(2, 12, 16, 0.1, 2)};
    const auto s = summarize(views, 3, 0);
    EXPECT_DOUBLE_EQ(s[0].timeRatio, 1.0);
    EXPECT_DOUBLE_EQ(s[1].timeRatio, 0.5);
    EXPECT_DOUBLE_EQ(s[2].timeRatio, 0.75);
    EXPECT_TRUE(s[1].pareto && s[2].pareto); // fastest; most accurate
    EXPECT_FALSE(s[0].pareto);               // 1.0x, RMSE 0.2: config 2 is faster and better
}
