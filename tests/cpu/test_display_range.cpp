// The one display mapping: natural ranges for physical quantities, robust percentile fits for the
// rest, over geometry pixels only.
#include "display/display_range.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ssao;

namespace {
Image ramp(int w, int h, float lo, float hi) {
    Image img{w, h, 1, {}};
    for (int i = 0; i < w * h; ++i)
        img.data.push_back(lo + (hi - lo) * float(i) / float(w * h - 1));
    return img;
}
ResourceDesc desc(Display d, int channels = 1) {
    ResourceDesc r;
    r.display = d;
    r.channels = channels;
    return r;
}
} // namespace

TEST(DisplayRange, PhysicalQuantitiesKeepTheirNaturalRange) {
    const Image img = ramp(64, 64, 0.9f, 1.0f); // AO that barely varies
    const DisplayRange ao = displayRange(img, desc(Display::Unit), nullptr, {});
    EXPECT_EQ(ao.lo.x, 0.0f);
    EXPECT_EQ(ao.hi.x, 1.0f);
    EXPECT_FALSE(ao.fitted);
    const DisplayRange n = displayRange(img, desc(Display::Direction, 3), nullptr, {});
    EXPECT_EQ(n.lo, glm::vec3(-1.0f));
    EXPECT_FALSE(needsFit(desc(Display::Color), ViewStyle{true, false}));
    // Asked to fit, AO is stretched over its own range.
    const DisplayRange fitted = displayRange(img, desc(Display::Unit), nullptr, ViewStyle{true, false});
    EXPECT_TRUE(fitted.fitted);
    EXPECT_NEAR(fitted.lo.x, 0.901f, 2e-3f);
    EXPECT_NEAR(fitted.hi.x, 0.999f, 2e-3f);
}

TEST(DisplayRange, DepthIsFittedOverGeometryIgnoringSkyAndOutliers) {
    // Depth 10..20 over geometry, sky = 0, and 0.5 % of pixels at 1e6 (a far stray triangle).
    Image depth{100, 100, 1, {}}, mask{100, 100, 1, {}};
    for (int i = 0; i < 100 * 100; ++i) {
        const bool sky = i < 3000;
        const bool stray = i % 200 == 7;
        const float v = sky ? 0.0f : stray ? 1e6f : 10.0f + 10.0f * float(i - 3000) / 7000.0f;
        depth.data.push_back(v);
        mask.data.push_back(sky ? 0.0f : 1.0f);
    }
    const DisplayRange r = displayRange(depth, desc(Display::Scalar), &mask, {});
    EXPECT_TRUE(r.fitted);
    EXPECT_NEAR(r.lo.x, 10.1f, 0.2f);
    EXPECT_NEAR(r.hi.x, 19.9f, 0.2f); // not 1e6: the 99th percentile ignores the stray 0.5 %
    // A mask at another resolution (half) is sampled at the nearest pixel.
    Image half{50, 50, 1, std::vector<float>(2500, 1.0f)};
    EXPECT_TRUE(displayRange(depth, desc(Display::Scalar), &half, {}).fitted);
}

TEST(DisplayRange, EncodedNormalsAreDecodedAndFlatImagesGetAWidth) {
    Image img{4, 4, 3, std::vector<float>(48, 0.75f)}; // (n+1)/2 = 0.75 → n = 0.5
    ResourceDesc d = desc(Display::Direction, 3);
    d.decodeScale = 2.0f, d.decodeOffset = -1.0f;
    const DisplayRange r = displayRange(img, d, nullptr, ViewStyle{true, false});
    for (int c = 0; c < 3; ++c) {
        EXPECT_LT(r.lo[c], 0.5f);
        EXPECT_GT(r.hi[c], 0.5f);
        EXPECT_LT(r.hi[c] - r.lo[c], 0.01f);
    }
    EXPECT_NE(rangeText(r, d).find("(fitted)"), std::string::npos);
}

TEST(DisplayRange, QuantileOfNothingIsNan) {
    std::vector<float> none;
    EXPECT_TRUE(std::isnan(quantile(none, 0.5)));
    std::vector<float> v = {5, 1, 4, 2, 3};
    EXPECT_EQ(quantile(v, 0.5), 3.0f);
    EXPECT_EQ(quantile(v, 0.0), 1.0f);
    EXPECT_EQ(quantile(v, 1.0), 5.0f);
}

TEST(DisplayRange, VectorsGetOneRangePerChannel) {
    // Positions: x spans 2 units, z spans 100. One shared range would flatten x to one grey.
    Image pos{10, 10, 3, {}};
    for (int i = 0; i < 100; ++i)
        pos.data.insert(pos.data.end(), {float(i % 10) * 0.2f, 1.0f, -10.0f - float(i)});
    const DisplayRange r = displayRange(pos, desc(Display::Vector, 3), nullptr, {});
    EXPECT_NEAR(r.lo.x, 0.0f, 0.01f);
    EXPECT_NEAR(r.hi.x, 1.8f, 0.01f);
    EXPECT_NEAR(r.lo.z, -109.0f, 1.1f);
    EXPECT_NEAR(r.hi.z, -10.0f, 1.1f);
    EXPECT_NE(rangeText(r, desc(Display::Vector, 3)).find("y "), std::string::npos);
}

TEST(DisplayRange, SignedErrorsAreSymmetricAboutZero) {
    const Image img = ramp(64, 64, -0.05f, 0.2f); // mostly too bright
    const DisplayRange natural = displayRange(img, desc(Display::Signed), nullptr, {});
    EXPECT_FALSE(natural.fitted);
    EXPECT_EQ(natural.lo.x, -kSignedRange); // as error.png: saturates at a quarter
    EXPECT_EQ(natural.hi.x, kSignedRange);
    const DisplayRange fitted = displayRange(img, desc(Display::Signed), nullptr, ViewStyle{true, false});
    EXPECT_TRUE(fitted.fitted);
    EXPECT_NEAR(fitted.hi.x, 0.1975f, 2e-3f); // the 99th percentile of the larger side...
    EXPECT_EQ(fitted.lo.x, -fitted.hi.x);     // ...on both: 0 stays white, in the middle
}
