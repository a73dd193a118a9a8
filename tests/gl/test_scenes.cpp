// The shared third-party scenes with no preset at all: what a new user sees first. AO must be
// visible (the radius follows each scene's size), finite, in [0,1]; the millimetre engine must not
// z-fight.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"

#include "scene/scene.h"
#include "test_util.h"

using namespace ssao;
using namespace ssaotest;

namespace {
class Scenes : public GlTest {};
} // namespace

TEST_F(Scenes, EverySharedSceneShowsAoWithTheDefaults) {
    // Before the radius followed the scene, the two millimetre CAD models got a 0.5 mm kernel
    // (under a pixel): flat grey, median 0.895 on the engine; CornellBox and Lantern read ~0.99.
    const auto files = sharedSceneFiles();
    ASSERT_GE(files.size(), 8u);
    for (const auto& f : files) {
        const std::string name = f.stem().string();
        auto r = makeRenderer(loadScene(f.string()), defaultSettings(), 640, 360);
        r->render();
        const Rendered out = readAll(*r);
        ASSERT_TRUE(finiteInRange(out.aoRaw, 0.0f, 1.0f)) << name;
        ASSERT_TRUE(finiteInRange(out.ao, 0.0f, 1.0f)) << name;
        const Image mask = out.position.channel(3);
        const Stats s = stats(out.ao, &mask);
        const RadiusInfo ri = r->radiusAtCentre();
        std::printf("%-18s AO mean %.3f, median %.3f, darkest 5%% <= %.3f; radius %.4g units = %.1f px\n",
                    name.c_str(), s.mean, s.p50, s.p05, ri.world, ri.pixels);
        EXPECT_GT(s.count, 640 * 360 / 50) << name << " is barely visible";
        EXPECT_GT(ri.pixels, 4.0f) << name << ": a kernel of a few pixels or less gives flat grey";
        EXPECT_GT(s.p50, 0.93) << name << ": most surfaces are open, not flat grey";
        EXPECT_LT(s.mean, 0.99) << name << ": AO must be visible, not flat white";
        EXPECT_LT(s.p05, 0.93) << name << ": the darkest pixels must be clearly occluded";
    }
}

TEST_F(Scenes, FittedClipPlanesRemoveTheEnginesZFighting) {
    // The file's camera has near 0.05 mm and far 1e6 mm: the depth test cannot separate the
    // engine's nearby surfaces and the G-buffer speckles between them, which the AO turns into
    // false occlusion. Reference: the same view with near 10 mm.
    const std::string path = std::string(SSAOLAB_SCENES_DIR) + "/2CylinderEngine/2CylinderEngine.gltf";
    const Scene scene = loadScene(path);
    Settings s = defaultSettings();
    s.kernel.noise = Noise::None;
    Camera ref = *scene.camera;
    ref.clip = ClipMode::Fixed;
    ref.nearZ = 10.0f;
    ref.farZ = 5000.0f;
    Camera file = *scene.camera;
    file.clip = ClipMode::Fixed;          // the file's planes ...
    file.depth = DepthMode::Standard;     // ... in a standard depth buffer (reversed-Z: test_lens.cpp)
    const Rendered rRef = render(path, s, 320, 180, ref);
    const Rendered rFit = render(path, s, 320, 180, *scene.camera); // the default: fitted
    const Rendered rFile = render(path, s, 320, 180, file);
    auto speckles = [&](const Rendered& a) {
        long n = 0;
        for (size_t i = 0; i < a.aoRaw.data.size(); ++i)
            n += std::abs(a.aoRaw.data[i] - rRef.aoRaw.data[i]) > 0.15f;
        return n;
    };
    const long fit = speckles(rFit), fileSpeckles = speckles(rFile);
    std::printf(
        "engine: %ld pixels differ from the near-10 reference with fitted planes, %ld with the file's\n", fit,
        fileSpeckles);
    EXPECT_LT(fit, 20);
    EXPECT_GT(fileSpeckles, 10 * std::max(fit, 5L))
        << "the file's planes do z-fight (else this test proves nothing)";
}
