// GL test support: one headless context per test binary (llvmpipe in CI — never skipped), and
// a helper that renders a scene and reads every buffer back.
#pragma once
#include "base/image.h"
#include "gl/context.h"
#include "renderer.h"
#include "settings/params.h"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace ssaotest {

struct Rendered {
    ssao::Image position, normal, depth, aoRaw, ao;
    ssao::FrameReport report;
    ssao::Camera camera;
};

// Fails the test (gtest) on any GL error raised during the test.
class GlTest : public ::testing::Test {
  protected:
    void SetUp() override;
    void TearDown() override;
};

ssao::Settings preset(const std::string& name);
ssao::Camera sceneCamera(const ssao::Scene& s);
Rendered readAll(ssao::Renderer& r);
// A renderer set up on `scene` (its own camera unless one is given); nothing rendered yet.
std::unique_ptr<ssao::Renderer> makeRenderer(const ssao::Scene& scene, const ssao::Settings& s, int w, int h,
                                             std::optional<ssao::Camera> camera = std::nullopt);
Rendered render(const std::string& scene, const ssao::Settings& s, int w, int h,
                std::optional<ssao::Camera> camera = std::nullopt);

// The counters of the G-buffer pass in the last frame (draws, triangles, draws_occluded, ...).
std::map<std::string, double> gbufferCounters(const ssao::Renderer& r);

// Mean of `img` over the frame's geometry pixels (position.w = 1).
double geometryMean(const Rendered& r, const ssao::Image& img);
double meanAbsDiff(const ssao::Image& a, const ssao::Image& b);
// The largest |a - b| (over the pixels where `mask` is non-zero, when given); inf if sizes differ.
double maxAbsDiff(const ssao::Image& a, const ssao::Image& b, const ssao::Image* mask = nullptr);
// Checks a float image: no NaN/inf anywhere and every value in [lo, hi].
::testing::AssertionResult finiteInRange(const ssao::Image& img, float lo, float hi);

} // namespace ssaotest
