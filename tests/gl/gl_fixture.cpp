#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"

#include "scene/scene.h"

#include <cmath>
#include <memory>

namespace ssaotest {

namespace {
class GlEnvironment : public ::testing::Environment {
  public:
    void SetUp() override {
        context_ = std::make_unique<ssao::gl::HeadlessContext>();
        ssao::gl::installDebugOutput(false);
        std::printf("GL renderer: %s via %s\n", context_->renderer().c_str(), context_->platform().c_str());
    }
    void TearDown() override { context_.reset(); }

  private:
    std::unique_ptr<ssao::gl::HeadlessContext> context_;
};
const auto* const kEnv = ::testing::AddGlobalTestEnvironment(new GlEnvironment);
} // namespace

void GlTest::SetUp() {
    ssao::gl::resetGlErrorCount();
}

void GlTest::TearDown() {
    ssao::gl::pollGlErrors();
    EXPECT_EQ(ssao::gl::glErrorCount(), 0) << "OpenGL reported errors during the test";
}

ssao::Settings preset(const std::string& name) {
    return ssao::loadPreset(std::string(SSAOLAB_ASSET_DIR) + "/presets/" + name + ".json");
}

ssao::Camera sceneCamera(const ssao::Scene& s) {
    return s.camera.value_or(ssao::frameBounds(s.bounds));
}

Rendered readAll(ssao::Renderer& r) {
    Rendered out;
    out.position = ssao::readBack(r.texture("gbuffer.position"), 4);
    out.normal = ssao::readBack(r.texture("gbuffer.normal"), 3);
    out.depth = ssao::readBack(r.texture("gbuffer.depth"), 1);
    out.aoRaw = ssao::readBack(r.texture("ao.raw"), 1);
    out.ao = ssao::readBack(r.texture("ao.denoised"), 1);
    out.camera = r.camera();
    return out;
}

std::unique_ptr<ssao::Renderer> makeRenderer(const ssao::Scene& scene, const ssao::Settings& s, int w, int h,
                                             std::optional<ssao::Camera> camera) {
    auto r = std::make_unique<ssao::Renderer>(SSAOLAB_SHADER_DIR);
    r->setSize(w, h);
    r->setScene(scene);
    r->setCamera(camera.value_or(sceneCamera(scene)));
    r->setSettings(s);
    return r;
}

Rendered render(const std::string& sceneSpec, const ssao::Settings& s, int w, int h,
                std::optional<ssao::Camera> camera) {
    auto r = makeRenderer(ssao::loadScene(sceneSpec), s, w, h, camera);
    ssao::FrameReport rep = r->render();
    Rendered out = readAll(*r);
    out.report = rep;
    return out;
}

std::map<std::string, double> gbufferCounters(const ssao::Renderer& r) {
    std::map<std::string, double> m;
    for (const auto& [k, v] : r.graph().pass("gbuffer")->counters())
        m[k] = v;
    return m;
}

double geometryMean(const Rendered& r, const ssao::Image& img) {
    const ssao::Image mask = r.position.channel(3);
    return ssao::stats(img, &mask).mean;
}

double meanAbsDiff(const ssao::Image& a, const ssao::Image& b) {
    double sum = 0;
    for (size_t i = 0; i < a.data.size() && i < b.data.size(); ++i)
        sum += std::abs(double(a.data[i]) - double(b.data[i]));
    return a.data.empty() ? 0.0 : sum / double(a.data.size());
}

double maxAbsDiff(const ssao::Image& a, const ssao::Image& b, const ssao::Image* mask) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) return INFINITY;
    double worst = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < a.channels; ++c)
                if (!mask || mask->at(x, y) != 0.0f)
                    worst = std::max(worst, double(std::abs(a.at(x, y, c) - b.at(x, y, c))));
    return worst;
}

::testing::AssertionResult finiteInRange(const ssao::Image& img, float lo, float hi) {
    long bad = 0, out = 0;
    float mn = INFINITY, mx = -INFINITY;
    for (float v : img.data) {
        if (!std::isfinite(v))
            ++bad;
        else if (v < lo || v > hi)
            ++out;
        if (std::isfinite(v)) mn = std::min(mn, v), mx = std::max(mx, v);
    }
    if (bad == 0 && out == 0) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << bad << " non-finite and " << out << " out-of-range values (min " << mn << ", max " << mx << ")";
}

} // namespace ssaotest
