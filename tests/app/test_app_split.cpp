// The split view: chain B of the same frame graph (sharing the G-buffer), comparing composites or
// AO buffers, their signed difference, and a divider that can be dragged.
#include "gl_fixture.h"
#include "gl/readback.h"
#include "ui_driver.h"

#include "test_util.h"

#include <filesystem>

using namespace ssao;
using namespace ssaotest;

namespace {
class AppSplit : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        AppOptions o;
        o.userPresetDir = std::string(SSAOLAB_TEST_TMP) + "/split_presets";
        o.renderScale = 0.3f;
        // These tests count the SSAO chain's passes and idle frames; the reference's background
        // trace (and its upload pass) has its own tests in test_app_reference.cpp.
        o.reference = false;
        ui_ = std::make_unique<UiDriver>(o);
        ui_->settle();
    }
    void TearDown() override {
        ui_.reset();
        GlTest::TearDown();
    }
    double meanOf(const std::string& buffer, int channels = 1) {
        const Image img = readBack(ui_->app().renderer().texture(buffer), channels);
        double s = 0;
        for (float v : img.data)
            s += v;
        return s / double(img.data.size());
    }
    std::unique_ptr<UiDriver> ui_;
};
using V = std::vector<std::string>;
} // namespace

TEST_F(AppSplit, AoOnOffAddsOneCompositeNotASecondRenderer) {
    ui_->click("mode#split");
    ui_->settle();
    ASSERT_EQ(ui_->app().view().mode, ViewMode::Split);
    ASSERT_EQ(ui_->app().view().splitKind, SplitKind::AoOnOff);
    // Entering the split view ran B's composite alone: the G-buffer and the AO are shared.
    EXPECT_EQ(ui_->app().frames().lastReport().ran(), V{"b.composite"});
    EXPECT_EQ(ui_->app().renderer().graph().resolve("b.ao.denoised"), "ao.denoised");
    EXPECT_LT(meanOf("composite", 3), meanOf("b.composite", 3)); // with AO the frame is darker
    // A camera move re-renders one G-buffer for both halves.
    ui_->app().cameraController().rotate(30, 0);
    ui_->app().frames().keepAwake();
    ui_->settle();
    const auto& order = ui_->app().renderer().graph().passOrder();
    EXPECT_EQ(std::count(order.begin(), order.end(), "gbuffer"), 1);
    EXPECT_EQ(order, (V{"gbuffer", "ao", "denoise", "composite", "b.composite"}));
}

TEST_F(AppSplit, PresetBRendersItsOwnAoOnTheSharedGBuffer) {
    ui_->app().view().mode = ViewMode::Split;
    ui_->app().view().splitKind = SplitKind::Preset;
    ui_->app().view().splitPresetB = "crytek-sphere";
    ui_->app().view().splitBuffer = "ao.raw"; // compare AO buffers, not only composites
    ui_->app().frames().keepAwake();
    ui_->settle();
    Renderer& r = ui_->app().renderer();
    ASSERT_TRUE(r.settingsB().has_value());
    EXPECT_EQ(r.settingsB()->kernel.shape, KernelShape::Sphere);
    EXPECT_LT(meanOf("b.ao.raw"), meanOf("ao.raw") - 0.1); // the sphere kernel's false occlusion
    ASSERT_NE(ui_->app().frames().views().find("ao.raw"), nullptr);
    ASSERT_NE(ui_->app().frames().views().find("b.ao.raw"), nullptr);
    // The inspector follows the half under the cursor.
    const ImVec4 v = ui_->rect("view#main");
    ui_->frame(v.x + (v.z - v.x) * 0.9f, v.y + (v.w - v.y) * 0.8f);
    ui_->frame(v.x + (v.z - v.x) * 0.9f, v.y + (v.w - v.y) * 0.8f);
    EXPECT_EQ(ui_->app().view().hoverChain, 1);
    const auto& pi = ui_->app().inspection();
    ASSERT_TRUE(pi.has_value());
    ASSERT_TRUE(pi->geometry) << "the floor is under the cursor";
    EXPECT_EQ(int(pi->taps.size()), r.settingsB()->kernel.samples);
}

TEST_F(AppSplit, DifferenceViewIsGreyWhereAEqualsBAndColouredWhereItDiffers) {
    ui_->app().view().mode = ViewMode::Split;
    ui_->app().view().splitKind = SplitKind::Preset;
    ui_->app().view().splitPresetB = "crytek-sphere";
    ui_->app().view().splitBuffer = "ao.raw";
    ui_->app().view().splitDifference = true;
    ui_->app().frames().keepAwake();
    ui_->settle();
    Renderer& r = ui_->app().renderer();
    const auto& d = ui_->app().frames().views().difference(r, "ao.raw", "b.ao.raw", ui_->app().view().diffScale);
    const Image img = readBack(d.target.texture(), 3);
    const Image mask = readBack(r.texture("gbuffer.depth"), 1);
    long red = 0, geometry = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (mask.at(x * mask.width / img.width, y * mask.height / img.height) > 0) {
                ++geometry;
                red += img.at(x, y, 0) > 0.6f && img.at(x, y, 2) < 0.4f; // A (hemisphere) brighter than B
            }
    EXPECT_GT(red, geometry / 3) << "the sphere kernel darkens most surfaces";
    // Identical halves: the difference is uniformly grey.
    ui_->app().view().splitKind = SplitKind::AoOnOff;
    ui_->app().frames().keepAwake();
    ui_->settle();
    const auto& same = ui_->app().frames().views().difference(r, "ao.raw", "b.ao.raw", 100.0f);
    const Image g = readBack(same.target.texture(), 3);
    for (size_t i = 0; i < g.data.size(); i += 3)
        ASSERT_TRUE(std::abs(g.data[i] - 0.5f) < 0.01f || std::abs(g.data[i] - 0.12f) < 0.01f) << i;
}

TEST_F(AppSplit, TheDividerCanBeDraggedWithoutMovingTheCamera) {
    ui_->click("mode#split");
    ui_->settle();
    const Camera before = ui_->app().cameraController().camera();
    const ImVec4 d = ui_->rect("split#divider");
    const ImVec4 v = ui_->rect("view#main");
    const float x = (d.x + d.z) * 0.5f, y = (d.y + d.w) * 0.5f;
    ui_->drag(x, y, v.x + (v.z - v.x) * 0.25f, y);
    EXPECT_NEAR(ui_->app().view().splitPosition, 0.25f, 0.02f);
    EXPECT_EQ(ui_->app().cameraController().camera().eye, before.eye);
}

TEST_F(AppSplit, TheDividerDragsFromAnywhereAlongItsLine) {
    // A user grabbed the line above and below its dot: that orbited the camera instead.
    ui_->click("mode#split");
    ui_->settle();
    const ImVec4 v = ui_->rect("view#main");
    for (float fy : {0.08f, 0.3f, 0.92f}) {
        const Camera before = ui_->app().cameraController().camera();
        const ImVec4 d = ui_->rect("split#divider");
        const float x = (d.x + d.z) * 0.5f + 3.0f, y = d.y + (d.w - d.y) * fy;
        const float to = ui_->app().view().splitPosition > 0.5f ? 0.3f : 0.7f;
        ui_->drag(x, y, v.x + (v.z - v.x) * to, y);
        EXPECT_NEAR(ui_->app().view().splitPosition, to, 0.02f) << "grabbed at " << fy << " of its height";
        EXPECT_EQ(ui_->app().cameraController().camera().eye, before.eye) << fy;
    }
}
