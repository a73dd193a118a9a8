// A close-up of a scene whose scene-mode radius is wider than the view (metrics/radius_check.h)
// through the explorer: the status says so once with the world radius that matches the view, the
// radius line offers it as a button, and the button switches to that world radius; the framed view
// of the same scene says nothing.
#include "gl_fixture.h"
#include "ui_driver.h"

#include <string>

using namespace ssao;
using namespace ssaotest;

namespace {
class AppRadiusHint : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        AppOptions o;
        o.userPresetDir = std::string(SSAOLAB_TEST_TMP) + "/radius_hint_presets";
        o.scene = "builtin:showcase";
        o.renderScale = 0.3f;
        o.reference = false;
        ui_ = std::make_unique<UiDriver>(o, 1600, 2600);
        ui_->settle();
    }
    void TearDown() override {
        ui_.reset();
        GlTest::TearDown();
    }
    AppCore& app() { return ui_->app(); }
    std::unique_ptr<UiDriver> ui_;
};
} // namespace

TEST_F(AppRadiusHint, ACloseUpSaysSoAndItsButtonSetsTheViewsWorldRadius) {
    ui_->frames(2);
    EXPECT_FALSE(app().frames().viewRadius().tooLarge) << "the showcase's own view: " << app().status();
    EXPECT_FALSE(ui_->has("radius#use_view"));
    EXPECT_EQ(app().status().find("--set ao.radius="), std::string::npos) << app().status();

    // 0.4 units from the red sphere: the view spans about half a unit, the scene radius is 0.86.
    Camera c = app().cameraController().camera();
    c.eye = {-1.5f, 0.8f, -0.8f};
    c.target = {-1.5f, 0.8f, -2.0f};
    c.up = {0, 1, 0};
    app().cameraController().reset(c, app().scene().bounds.radius());
    ui_->settle();
    ui_->frames(2);
    const ViewRadiusCheck vr = app().frames().viewRadius();
    ASSERT_TRUE(vr.tooLarge) << "median depth " << vr.medianDepth << ", extent " << vr.viewExtent;
    EXPECT_NE(app().status().find("--set ao.radius="), std::string::npos) << app().status();
    ASSERT_TRUE(ui_->has("radius#use_view"));
    ui_->save(std::string(SSAOLAB_TEST_TMP) + "/radius_hint.png"); // to look at what the test saw

    ui_->click("radius#use_view");
    ui_->settle();
    EXPECT_EQ(app().settings().ao.radiusMode, RadiusMode::World);
    EXPECT_FLOAT_EQ(app().settings().ao.radius, float(vr.suggested));
    EXPECT_NEAR(vr.suggested, 0.05 * vr.viewExtent, 0.01 * vr.viewExtent);
    EXPECT_NE(app().status().find("world units"), std::string::npos) << app().status();
    app().view().widgetRects.clear(); // what the next frames draw
    ui_->frames(2);
    EXPECT_FALSE(app().frames().viewRadius().tooLarge) << "a world radius is the user's own";
    EXPECT_FALSE(ui_->has("radius#use_view")) << "no button once it is used";
}
