// Reversed-Z and orthographic cameras through the whole pipeline: the G-buffer, every technique,
// depth reconstruction, and the z-fighting reversed depth exists to remove.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"

#include "scene/scene.h"
#include "techniques/technique.h"

#include <cmath>

using namespace ssao;
using namespace ssaotest;

namespace {
class Lens : public GlTest {};

const std::string kEngine = std::string(SSAOLAB_SCENES_DIR) + "/2CylinderEngine/2CylinderEngine.gltf";

Camera withLens(Camera c, Projection p, DepthMode d) {
    c.projectionKind = p, c.depth = d;
    return c;
}
} // namespace

TEST_F(Lens, ReversedDepthDrawsTheSameFrameAsStandard) {
    // Fitted planes (far/near < 10 here): both mappings resolve every surface, so only the
    // hardware depth values differ.
    const Scene scene = loadScene("builtin:showcase");
    const Camera cam = withLens(sceneCamera(scene), Projection::Perspective, DepthMode::Standard);
    const Rendered s = render("builtin:showcase", defaultSettings(), 320, 180, cam);
    const Rendered r = render("builtin:showcase", defaultSettings(), 320, 180,
                              withLens(cam, Projection::Perspective, DepthMode::Reversed));
    EXPECT_LT(meanAbsDiff(s.depth, r.depth), 1e-5 * geometryMean(s, s.depth));
    EXPECT_LT(meanAbsDiff(s.ao, r.ao), 1e-4);
    EXPECT_TRUE(finiteInRange(r.ao, 0.0f, 1.0f));
}

TEST_F(Lens, ReversedDepthRemovesTheEnginesZFightingAtItsOwnPlanes) {
    // 2CylinderEngine's camera: near 0.05, far 1e6 (mm), the engine 1200..2000 away. A standard
    // depth buffer gives its fins z-fighting speckles (false AO); reversed depth draws what the
    // tightly fitted planes draw.
    const Scene scene = loadScene(kEngine);
    Camera own = withLens(sceneCamera(scene), Projection::Perspective, DepthMode::Standard);
    own.clip = ClipMode::Fixed;
    ASSERT_GT(own.farZ / own.nearZ, 1e6f);
    Camera fit = own;
    fit.clip = ClipMode::Fit; // the renderer fits the planes to the scene every frame
    const Rendered fitted = render(kEngine, defaultSettings(), 320, 180, fit);
    ASSERT_LT(fitted.camera.farZ / fitted.camera.nearZ, 10.0f);
    const Rendered standard = render(kEngine, defaultSettings(), 320, 180, own);
    const Rendered reversed =
        render(kEngine, defaultSettings(), 320, 180, withLens(own, Projection::Perspective, DepthMode::Reversed));
    const double dStandard = meanAbsDiff(standard.aoRaw, fitted.aoRaw);
    const double dReversed = meanAbsDiff(reversed.aoRaw, fitted.aoRaw);
    std::printf("engine at its own planes: raw AO differs from the fitted planes' by %.2e (standard depth), "
                "%.2e (reversed)\n",
                dStandard, dReversed);
    EXPECT_GT(dStandard, 1e-3);
    EXPECT_LT(dReversed, 1e-4);
    EXPECT_LT(dReversed * 20.0, dStandard);
}

TEST_F(Lens, OrthographicPlaneIsUnoccludedAndEveryTechniqueStaysInRange) {
    const Scene plane = loadScene("builtin:plane");
    for (const TechniqueInfo& t : techniques()) {
        for (DepthMode d : {DepthMode::Standard, DepthMode::Reversed}) {
            Settings s = defaultSettings();
            setParam(s, "ao.technique", t.id);
            const Rendered r =
                render("builtin:plane", s, 240, 135, withLens(sceneCamera(plane), Projection::Orthographic, d));
            EXPECT_TRUE(finiteInRange(r.ao, 0.0f, 1.0f)) << t.id;
            const double mean = geometryMean(r, r.ao);
            std::printf("orthographic plane, %s, %s depth: AO mean %.4f\n", t.id.c_str(), depthModeName(d), mean);
            EXPECT_GT(mean, 0.95) << t.id << " " << depthModeName(d);
        }
    }
}

TEST_F(Lens, PositionsFromTheDepthBufferMatchTheGBufferInEveryLens) {
    // The kernel's seed-000/001 path rebuilds positions from the hardware depth (frameLinearDepth,
    // frameViewPosition); with each lens it must agree with the stored positions.
    const Scene scene = loadScene("builtin:showcase");
    for (Projection p : {Projection::Perspective, Projection::Orthographic})
        for (DepthMode d : {DepthMode::Standard, DepthMode::Reversed}) {
            Settings s = preset("learnopengl");
            s.kernel.noise = Noise::None;
            const Camera cam = withLens(sceneCamera(scene), p, d);
            const Rendered fromPositions = render("builtin:showcase", s, 240, 135, cam);
            setParam(s, "kernel.position_source", "depth");
            const Rendered fromDepth = render("builtin:showcase", s, 240, 135, cam);
            const double diff = meanAbsDiff(fromPositions.aoRaw, fromDepth.aoRaw);
            std::printf("%s, %s depth: raw AO from depth vs positions: mean |diff| %.2e\n", projectionName(p),
                        depthModeName(d), diff);
            EXPECT_LT(diff, 5e-3) << projectionName(p) << " " << depthModeName(d);
        }
}
