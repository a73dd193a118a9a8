// Camera controller and preset store: pure logic, no GL.
#include "scene/view_fit.h"
#include "settings/params.h"
#include "settings/preset_store.h"
#include "util/error.h"
#include "view/frame/camera_controller.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace ssao;
namespace fs = std::filesystem;

TEST(CameraController, OrbitKeepsDistanceAndTarget) {
    CameraController c;
    c.reset(Camera{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 0.1f, 100}, 2.0f);
    c.rotate(100, 40);
    EXPECT_NEAR(glm::length(c.camera().eye), 5.0f, 1e-4f);
    EXPECT_EQ(c.camera().target, glm::vec3(0));
    EXPECT_GT(c.camera().eye.y, 0.0f); // dragging down looks from above
    c.rotate(0, 100000);               // pitch is clamped short of the pole: the view never degenerates
    EXPECT_NO_THROW(validateCamera(c.camera()));
}

TEST(CameraController, DollyingInKeepsTheTargetInsideTheFittedClipPlanes) {
    // The controller leaves the planes to the renderer, which fits them to the scene per view.
    Bounds b;
    b.add({-2, -2, -2});
    b.add({2, 2, 2});
    CameraController c;
    c.reset(Camera{{0, 0, 50}, {0, 0, 0}, {0, 1, 0}, 60, 20.0f, 100}, 2.0f);
    for (int i = 0; i < 40; ++i) {
        c.zoom(1); // dolly in to ~0.7 units from the target, inside the box
        const Camera e = effectiveCamera(c.camera(), b);
        const float dist = glm::length(e.eye - e.target);
        EXPECT_LT(e.nearZ, dist) << "step " << i; // the target is never behind the near plane
        EXPECT_GT(e.farZ, dist) << "step " << i;
        EXPECT_NO_THROW(validateCamera(e));
    }
}

TEST(CameraController, ZoomPanAndFly) {
    CameraController c;
    c.reset(Camera{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 0.1f, 100}, 2.0f);
    c.zoom(1);
    EXPECT_NEAR(glm::length(c.camera().eye), 4.5f, 1e-4f);
    c.pan(10, 0, 100);
    EXPECT_LT(c.camera().target.x, 0.0f); // dragging right moves the scene right: camera goes left
    c.setMode(CameraController::Mode::Fly);
    const glm::vec3 eye = c.camera().eye;
    c.move({0, 0, 1}, 0.5f); // forward by half a scene radius
    EXPECT_NEAR(glm::length(c.camera().eye - eye), 1.0f, 1e-4f);
    const glm::vec3 e2 = c.camera().eye;
    c.rotate(50, 0); // fly: look around, the eye stays
    EXPECT_NEAR(glm::length(c.camera().eye - e2), 0.0f, 1e-5f);
}

