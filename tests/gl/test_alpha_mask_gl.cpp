// MASK cut-outs in the G-buffer (include/alpha_mask.glsl) against the reference's Embree filter
// (scene/alpha_mask.h): through the checkerboard lid the G-buffer shows the floor exactly where the
// reference's primary rays reach it, and every scene pass (back faces, guard band) cuts the same.
#include "gl_fixture.h"
#include "cpu/reference_scenes.h"
#include "lid_scene.h"

#include "gl/readback.h"
#include "passes/back_face_pass.h"
#include "reference/embree_scene.h"
#include "reference/reference_ao.h"
#include "scene/load/gltf_loader.h"

#include <cmath>
#include <cstdio>

using namespace ssao;
using namespace ssaotest;

namespace {
class AlphaMaskGl : public GlTest {};
} // namespace

TEST_F(AlphaMaskGl, TheGBufferShowsTheFloorThroughTheHolesWhereTheReferenceDoes) {
    LidSpec spec;
    const Scene scene = loadGltf(writeLidScene("lid_gl", spec));
    Camera cam;
    cam.eye = {0.05f, 3.0f, 0.03f}; // off the cells' corners
    cam.target = {0.05f, 0.0f, 0.03f};
    cam.up = {0, 0, -1};
    cam.fovYDeg = 25.0f;
    cam.nearZ = 0.5f;
    cam.farZ = 10.0f;
    const int w = 128, h = 128;
    Settings s = defaultSettings();
    s.ao.technique = "vbao";
    s.gbuffer.backFaces = true;
    s.gbuffer.guardBandPx = 8;
    auto r = makeRenderer(scene, s, w, h, cam);
    r->render();
    const Rendered gb = readAll(*r);
    EmbreeScene rt(scene);
    const ReferenceImage ref = traceReference(rt, cam, w, h, {1.0f, 16});
    // Both images' rows run top-down (gl/readback.h flips GL's).
    long lid = 0, floorInHoles = 0, agree = 0, inLid = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float dg = gb.depth.data[size_t(y) * w + x];
            const float dr = ref.depth[size_t(y) * w + x];
            const bool gLid = std::abs(dg - (3.0f - spec.height)) < 0.01f;
            const bool rLid = std::abs(dr - (3.0f - spec.height)) < 0.01f;
            agree += gLid == rLid && std::abs(dg - dr) < 0.01f;
            lid += gLid;
            // Pixels whose ray crosses the lid's square: the floor shows through the open half.
            const glm::vec3 p = hitPosition(cam, w, h, x, y, 3.0f - spec.height);
            if (std::abs(p.x) < spec.lidHalf && std::abs(p.z) < spec.lidHalf) {
                ++inLid;
                floorInHoles += std::abs(dg - 3.0f) < 0.01f;
            }
        }
    std::printf("lid seen from above, %dx%d: %ld pixels inside the lid's square, %ld of them show the floor "
                "through a hole; G-buffer and reference agree on %ld of %d pixels\n",
                w, h, inLid, floorInHoles, agree, w * h);
    ASSERT_GT(inLid, 2000);
    EXPECT_NEAR(double(floorInHoles) / double(inLid), 0.5, 0.05) << "half the lid is open";
    EXPECT_GT(double(agree), 0.99 * w * h) << "only pixels on a cell's edge may differ";
    // The back-face layer is cut the same way (no back face behind an open cell but the floor's none).
    const Image back = readBack(r->texture(BackFacePass::kOutput), 1);
    EXPECT_TRUE(finiteInRange(back, 0.0f, 100.0f));
    EXPECT_TRUE(finiteInRange(gb.ao, 0.0f, 1.0f));
    EXPECT_TRUE(finiteInRange(gb.aoRaw, 0.0f, 1.0f));
}
