// The renderer re-runs only the passes whose inputs changed.
#include "gl_fixture.h"

#include "scene/scene.h"

using namespace ssao;
using namespace ssaotest;

namespace {
class Passes : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        scene_ = loadScene("builtin:showcase");
        r_ = makeRenderer(scene_, defaultSettings(), 160, 90);
    }
    void TearDown() override {
        r_.reset();
        GlTest::TearDown();
    }
    std::vector<std::string> ranAfter(const std::string& assignment) {
        Settings s = r_->settings();
        applyAssignment(s, assignment);
        r_->setSettings(s);
        return r_->render().ran();
    }
    Scene scene_;
    std::unique_ptr<Renderer> r_;
};
using V = std::vector<std::string>;
} // namespace

TEST_F(Passes, FirstFrameRunsAllThenNothingUntilSomethingChanges) {
    FrameReport first = r_->render();
    EXPECT_EQ(first.ran(), (V{"gbuffer", "ssao", "blur", "composite"}));
    for (auto& p : first.passes) {
        EXPECT_GE(p.gpuMs, 0.0) << p.name;     // timer queries answered...
        EXPECT_LT(p.gpuMs, 10000.0) << p.name; // ...with a real time (llvmpipe first-query guard)
    }
    EXPECT_EQ(r_->render().ran(), V{});
}

TEST_F(Passes, BlurSettingRerunsOnlyBlurAndComposite) {
    r_->render();
    Image rawBefore = readBack(r_->ssao().aoRaw(), 1), aoBefore = readBack(r_->blur().ao(), 1);
    EXPECT_EQ(ranAfter("blur.kind=gaussian"), (V{"blur", "composite"}));
    EXPECT_EQ(ranAfter("blur.sigma=3"), (V{"blur", "composite"}));
    Image rawAfter = readBack(r_->ssao().aoRaw(), 1), aoAfter = readBack(r_->blur().ao(), 1);
    EXPECT_EQ(rawBefore.data, rawAfter.data); // not recomputed, so bit-identical
    EXPECT_NE(aoBefore.data, aoAfter.data);   // and the blur did change the result
}

TEST_F(Passes, EachSettingGroupInvalidatesItsPassAndWhatFollows) {
    r_->render();
    EXPECT_EQ(ranAfter("ssao.radius=0.8"), (V{"ssao", "blur", "composite"}));
    EXPECT_EQ(ranAfter("composite.ambient=0.5"), (V{"composite"}));
    EXPECT_EQ(ranAfter("gbuffer.normal_format=rgba8"), (V{"gbuffer", "ssao", "blur", "composite"}));
    EXPECT_EQ(ranAfter("ssao.radius=0.8"), V{}); // same value: nothing changed
}

TEST_F(Passes, CameraSceneAndSizeInvalidateEverything) {
    r_->render();
    Camera c = r_->camera();
    c.eye.x += 0.1f;
    r_->setCamera(c);
    EXPECT_EQ(r_->render().ran().size(), 4u);
    r_->setSize(100, 50);
    EXPECT_EQ(r_->render().ran().size(), 4u);
    EXPECT_EQ(r_->ssao().aoRaw().width(), 100);
    r_->setScene(scene_);
    EXPECT_EQ(r_->render().ran().size(), 4u);
}
