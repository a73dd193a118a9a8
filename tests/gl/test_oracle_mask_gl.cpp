// The screen-space oracle (reference/screen_layers.h) on cut-out and transparent surfaces, against
// the reference and the G-buffer: the checkerboard lid of tests/lid_scene.h seen at a slant, so the
// floor shows through the open cells and its AO rays leave under the solid ones. A MASK surface is
// a sheet: the oracle lets a ray through unless it crosses a solid texel, as the reference does
// (before, each solid cell was a slab R thick, and the floor seen through the holes read 0.3 darker).
#include "gl_fixture.h"
#include "cpu/reference_scenes.h"
#include "lid_scene.h"

#include "reference/embree_scene.h"
#include "reference/reference_ao.h"
#include "scene/load/gltf_loader.h"

#include <cmath>
#include <cstdio>

using namespace ssao;
using namespace ssaotest;

namespace {
class OracleMaskGl : public GlTest {};

struct ModeScope {
    Transparent saved = transparentMode();
    ~ModeScope() { setTransparentMode(saved); }
};

Camera slantCamera() {
    Camera c;
    c.eye = {0.3f, 2.0f, 1.5f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.up = {0, 1, 0};
    c.fovYDeg = 40.0f;
    c.nearZ = 0.5f;
    c.farZ = 10.0f;
    c.clip = ClipMode::Fixed;
    return c;
}

ReferenceSettings oracleSettings(float R, int rays) {
    ReferenceSettings s{R, rays};
    s.visibility = ReferenceVisibility::Screen;
    return s;
}

// Where the view ray to the floor point `p` crosses the lid's plane inside the lid's square.
bool throughLid(const Camera& c, const LidSpec& spec, const glm::vec3& p) {
    const float t = (spec.height - c.eye.y) / (p.y - c.eye.y);
    const glm::vec3 q = c.eye + (p - c.eye) * t;
    return std::abs(q.x) < spec.lidHalf && std::abs(q.z) < spec.lidHalf;
}

struct Comparison {
    long pixels = 0, gbufferAgrees = 0;
    double sumDiff = 0, sumSq = 0, sumNoise = 0; // oracle - truth; both estimates' variance
    double mean() const { return sumDiff / double(pixels); }
    double rms() const { return std::sqrt(sumSq / double(pixels)); }
    double noise() const { return std::sqrt(sumNoise / double(pixels)); }
};

// The floor pixels seen through the lid's square (through its open cells), oracle against truth.
Comparison floorThroughLid(const Camera& cam, const LidSpec& spec, const Rendered& gb, const ReferenceImage& truth,
                           const ReferenceImage& oracle, int w, int h) {
    Comparison c;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            if (truth.geometry[i] == 0.0f || truth.ambiguous[i] > 0.0f) continue;
            const glm::vec3 p = hitPosition(cam, w, h, x, y, truth.depth[i]);
            if (std::abs(p.y) > 1e-3f || !throughLid(cam, spec, p)) continue;
            ++c.pixels;
            c.gbufferAgrees += std::abs(gb.depth.data[i] - truth.depth[i]) < 0.01f * truth.depth[i];
            const double d = double(oracle.ao[i]) - double(truth.ao[i]);
            c.sumDiff += d;
            c.sumSq += d * d;
            c.sumNoise += double(truth.stdErr[i]) * truth.stdErr[i] + double(oracle.stdErr[i]) * oracle.stdErr[i];
        }
    return c;
}
} // namespace

TEST_F(OracleMaskGl, TheOracleSeesThroughCutOutTexelsAsTheReferenceDoes) {
    LidSpec spec; // 8 x 8 checkerboard, half open, 0.25 over the floor
    const Scene scene = loadGltf(writeLidScene("oracle_lid_gl", spec));
    const Camera cam = slantCamera();
    const int w = 160, h = 90;
    const float R = 1.0f;
    auto r = makeRenderer(scene, defaultSettings(), w, h, cam);
    r->render();
    const Rendered gb = readAll(*r);
    EmbreeScene rt(scene);
    const ReferenceImage truth = traceReference(rt, cam, w, h, {R, 256});
    const ReferenceImage oracle = traceReference(rt, cam, w, h, oracleSettings(R, 256));
    const Comparison c = floorThroughLid(cam, spec, gb, truth, oracle, w, h);
    std::printf("floor through the lid's open cells, %dx%d, R %.2g: %ld pixels (G-buffer agrees on %ld); oracle - "
                "truth mean %+.4f, RMS %.4f, the two estimates' noise %.4f\n",
                w, h, R, c.pixels, c.gbufferAgrees, c.mean(), c.rms(), c.noise());
    ASSERT_GT(c.pixels, 300) << "the floor shows through the open cells";
    EXPECT_GT(double(c.gbufferAgrees), 0.97 * double(c.pixels)) << "the G-buffer holds what the oracle's layer holds";
    EXPECT_LT(std::abs(c.mean()), 0.02) << "the oracle is as open as the truth under the cut-out cells";
    EXPECT_LT(c.rms(), 1.5 * c.noise()) << "the two agree within their noise";
}

TEST_F(OracleMaskGl, BlendSurfacesAreWhatTheReferenceMakesOfThemSkippedOrOpaque) {
    ModeScope scope;
    LidSpec spec;
    spec.alphaMode = "BLEND";
    const Camera cam = slantCamera();
    const int w = 96, h = 54;
    const float R = 1.0f;
    for (Transparent mode : {Transparent::Skip, Transparent::Opaque}) {
        setTransparentMode(mode);
        const Scene scene = loadGltf(writeLidScene("oracle_blend_gl", spec));
        auto r = makeRenderer(scene, defaultSettings(), w, h, cam);
        r->render();
        const Rendered gb = readAll(*r);
        EmbreeScene rt(scene);
        const ReferenceImage truth = traceReference(rt, cam, w, h, {R, 64});
        const ReferenceImage oracle = traceReference(rt, cam, w, h, oracleSettings(R, 64));
        long lid = 0, agree = 0, same = 0, n = 0;
        double worst = 0;
        for (size_t i = 0; i < truth.ao.size(); ++i) {
            if (truth.geometry[i] == 0.0f) continue;
            ++n;
            const glm::vec3 p = hitPosition(cam, w, h, int(i % w), int(i / w), truth.depth[i]);
            lid += std::abs(p.y - spec.height) < 1e-3f;
            agree += std::abs(gb.depth.data[i] - truth.depth[i]) < 0.01f * truth.depth[i];
            same += oracle.depth[i] == truth.depth[i] && oracle.geometry[i] == truth.geometry[i];
            if (mode == Transparent::Skip) worst = std::max(worst, std::abs(double(oracle.ao[i]) - truth.ao[i]));
        }
        std::printf("BLEND lid, %s: %ld of %ld pixels see the lid; G-buffer agrees on %ld, the oracle's layer on %ld\n",
                    mode == Transparent::Skip ? "skipped" : "opaque", lid, n, agree, same);
        EXPECT_EQ(same, n) << "the oracle's layer is the reference's primary hits";
        EXPECT_GT(double(agree), 0.99 * double(n)) << "the G-buffer draws what the reference traces";
        if (mode == Transparent::Skip) {
            EXPECT_EQ(lid, 0) << "a skipped BLEND surface is in neither";
            EXPECT_EQ(worst, 0.0) << "an open floor: the oracle and the truth both read 1";
        } else {
            EXPECT_GT(lid, 300) << "drawn as opaque, the lid is a surface of both";
        }
    }
}
