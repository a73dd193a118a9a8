// The explorer's UI code, driven through Dear ImGui with the real renderer (llvmpipe in CI).
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"
#include "ui_driver.h"

#include "settings/preset.h"
#include "test_util.h"

#include <filesystem>
#include <fstream>

using namespace ssao;
using namespace ssaotest;
namespace fs = std::filesystem;

namespace {

class AppUi : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        userDir_ = std::string(SSAOLAB_TEST_TMP) + "/user_presets_" +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(userDir_);
        AppOptions o;
        o.userPresetDir = userDir_;
        o.renderScale = 0.3f; // keeps llvmpipe fast; the UI logic is the same at any scale
        // These tests count the SSAO chain's passes and idle frames; the reference's background
        // trace (and its upload pass) has its own tests in test_app_reference.cpp.
        o.reference = false;
        ui_ = std::make_unique<UiDriver>(o);
    }
    void TearDown() override {
        ui_.reset();
        GlTest::TearDown();
    }
    Image aoRaw() { return readBack(ui_->app().renderer().texture("ao.raw"), 1); }
    Image composite() { return readBack(ui_->app().renderer().texture("composite"), 4); }
    std::string userDir_;
    std::unique_ptr<UiDriver> ui_;
};

} // namespace

TEST_F(AppUi, CheckboxChangesTheSettingAndTheAoImage) {
    Image before = aoRaw();
    ASSERT_FALSE(ui_->app().settings().kernel.separable);
    ui_->click("kernel.separable", 0.1f);
    ui_->frames(2);
    EXPECT_TRUE(ui_->app().settings().kernel.separable);
    EXPECT_TRUE(ui_->app().unsavedChanges());
    EXPECT_NE(aoRaw().data, before.data);
}

TEST_F(AppUi, SliderDragRendersReducedThenReRunsOnlyWhatItInvalidates) {
    ui_->app().frames().interactiveScale = 0.15f; // below this fixture's render scale (0.3)
    ui_->settle();
    const int fullW = ui_->app().renderer().width();
    Image before = aoRaw();
    const ImVec4 r = ui_->rect("ao.radius_scene");
    const float y = (r.y + r.w) * 0.5f;
    ui_->frame(r.x + (r.z - r.x) * 0.3f, y, false);
    ui_->frame(r.x + (r.z - r.x) * 0.3f, y, true);
    std::vector<std::vector<std::string>> ran;
    for (int i = 1; i <= 4; ++i) {
        const int framesBefore = ui_->app().frames().framesRendered();
        ui_->frame(r.x + (r.z - r.x) * (0.3f + 0.05f * float(i)), y, true);
        if (ui_->app().frames().framesRendered() > framesBefore) ran.push_back(ui_->app().frames().lastReport().ran());
        // While the slider is held the frame is rendered at the interactive scale.
        EXPECT_LT(ui_->app().renderer().width(), fullW);
    }
    ASSERT_GE(ran.size(), 2u);
    // After the first reduced frame, a drag step re-runs the AO chain only, not the G-buffer.
    EXPECT_EQ(ran.back(), (std::vector<std::string>{"ao", "denoise", "composite"}));
    ui_->frame(r.x + (r.z - r.x) * 0.5f, y, false);
    ui_->settle();
    EXPECT_EQ(ui_->app().renderer().width(), fullW); // refined to full resolution once released
    const float v = ui_->app().settings().ao.radiusScene;
    EXPECT_NE(v, Settings{}.ao.radiusScene);
    EXPECT_GE(v, float(findParam("ao.radius_scene")->min));
    EXPECT_LE(v, float(findParam("ao.radius_scene")->max));
    EXPECT_NE(aoRaw().data, before.data);
}

TEST_F(AppUi, CtrlClickTextEntryIsClampedToTheRange) {
    ui_->click("ao.radius_scene", 0.5f,
               /*ctrl=*/true); // Ctrl+Click turns the slider into a text field (all selected)
    ui_->type("99999");
    ui_->pressEnter();
    ui_->frames(2);
    EXPECT_FLOAT_EQ(ui_->app().settings().ao.radiusScene, 0.5f); // AlwaysClamp: not 99999
}

TEST_F(AppUi, ResetButtonRestoresTheDefault) {
    ui_->app().settings().kernel.bias = 0.3f;
    ui_->frames(2);
    ui_->click("kernel.bias#reset");
    ui_->frame();
    EXPECT_FLOAT_EQ(ui_->app().settings().kernel.bias, Settings{}.kernel.bias);
}

