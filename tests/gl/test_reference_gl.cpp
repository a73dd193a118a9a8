// The reference traces the same view the rasteriser draws: its primary hits land where the
// G-buffer's do (same pixels covered, same linear depth on interior pixels), and judging a frame
// against it gives physically sensible numbers.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"

#include "metrics/evaluate.h"
#include "output/reference_report.h"
#include "reference/reference_ao.h"
#include "scene/scene.h"

#include <cmath>

using namespace ssao;
using namespace ssaotest;

namespace {
class ReferenceGl : public GlTest {};

// Pixels whose 3x3 neighbourhood is geometry in both images with smooth depth (no silhouette).
bool interior(const Image& gbDepth, const ReferenceImage& ref, int x, int y) {
    if (x < 1 || y < 1 || x >= ref.width - 1 || y >= ref.height - 1) return false;
    const float z = ref.depth[size_t(y) * ref.width + x];
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const size_t i = size_t(y + dy) * ref.width + (x + dx);
            if (ref.geometry[i] == 0.0f || gbDepth.at(x + dx, y + dy) <= 0.0f) return false;
            if (std::abs(ref.depth[i] - z) > 0.02f * z) return false;
        }
    return true;
}
} // namespace

TEST_F(ReferenceGl, PrimaryHitsAlignWithTheGBuffer) {
    for (const std::string& spec :
         {std::string("builtin:showcase"), std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf",
          std::string(SSAOLAB_SCENES_DIR) + "/2CylinderEngine/2CylinderEngine.gltf"}) {
      const Scene scene = loadScene(spec);
      for (Projection lens : {Projection::Perspective, Projection::Orthographic}) { // parallel rays too
        Camera cam = sceneCamera(scene);
        cam.projectionKind = lens;
        auto r = makeRenderer(scene, defaultSettings(), 320, 180, cam);
        r->render();
        const Rendered out = readAll(*r);
        EmbreeScene rt(scene);
        ReferenceTracer tracer(rt, r->camera(), 320, 180, {r->radiusAtCentre().world, 1});
        const ReferenceImage ref = tracer.image(); // primary hits only: no AO rays needed
        long agree = 0, interiorPixels = 0, off = 0;
        double worst = 0;
        for (int y = 0; y < 180; ++y)
            for (int x = 0; x < 320; ++x) {
                const bool g = out.depth.at(x, y) > 0.0f, t = ref.geometry[size_t(y) * 320 + x] > 0.0f;
                agree += g == t;
                if (!interior(out.depth, ref, x, y)) continue;
                ++interiorPixels;
                const double zr = ref.depth[size_t(y) * 320 + x], zg = out.depth.at(x, y);
                worst = std::max(worst, std::abs(zr - zg) / zr);
                off += std::abs(zr - zg) > 1e-4 * zr;
            }
        std::printf("%s, %s: coverage agrees on %.3f %% of pixels; %ld interior pixels, %ld differ by > 1e-4 "
                    "relative, worst %.2e\n",
                    scene.name.c_str(), projectionName(lens), 100.0 * agree / (320 * 180), interiorPixels, off, worst);
        EXPECT_GT(agree, long(0.995 * 320 * 180)) << scene.name << " " << projectionName(lens);
        EXPECT_GT(interiorPixels, 320 * 180 / 10) << scene.name << " " << projectionName(lens);
        // The CAD engine has a few coincident faces (2 of 18139 pixels): either surface is "right".
        EXPECT_LE(off, interiorPixels / 1000) << scene.name << ", worst " << worst << " " << projectionName(lens);
      }
    }
}

TEST_F(ReferenceGl, JudgingAFrameGivesSensibleNumbers) {
    // An open plane: the reference is exactly 1; the SSAO frame is nearly 1 too, so the error is
    // small, finite, and the PSNR high.
    const Scene plane = loadScene("builtin:plane");
    auto r = makeRenderer(plane, defaultSettings(), 160, 90);
    r->render();
    EmbreeScene rt(plane);
    const ReferenceSettings rs = referenceSettingsFor(r->radiusAtCentre(), 64, ReferenceVariant::Visibility);
    const ReferenceImage ref = traceReference(rt, r->camera(), 160, 90, rs);
    long geo = 0;
    for (size_t i = 0; i < ref.ao.size(); ++i)
        if (ref.geometry[i] > 0.0f) {
            ++geo;
            ASSERT_EQ(ref.ao[i], 1.0f);
        }
    ASSERT_GT(geo, 160 * 90 / 4);
    const Evaluation e = evaluate(readBack(r->texture("ao.denoised"), 1), ref);
    EXPECT_EQ(e.metrics.nonFinite, 0);
    EXPECT_EQ(e.metrics.geometryPixels, geo);
    EXPECT_LT(e.metrics.rmse, 0.05);
    EXPECT_LE(e.metrics.bias, 0.0); // AO can only be at or below the unoccluded reference
    EXPECT_GT(e.metrics.psnrGeometrySrgb, 25.0);

    // CornellBox: corners are occluded in the reference, and the default SSAO misses some of it.
    const Scene cornell = loadScene(std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf");
    auto rc = makeRenderer(cornell, defaultSettings(), 240, 135);
    rc->render();
    EmbreeScene rtc(cornell);
    const ReferenceImage refc =
        traceReference(rtc, rc->camera(), 240, 135, referenceSettingsFor(rc->radiusAtCentre(), 128, ReferenceVariant::Visibility));
    const Evaluation ec = evaluate(readBack(rc->texture("ao.denoised"), 1), refc);
    std::printf("CornellBox 240x135 default kernel: RMSE %.4f bias %+.4f PSNR %.2f dB SSIM %.4f, edge %.4f "
                "interior %.4f\n",
                ec.metrics.rmse, ec.metrics.bias, ec.metrics.psnrGeometrySrgb, ec.metrics.ssim,
                ec.metrics.rmseEdge, ec.metrics.rmseInterior);
    EXPECT_GT(ec.metrics.rmse, 0.0);
    EXPECT_LT(ec.metrics.rmse, 0.5);
    EXPECT_GT(ec.metrics.edgePixels, 0);
    EXPECT_GT(ec.metrics.interiorPixels, ec.metrics.edgePixels);
    EXPECT_GT(ec.metrics.ssim, 0.5);
}
