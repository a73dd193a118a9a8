// skip.motion_lod on the GPU: the moving frame of a large shared scene draws a clustered level
// (scene/gpu/motion_lod.h) and sees the same surfaces as the full mesh to within its cells - the same
// pixels covered but for a sliver of silhouette, depths within a cell, the same AO to within a
// hundredth on average - and a still frame draws the full mesh.
#include "gl_fixture.h"

#include "scene/load/gltf_loader.h"
#include "test_util.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace ssao;
using namespace ssaotest;

namespace {
class MotionLodGl : public GlTest {};
} // namespace

TEST_F(MotionLodGl, TheMovingFrameOfLargeSharedScenesSeesTheSameSurfacesWithinACell) {
    int compared = 0;
    for (const auto& f : ssaotest::sharedSceneFiles()) {
        const Scene scene = loadGltf(f.string());
        if (scene.triangleCount() < kMotionLodMinTriangles) continue;
        const int w = 410, h = 216; // the default window's moving frame (0.35 x 1172x616)
        auto r = std::make_unique<Renderer>(SSAOLAB_SHADER_DIR);
        r->enableMotionLods();
        r->setSize(w, h);
        r->setScene(scene);
        r->setCamera(sceneCamera(scene));
        r->setSettings(preset("vbao-medium"));
        r->render();
        ASSERT_EQ(r->drewLod(), -1) << "not moving: the full mesh";
        const Rendered full = readAll(*r);
        r->setMoving(true);
        const FrameReport moving = r->render();
        const int level = r->drewLod();
        if (level < 0) { // no level's cell is fine enough at this framing (FlightHelmet's)
            std::printf("%s: no level at its camera\n", f.filename().string().c_str());
            continue;
        }
        ++compared;
        const Rendered lod = readAll(*r);
        EXPECT_TRUE(finiteInRange(lod.ao, 0.0f, 1.0f)) << f;
        // Each draw takes the coarsest level whose cell covers at most a pixel at its own nearest
        // depth (DrawOptions::lodView): never more triangles than `level` everywhere, and on these
        // CAD parts at different depths some draws coarser.
        double triangles = -1, coarser = -1;
        for (const auto& p : moving.passes)
            for (const auto& [k, v] : p.counters)
                if (p.name == "gbuffer" && k == "triangles") triangles = v;
                else if (p.name == "gbuffer" && k == "motion_lod_draws_coarser") coarser = v;
        std::printf("%s: %.0f triangles drawn moving (level %d everywhere: %zu), %.0f draws coarser\n",
                    f.filename().string().c_str(), triangles, level, r->gpuScene()->lodTriangles(level), coarser);
        EXPECT_LE(triangles, double(r->gpuScene()->lodTriangles(level))) << f;
        EXPECT_GT(triangles, 0.0) << f;
        EXPECT_GE(coarser, 0.0) << f;
        // A pixel's world footprint at depth d: no draw's cell is larger there.
        const Camera cam = sceneCamera(scene);
        const float pixelPerDepth = 2.0f * std::tan(glm::radians(cam.fovYDeg) * 0.5f) / float(h);
        size_t geometry = 0, coverage = 0, near = 0, both = 0;
        double aoDiff = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const bool a = full.position.at(x, y, 3) > 0, b = lod.position.at(x, y, 3) > 0;
                geometry += a;
                coverage += a != b;
                if (!(a && b)) continue;
                ++both;
                const float cell = pixelPerDepth * full.depth.at(x, y); // at most the cell of this draw's level
                near += std::fabs(full.depth.at(x, y) - lod.depth.at(x, y)) <= std::sqrt(3.0f) * cell;
                aoDiff += std::fabs(full.ao.at(x, y) - lod.ao.at(x, y));
            }
        ASSERT_GT(both, 0u);
        const double coverageShare = double(coverage) / double(geometry), nearShare = double(near) / double(both);
        aoDiff /= double(both);
        std::printf("%s: level %d (cell %g), %zu geometry pixels: %.2f %% covered differently, %.1f %% within a cell's "
                    "diagonal in depth, mean |AO difference| %.4f\n",
                    f.filename().string().c_str(), level, r->gpuScene()->lodCell(level), geometry, 100.0 * coverageShare, 100.0 * nearShare, aoDiff);
        EXPECT_LT(coverageShare, 0.02) << f; // silhouettes move by at most a cell, under a pixel
        EXPECT_GT(nearShare, 0.95) << f;     // the rest: edges where the nearest surface changes
        EXPECT_LT(aoDiff, 0.01) << f; // normals of other cones never merge (motion_lod.h)
        r->setMoving(false);
        r->render();
        EXPECT_EQ(r->drewLod(), -1);
    }
    EXPECT_GE(compared, 2) << "2CylinderEngine and ReciprocatingSaw draw a level at their cameras";
}