TEST_F(AppUi, ComboSelectsAnotherKernel) {
    Image mask = readBack(ui_->app().renderer().texture("gbuffer.position"), 4).channel(3);
    const double before = stats(aoRaw(), &mask).mean;
    ui_->click("kernel.shape");
    ui_->frame();
    ASSERT_TRUE(ui_->has("kernel.shape#sphere"));
    ui_->click("kernel.shape#sphere");
    ui_->settle();
    EXPECT_EQ(ui_->app().settings().kernel.shape, KernelShape::Sphere);
    EXPECT_LT(stats(aoRaw(), &mask).mean, before - 0.2); // the sphere kernel's false occlusion
}

TEST_F(AppUi, PresetSavedFromTheUiLoadsBackAndRendersTheSameHeadless) {
    setParam(ui_->app().settings(), "ao.radius_mode", "world");
    ui_->app().settings().ao.radius = 0.8f;
    ui_->app().settings().denoise.kind = DenoiseKind::Gaussian;
    ui_->settle();
    ui_->click("tab#Presets");
    ui_->frame();
    ui_->click("preset#name");
    ui_->type("my tuned");
    ui_->click("preset#save");
    ui_->frames(2);
    const std::string path = userDir_ + "/my tuned.json";
    ASSERT_TRUE(fs::exists(path)) << ui_->app().status();
    EXPECT_FALSE(ui_->app().unsavedChanges());
    Preset p = readPresetFile(path);
    EXPECT_TRUE(p.settings == ui_->app().settings());
    ASSERT_TRUE(p.camera.has_value());
    ASSERT_TRUE(p.scene.has_value());
    EXPECT_EQ(*p.scene, "builtin:showcase");
    ASSERT_TRUE(p.size.has_value());
    Renderer& appR = ui_->app().renderer();
    EXPECT_EQ(p.size->first, appR.width()); // the full-resolution view size
    EXPECT_EQ(p.size->second, appR.height());

    // The same preset rendered headless (its scene, size and camera) equals the app's frame.
    Renderer headless(SSAOLAB_SHADER_DIR);
    headless.setSize(p.size->first, p.size->second);
    headless.setScene(loadScene(*p.scene));
    headless.setCamera(*p.camera);
    headless.setSettings(p.settings);
    headless.render();
    Image a = readBack(appR.texture("ao.denoised"), 1), b = readBack(headless.texture("ao.denoised"), 1);
    double maxDiff = 0;
    for (size_t i = 0; i < a.data.size(); ++i)
        maxDiff = std::max(maxDiff, double(std::abs(a.data[i] - b.data[i])));
    EXPECT_LT(maxDiff, 1e-4);
    Image ca = readBack(appR.texture("composite"), 4), cb = readBack(headless.texture("composite"), 4);
    EXPECT_EQ(ca.data, cb.data);

    // It is listed, and loading it from the list restores the settings.
    ui_->app().settings().ao.radius = 0.3f;
    EXPECT_TRUE(ui_->app().unsavedChanges());
    ui_->frame();
    ui_->click("preset#my tuned");
    ui_->click("preset#load");
    EXPECT_FLOAT_EQ(ui_->app().settings().ao.radius, 0.8f);
}

TEST_F(AppUi, PresetRenameAndDeleteWorkOnUserPresetsOnly) {
    ASSERT_TRUE(ui_->app().savePreset("first"));
    EXPECT_TRUE(ui_->app().renamePreset("first", "second"));
    EXPECT_TRUE(fs::exists(userDir_ + "/second.json"));
    EXPECT_FALSE(fs::exists(userDir_ + "/first.json"));
    EXPECT_FALSE(ui_->app().renamePreset("learnopengl", "x"));
    EXPECT_TRUE(ui_->app().statusIsError());
    EXPECT_FALSE(ui_->app().deletePreset("learnopengl"));
    EXPECT_FALSE(ui_->app().savePreset("learnopengl")); // may not shadow a seed preset
    EXPECT_TRUE(ui_->app().deletePreset("second"));
    EXPECT_FALSE(fs::exists(userDir_ + "/second.json"));
    // Built-in presets are listed first.
    const auto& e = ui_->app().presets().entries();
    ASSERT_FALSE(e.empty());
    EXPECT_TRUE(e.front().builtin);
}

