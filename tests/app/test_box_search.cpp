// tune --engine's search, on functions whose optimum is known: it finds a minimum in the interior,
// it escapes a local basin by its second start, it widens a wall where the optimum lies beyond the
// search range (as far as the range allowed), and it reports a wall it could not move.
#include "commands/tune/box_search.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ssao;

namespace {
// A scorer from a function of one point, counting the points it scored.
BatchScorer scorer(std::function<double(const std::vector<double>&)> f, int* points) {
    return [f, points](const std::vector<std::vector<double>>& pts) {
        std::vector<double> out;
        for (const auto& p : pts)
            out.push_back(f(p)), ++*points;
        return out;
    };
}
} // namespace

TEST(BoxSearch, FindsAnInteriorMinimumInLogAndLinearUnits) {
    // (log x - log 2)^2 + (y - 0.3)^2 over x in [0.25, 4] (log) and y in [0, 1].
    auto f = [](const std::vector<double>& p) { return std::pow(std::log(p[0] / 2.0), 2) + std::pow(p[1] - 0.3, 2); };
    int points = 0;
    const std::vector<BoxDim> dims = {{0.25, 4, true, 1e-9, 1e9, 1.0}, {0, 1, false, 0, 1, 0.9}};
    const BoxResult r = boxSearch(dims, f({1.0, 0.9}), scorer(f, &points), {3, 7});
    EXPECT_NEAR(r.x[0], 2.0, 0.2);
    EXPECT_NEAR(r.x[1], 0.3, 0.05);
    EXPECT_LT(r.score, 0.01);
    EXPECT_EQ(r.walls, (std::vector<int>{0, 0}));
    EXPECT_LE(r.batches, boxSearchBatches(2, {3, 7}));
}

TEST(BoxSearch, ASecondStartEscapesTheBasinOfTheStart) {
    // Two basins on [0, 1]: a shallow one at 0.15 (where the search starts) and the deep one at 0.8.
    auto f = [](const std::vector<double>& p) {
        const double x = p[0];
        return std::min(0.5 + 10 * (x - 0.15) * (x - 0.15), 10 * (x - 0.8) * (x - 0.8));
    };
    int points = 0;
    const BoxResult r = boxSearch({{0, 1, false, 0, 1, 0.15}}, f({0.15}), scorer(f, &points), {3, 5});
    EXPECT_NEAR(r.x[0], 0.8, 0.05);
    EXPECT_LT(r.score, 0.05);
}

TEST(BoxSearch, AWallMovesAsFarAsAllowedAndOneThatCannotIsReported) {
    // The optimum at x = 12, past the search range [0.25, 4]: widened (log span 16x) it is found.
    auto f = [](const std::vector<double>& p) { return std::pow(std::log(p[0] / 12.0), 2); };
    int points = 0;
    const BoxResult wide = boxSearch({{0.25, 4, true, 1e-6, 1e6, 1.0}}, f({1.0}), scorer(f, &points), {3, 7});
    EXPECT_GT(wide.hi[0], 4.0);
    EXPECT_NEAR(wide.x[0], 12.0, 2.0);
    EXPECT_EQ(wide.walls[0], 0);
    // The engine accepts at most 5: the range widens to 5, the fit ends there, reported at the top.
    const BoxResult capped = boxSearch({{0.25, 4, true, 1e-6, 5, 1.0}}, f({1.0}), scorer(f, &points), {3, 7});
    EXPECT_DOUBLE_EQ(capped.hi[0], 5.0);
    EXPECT_NEAR(capped.x[0], 5.0, 0.1);
    EXPECT_EQ(capped.walls[0], 1);
    EXPECT_TRUE(capped.atLimit[0]);
    EXPECT_FALSE(wide.atLimit[0]);
    // Far past the range with room to widen: three widenings by the span reach it (x16 each in log).
    auto far = [](const std::vector<double>& p) { return std::pow(std::log(p[0] / 500.0), 2); };
    const BoxResult reach = boxSearch({{0.25, 4, true, 1e-6, 1e6, 1.0}}, far({1.0}), scorer(far, &points), {3, 7});
    EXPECT_NEAR(reach.x[0], 500.0, 100.0);
    // Never worse than the start: a flat function keeps it.
    const BoxResult flat = boxSearch({{0, 1, false, 0, 1, 0.4}}, 1.0, scorer([](const std::vector<double>&) { return 1.0; }, &points),
                                     {2, 3});
    EXPECT_EQ(flat.x[0], 0.4);
    EXPECT_EQ(flat.score, 1.0);
}