TEST(PresetStore, SaveListRenameDeleteAndNameRules) {
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/store";
    fs::remove_all(dir);
    PresetStore store(std::string(SSAOLAB_ASSET_DIR) + "/presets", dir);
    const size_t builtins = store.entries().size();
    EXPECT_GE(builtins, 6u);
    Preset p;
    p.name = "mine";
    p.settings = defaultSettings();
    p.settings.kernel.samples = 17;
    p.camera = Camera{{1, 2, 3}, {0, 0, 0}, {0, 1, 0}, 50, 0.5f, 50};
    store.save(p);
    ASSERT_EQ(store.entries().size(), builtins + 1);
    EXPECT_FALSE(store.entries().back().builtin);
    Preset back = store.load("mine");
    EXPECT_EQ(back.settings.kernel.samples, 17);
    ASSERT_TRUE(back.camera.has_value());
    EXPECT_EQ(back.camera->eye, glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(back.camera->fovYDeg, 50.0f);
    p.name = "../escape";
    EXPECT_THROW(store.save(p), Error);
    p.name = "";
    EXPECT_THROW(store.save(p), Error);
    p.name = "seed003";
    EXPECT_THROW(store.save(p), Error);
    store.rename("mine", "yours");
    EXPECT_EQ(store.find("mine"), nullptr);
    EXPECT_NE(store.find("yours"), nullptr);
    EXPECT_THROW(store.remove("learnopengl"), Error);
    store.remove("yours");
    EXPECT_EQ(store.entries().size(), builtins);
}

TEST(PresetFiles, CameraBookmarkIsValidated) {
    nlohmann::json j = {{"camera", {{"eye", {0, 0, 0}}, {"target", {0, 0, 0}}}}};
    EXPECT_THROW(presetFromJson(j, "t"), Error); // eye == target
    j = {{"camera", {{"eye", {0, 0, 1}}, {"target", {0, 0, 0}}, {"zoom", 2}}}};
    EXPECT_THROW(presetFromJson(j, "t"), Error); // unknown camera key
    j = {{"camera", {{"eye", {0, 0, 1}}, {"target", {0, 0, 0}}, {"near", 0.5}, {"far", 9}}},
         {"ao", {{"radius", 2}}}};
    Preset p = presetFromJson(j, "t");
    EXPECT_FLOAT_EQ(p.settings.ao.radius, 2.0f);
    EXPECT_FLOAT_EQ(p.camera->farZ, 9.0f);
}

TEST(PresetStore, OneLookupForTheAppAndTheCommandLine) {
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/store_lookup";
    fs::remove_all(dir);
    PresetStore store(std::string(SSAOLAB_ASSET_DIR) + "/presets", dir);
    Preset p;
    p.name = "from the app";
    store.save(p);
    // Seed presets by name, then the user's, then a path.
    EXPECT_EQ(store.resolve("learnopengl"), std::string(SSAOLAB_ASSET_DIR) + "/presets/learnopengl.json");
    EXPECT_EQ(store.resolve("from the app"), dir + "/from the app.json");
    EXPECT_EQ(store.open("from the app").name, "from the app");
    EXPECT_EQ(store.resolve(dir + "/from the app.json"), dir + "/from the app.json");
    try {
        store.resolve("nonesuch");
        FAIL();
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("no preset named 'nonesuch'"), std::string::npos) << what;
        EXPECT_NE(what.find(dir), std::string::npos) << "says where it looked: " << what;
    }
    EXPECT_THROW(store.resolve("/no/such/file.json"), Error);
}

TEST(CameraController, ZoomingOutAFixedClipCameraNeverClipsItsScene) {
    // Built-in scenes keep their designed planes (far 60 for the showcase); zooming out 100x the
    // scene radius must widen them, not clip the scene away.
    CameraController c;
    Camera designed{{3, 2, 4}, {0, 0, 0}, {0, 1, 0}, 60, 0.1f, 60.0f};
    designed.clip = ClipMode::Fixed;
    c.reset(designed, 8.0f, glm::vec3(0.0f));
    for (int i = 0; i < 60; ++i)
        c.zoom(-1);
    const Camera& z = c.camera();
    const float dist = glm::length(z.eye);
    EXPECT_GT(dist, 300.0f);
    EXPECT_GT(z.farZ, dist + 8.0f); // the whole scene (radius 8 around the origin) is inside far
    EXPECT_EQ(z.clip, ClipMode::Fixed);
    EXPECT_NO_THROW(validateCamera(z));
}

TEST(CameraControllerScale, ADragAcrossTheViewIsHalfATurnWhateverItsSize) {
    // 160 px turned the camera about 90 degrees in a small window; the turn now scales with the view.
    for (float width : {400.0f, 1600.0f}) {
        CameraController c;
        Camera cam;
        cam.eye = {0, 0, 5};
        cam.target = {0, 0, 0};
        c.reset(cam, 1.0f);
        c.rotate(width, 0, width);
        const glm::vec3 e = c.camera().eye;
        EXPECT_NEAR(e.z, -5.0f, 1e-3f) << width; // half a turn around the target
        EXPECT_NEAR(e.x, 0.0f, 1e-3f) << width;
        c.reset(cam, 1.0f);
        c.rotate(160, 0, width);
        const float deg = glm::degrees(std::atan2(c.camera().eye.x, c.camera().eye.z));
        EXPECT_NEAR(std::abs(deg), 180.0f * 160.0f / width, 0.05f) << width;
    }
}