TEST_F(AppUi, DroppingABadFileShowsTheErrorAndKeepsTheScene) {
    const std::string name = ui_->app().scene().name;
    const std::string bad = writeTemp("app_corrupt.gltf", "{ corrupt");
    ui_->app().dropFiles({bad});
    ui_->frame();
    EXPECT_TRUE(ui_->app().statusIsError());
    EXPECT_NE(ui_->app().status().find("cannot load glTF"), std::string::npos) << ui_->app().status();
    EXPECT_EQ(ui_->app().scene().name, name);
    ui_->app().dropFiles({std::string(SSAOLAB_ASSET_DIR) + "/presets/seed003.json"});
    EXPECT_FALSE(ui_->app().statusIsError());
    EXPECT_EQ(ui_->app().settings().kernel.rangeCheck, RangeCheck::Hard);
    ui_->app().dropFiles({std::string(SSAOLAB_SCENES_DIR) + "/ShaderBall/shader_ball.gltf"});
    ui_->frames(2);
    EXPECT_NE(ui_->app().scene().name.find("shader_ball"), std::string::npos);
    EXPECT_TRUE(finiteInRange(aoRaw(), 0.0f, 1.0f));
}

TEST_F(AppUi, ClickingAGridCellEnlargesItAndTheInspectorsFollowTheCursor) {
    ASSERT_EQ(ui_->app().view().mode, ViewMode::Grid);
    ui_->click("view#ao.raw");
    ui_->frame();
    EXPECT_EQ(ui_->app().view().mode, ViewMode::Single);
    EXPECT_EQ(ui_->app().view().enlarged, "ao.raw");
    // Hover the middle of the enlarged view: the pixel inspector and sample inspector follow.
    const ImVec4 r = ui_->rect("view#main");
    ui_->frame((r.x + r.z) * 0.5f, r.y + (r.w - r.y) * 0.7f);
    ui_->frame((r.x + r.z) * 0.5f, r.y + (r.w - r.y) * 0.7f);
    const glm::ivec2 px = ui_->app().hoverPixel();
    EXPECT_NEAR(px.x, ui_->app().renderer().width() / 2, 2);
    const auto& pi = ui_->app().inspection();
    ASSERT_TRUE(pi && pi->geometry);
    EXPECT_EQ(int(pi->taps.size()), ui_->app().settings().kernel.samples);
    // The taps are the GPU's own record: its AO is the value in ao.raw at that pixel.
    EXPECT_NEAR(pi->ao, ui_->app().valueAt("ao.raw", px).at(0), 1e-5);
    EXPECT_EQ(ui_->app().valueAt("ao.raw", px).size(), 1u); // a scalar buffer shows one value
    EXPECT_EQ(ui_->app().valueAt("gbuffer.normal", px).size(), 3u);
    ui_->save(std::string(SSAOLAB_TEST_TMP) + "/ui_single_view.png");
}

TEST_F(AppUi, DraggingTheViewOrbitsTheCamera) {
    ui_->click("view#composite");
    ui_->frame();
    const Camera before = ui_->app().cameraController().camera();
    const ImVec4 r = ui_->rect("view#main");
    const float cx = (r.x + r.z) * 0.5f, cy = (r.y + r.w) * 0.5f;
    ui_->drag(cx, cy, cx + 120, cy + 30);
    ui_->frame();
    const Camera after = ui_->app().cameraController().camera();
    EXPECT_GT(glm::length(after.eye - before.eye), 0.1f);
    EXPECT_NEAR(glm::length(after.eye - after.target), glm::length(before.eye - before.target),
                1e-3f);                                  // orbit keeps distance
    EXPECT_EQ(ui_->app().frames().lastReport().ran().size(), 4u); // a camera move re-renders everything
}

TEST_F(AppUi, CameraPanelSwitchesTheLensAndAViewOfTheAoAloneCullsTheComposite) {
    ui_->settle();
    ui_->click("tab#Scene & camera");
    ui_->frame();
    ui_->click("camera#orthographic");
    ui_->click("camera#depth_standard");
    ui_->frames(2);
    const Camera& rendered = ui_->app().renderer().camera();
    EXPECT_TRUE(rendered.orthographic());
    EXPECT_EQ(rendered.depth, DepthMode::Standard);
    const Image mask = readBack(ui_->app().renderer().texture("gbuffer.position"), 4).channel(3);
    EXPECT_GT(stats(mask).mean, 0.2); // the orthographic view still frames the scene
    // "Reset view" keeps the lens the user chose.
    ui_->app().resetCamera();
    ui_->frames(2);
    EXPECT_TRUE(ui_->app().renderer().camera().orthographic());
    ui_->click("camera#perspective");
    ui_->click("camera#depth_reversed");
    ui_->frames(2);
    EXPECT_FALSE(ui_->app().renderer().camera().orthographic());
    EXPECT_EQ(ui_->app().renderer().camera().depth, DepthMode::Reversed);

    // A single view of the raw AO: the composite is not run (culled), the grid brings it back.
    ui_->app().view().mode = ViewMode::Single;
    ui_->app().view().enlarged = "ao.raw";
    ui_->app().settings().ao.power = 1.3f;
    ui_->app().frames().keepAwake();
    ui_->frames(3);
    const FrameReport& single = ui_->app().frames().lastReport();
    bool culled = false;
    for (const auto& p : single.passes)
        culled = culled || (p.name == "composite" && p.culled);
    EXPECT_TRUE(culled);
    // The pixel readout shows nothing for what this view did not compute, not an older frame's values.
    EXPECT_TRUE(ui_->app().valueAt("composite", {10, 10}).empty());
    EXPECT_FALSE(ui_->app().valueAt("ao.raw", {10, 10}).empty());
    ui_->app().view().mode = ViewMode::Grid;
    ui_->app().frames().keepAwake();
    ui_->frames(2);
    const auto ran = ui_->app().frames().lastReport().ran();
    EXPECT_NE(std::find(ran.begin(), ran.end(), "composite"), ran.end());
    EXPECT_FALSE(ui_->app().valueAt("composite", {10, 10}).empty());
}

