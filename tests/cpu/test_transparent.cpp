// Transparent glTF surfaces (scene.h Transparent): BLEND and transmissive materials are skipped by
// default - as engines draw them after the AO, neither in the G-buffer nor an occluder - and drawn
// as solids with `--transparent opaque`. CornellBox's glass sphere and FlightHelmet's lenses are
// BLEND.
#include "reference/embree_scene.h"
#include "reference/reference_ao.h"
#include "scene/load/gltf_loader.h"
#include "scene/scene.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using namespace ssao;

namespace {
struct ModeScope { // restores the process-wide mode whatever the test does
    Transparent saved = transparentMode();
    ~ModeScope() { setTransparentMode(saved); }
};
Scene load(const std::string& file, Transparent t) {
    setTransparentMode(t);
    return loadGltf(std::string(SSAOLAB_SCENES_DIR) + file);
}
} // namespace

TEST(Transparent, BlendSurfacesAreSkippedByDefaultAndCountedEitherWay) {
    ModeScope scope;
    EXPECT_EQ(Transparent::Skip, Transparent{}) << "skip is the default";
    for (const char* file : {"/CornellBox/cornellBox.gltf", "/FlightHelmet/FlightHelmet.gltf"}) {
        const Scene skip = load(file, Transparent::Skip), opaque = load(file, Transparent::Opaque);
        EXPECT_GT(skip.materials.blend, 0u) << file;
        EXPECT_TRUE(skip.materials.blendSkipped) << file;
        EXPECT_FALSE(opaque.materials.blendSkipped) << file;
        EXPECT_EQ(skip.materials.blend, opaque.materials.blend) << file;
        EXPECT_EQ(skip.triangleCount(), skip.materials.opaque + skip.materials.mask) << file;
        EXPECT_EQ(opaque.triangleCount(), opaque.materials.opaque + opaque.materials.mask + opaque.materials.blend)
            << file;
    }
    EXPECT_THROW(parseTransparent("glass"), Error);
}

TEST(Transparent, WithoutTheGlassSphereTheReferenceOnlyOpensUp) {
    // The same camera and rays; where both frames see the same surface (same depth), removing an
    // occluder can only turn occluded rays into open ones: the skip reference is never darker
    // (beyond a grazing ray's rounding), and under the sphere it is much brighter.
    ModeScope scope;
    const Scene skip = load("/CornellBox/cornellBox.gltf", Transparent::Skip);
    const Scene opaque = load("/CornellBox/cornellBox.gltf", Transparent::Opaque);
    ASSERT_TRUE(opaque.camera.has_value());
    Camera cam = *opaque.camera;
    EmbreeScene a(skip), b(opaque);
    const float R = 0.05f * 2.0f * opaque.bounds.radius();
    const int w = 96, h = 54;
    const ReferenceImage rs = traceReference(a, cam, w, h, {R, 64});
    const ReferenceImage ro = traceReference(b, cam, w, h, {R, 64});
    long same = 0, darker = 0, opened = 0;
    double sumSkip = 0, sumOpaque = 0;
    for (size_t i = 0; i < rs.ao.size(); ++i) {
        if (!(rs.geometry[i] > 0.0f && ro.geometry[i] > 0.0f) || rs.depth[i] != ro.depth[i]) continue;
        ++same;
        // The rays need not be the same ones (the sequence follows the primitive hit, whose index
        // moves when triangles go): a pixel may be darker by its noise, not by three times it.
        const double p = ro.ao[i], sigma = std::sqrt(std::max(p * (1.0 - p), 1.0 / 64) / 64.0);
        darker += rs.ao[i] < ro.ao[i] - 3.0 * sigma;
        sumSkip += rs.ao[i], sumOpaque += ro.ao[i];
        opened += rs.ao[i] > ro.ao[i] + 0.05f;
    }
    std::printf("CornellBox %dx%d, R = %.3f, 64 rays: where both see the same surface (%ld pixels) the reference "
                "reads %.4f with the glass sphere skipped, %.4f with it opaque; %ld pixels open up by more than 0.05\n",
                w, h, R, same, sumSkip / double(same), sumOpaque / double(same), opened);
    ASSERT_GT(same, 1000);
    EXPECT_EQ(darker, 0);
    EXPECT_GT(sumSkip, sumOpaque);
    EXPECT_GT(opened, 5) << "the floor and walls the sphere shaded";
}