TEST_F(AppUi, IdleFramesRenderNothing) {
    ui_->settle(); // let hover/input settle
    ui_->frames(4);
    const int rendered = ui_->app().frames().framesRendered();
    ui_->frames(10);
    EXPECT_EQ(ui_->app().frames().framesRendered(), rendered); // no SSAO pass ran without a change
    EXPECT_FALSE(ui_->app().frames().busy());                  // and the window loop may sleep
    ui_->app().settings().composite.ambient = 0.5f;
    ui_->app().frames().keepAwake();
    ui_->frame();
    EXPECT_EQ(ui_->app().frames().framesRendered(), rendered + 1);
}

TEST_F(AppUi, BrokenShaderKeepsTheLastGoodProgramAndShowsFileAndLine) {
    // Work on a copy of shaders/ so the real files are never touched.
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/hot_shaders";
    fs::remove_all(dir);
    fs::copy(SSAOLAB_SHADER_DIR, dir, fs::copy_options::recursive);
    ui_.reset();
    AppOptions o;
    o.userPresetDir = userDir_;
    o.shaderDir = dir;
    o.renderScale = 0.3f;
    ui_ = std::make_unique<UiDriver>(o);
    ui_->frames(2);
    Image good = aoRaw();

    const std::string frag = dir + "/techniques/kernel/kernel.frag";
    std::string text;
    {
        std::ifstream in(frag);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    std::ofstream(frag) << text << "\nthis is not glsl;\n";
    fs::last_write_time(frag, fs::last_write_time(frag) + std::chrono::seconds(2));
    ui_->app().pollShaderReload();
    ui_->frame();
    EXPECT_NE(ui_->app().frames().shaderError().find("techniques/kernel/kernel.frag:"), std::string::npos)
        << ui_->app().frames().shaderError() << " / " << ui_->app().status();
    ui_->app().renderer().invalidate(); // still renders, with the last good program
    ui_->frames(2);
    EXPECT_EQ(aoRaw().data, good.data);

    std::ofstream(frag) << text; // fixed: the error clears
    fs::last_write_time(frag, fs::last_write_time(frag) + std::chrono::seconds(4));
    ui_->app().pollShaderReload();
    ui_->frame();
    EXPECT_TRUE(ui_->app().frames().shaderError().empty()) << ui_->app().frames().shaderError();
}

TEST_F(AppUi, ClosingTheAppReleasesEveryGlObject) {
    ui_->app().view().mode = ViewMode::Split; // also chain B
    ui_->app().view().splitKind = SplitKind::Preset;
    ui_->frames(2);
    Renderer& r = ui_->app().renderer();
    const GLuint chainB = r.texture("b.ao.raw").id();
    ASSERT_TRUE(glIsTexture(chainB));
    ui_->app().view().mode = ViewMode::Grid;
    ui_->frames(2);
    EXPECT_FALSE(glIsTexture(chainB)) << "leaving the split view frees chain B";
    std::vector<GLuint> textures;
    for (const Resource* res : r.graph().resources(true))
        textures.push_back(res->texture.id());
    for (const Resource* res : r.buffers())
        textures.push_back(ui_->app().frames().views().find(res->desc.name)->target.texture().id());
    for (GLuint id : textures)
        ASSERT_TRUE(glIsTexture(id)) << id;
    ui_.reset();
    for (GLuint id : textures)
        EXPECT_FALSE(glIsTexture(id)) << "texture " << id << " leaked";
}

TEST_F(AppUi, GltfCamerasAreSelectableAndScenesWithoutOneAreFramed) {
    ASSERT_TRUE(ui_->app().openScene(std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf"));
    ASSERT_FALSE(ui_->app().scene().cameras.empty());
    ui_->app().cameraController().rotate(200, 0); // move away from the file's camera...
    ui_->app().selectSceneCamera(0);              // ...and back to it
    EXPECT_EQ(ui_->app().cameraController().camera().eye, ui_->app().scene().cameras[0].second.eye);
    ASSERT_TRUE(ui_->app().openScene(std::string(SSAOLAB_SCENES_DIR) + "/FlightHelmet/FlightHelmet.gltf"));
    const Camera framed = frameBounds(ui_->app().scene().bounds);
    EXPECT_EQ(ui_->app().cameraController().camera().eye, framed.eye);
    ui_->frames(2);
    Image mask = readBack(ui_->app().renderer().texture("gbuffer.position"), 4).channel(3);
    EXPECT_GT(stats(mask, &mask).count, mask.width * mask.height / 20) << "the framed helmet fills the view";
}

TEST_F(AppUi, FlyModeMovesWithWasdWhileHoveringTheView) {
    ui_->click("view#composite");
    ui_->frame();
    ui_->app().cameraController().setMode(CameraController::Mode::Fly);
    const ImVec4 r = ui_->rect("view#main");
    const float cx = (r.x + r.z) * 0.5f, cy = (r.y + r.w) * 0.5f;
    ui_->frame(cx, cy);
    const Camera before = ui_->app().cameraController().camera();
    ImGui::GetIO().KeysDown['W'] = true;
    for (int i = 0; i < 10; ++i)
        ui_->frame(cx, cy);
    ImGui::GetIO().KeysDown['W'] = false;
    ui_->frame(cx, cy);
    const Camera after = ui_->app().cameraController().camera();
    const glm::vec3 fwd = glm::normalize(before.target - before.eye);
    EXPECT_GT(glm::dot(after.eye - before.eye, fwd), 0.01f);                        // moved forward
    EXPECT_NEAR(glm::length(glm::cross(after.eye - before.eye, fwd)), 0.0f, 1e-3f); // along the view only
}

TEST_F(AppUi, WindowResizeAndHiDpiScaleTheRenderSize) {
    ui_->settle();
    const int w0 = ui_->app().renderer().width(), h0 = ui_->app().renderer().height();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(1200, 1800); // the window got smaller
    ui_->frames(2);
    const int w1 = ui_->app().renderer().width();
    EXPECT_LT(w1, w0);
    EXPECT_EQ(ui_->app().frames().lastReport().ran().size(), 4u); // a new size re-renders every pass
    io.DisplayFramebufferScale = ImVec2(2, 2);           // a HiDPI monitor: twice the pixels
    ui_->frames(2);
    EXPECT_NEAR(ui_->app().renderer().width(), 2 * w1, 2);
    EXPECT_GT(ui_->app().renderer().height(), h0);
    io.DisplayFramebufferScale = ImVec2(1, 1);
    EXPECT_TRUE(finiteInRange(aoRaw(), 0.0f, 1.0f));
}

TEST_F(AppUi, TheTransparentToggleReloadsTheSceneKeepingTheCamera) {
    struct Restore {
        Transparent saved = transparentMode();
        ~Restore() { setTransparentMode(saved); }
    } restore;
    ASSERT_TRUE(ui_->app().openScene(std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf"));
    ui_->frames(2);
    const size_t skipped = ui_->app().scene().triangleCount();
    ASSERT_TRUE(ui_->app().scene().materials.blendSkipped);
    ui_->app().selectSceneCamera(0);
    ui_->frames(1);
    const glm::vec3 eye = ui_->app().cameraController().camera().eye;
    ui_->click("tab#Scene & camera");
    ui_->frames(2);
    ui_->click("scene#transparent", 0.05f);
    ui_->frames(2);
    EXPECT_EQ(transparentMode(), Transparent::Opaque);
    EXPECT_FALSE(ui_->app().scene().materials.blendSkipped);
    EXPECT_EQ(ui_->app().scene().triangleCount(), skipped + ui_->app().scene().materials.blend) << "the glass sphere is back";
    EXPECT_LT(glm::length(ui_->app().cameraController().camera().eye - eye), 1e-5f) << "the camera stays";
    ui_->click("scene#transparent", 0.05f);
    ui_->frames(2);
    EXPECT_EQ(ui_->app().scene().triangleCount(), skipped);
}
