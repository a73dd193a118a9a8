// Reduced-resolution AO back to full size (denoise.upsample): joint filters at the AO's resolution
// and upsamples with passes/upsample_joint.frag; filter lets the filter's last pass upsample.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"

#include "scene/scene.h"
#include "settings/params.h"
#include "techniques/technique.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

using namespace ssao;
using namespace ssaotest;

namespace {
class Upsample : public GlTest {};

Settings with(const std::string& technique, const std::string& kind, const std::string& res, const std::string& up) {
    Settings s = defaultSettings();
    setParam(s, "ao.technique", technique);
    setParam(s, "denoise.kind", kind);
    setParam(s, "ao.resolution", res);
    setParam(s, "denoise.upsample", up);
    return s;
}

// A sentinel put in ao.denoised, then one forced frame: how many of its texels still hold it (all
// of them: the upsample pass wrote nothing; none: it ran). `ran`: the passes of that frame.
long sentinelsLeft(Renderer& r, std::vector<std::string>* ran = nullptr) {
    const float sentinel = 7.0f;
    glClearTexImage(r.texture("ao.denoised").id(), 0, GL_RED, GL_FLOAT, &sentinel);
    r.invalidate();
    const std::vector<std::string> passes = r.render().ran();
    if (ran) *ran = passes;
    const Image ao = readBack(r.texture("ao.denoised"), 1);
    return long(std::count(ao.data.begin(), ao.data.end(), sentinel));
}

// Top-row-first image row of GL row y (gl_FragCoord counts from the bottom).
int row(int glY, int height) { return height - 1 - glY; }
} // namespace

TEST_F(Upsample, EveryDenoiserAtEveryReducedResolutionKeepsAPlaneOpenAndAoInRange) {
    for (const auto& t : techniques())
        for (const char* kind : {"auto", "none", "box4", "gaussian", "bilateral"})
            for (const char* res : {"half", "quarter"})
                for (const char* up : {"joint", "filter"}) {
                    const std::string& technique = t.id;
                    const std::string what = technique + " " + kind + " " + res + " " + up;
                    const Rendered plane = render("builtin:plane", with(technique, kind, res, up), 160, 90);
                    EXPECT_TRUE(finiteInRange(plane.ao, 0.0f, 1.0f)) << what;
                    // A flat plane is unoccluded at any setting (the kernel's own floor aside: its
                    // hemisphere test may self-occlude a few % on llvmpipe's depth).
                    EXPECT_GT(geometryMean(plane, plane.ao), 0.97) << what;
                    const Rendered show = render("builtin:showcase", with(technique, kind, res, up), 160, 90);
                    EXPECT_TRUE(finiteInRange(show.ao, 0.0f, 1.0f)) << what;
                }
}

TEST_F(Upsample, JointKeepsEachAoTexelAtTheGBufferTexelItWasComputedAt) {
    // denoise none at half resolution: AO texel (i, j) was computed at G-buffer texel (2i, 2j)
    // (aoPixelUv), so there the joint upsample returns it unchanged - one corner, weight 1.
    const int w = 160, h = 90;
    const Rendered r = render("builtin:showcase", with("vbao", "none", "half", "joint"), w, h);
    long checked = 0, differ = 0;
    for (int j = 0; j < h / 2; ++j)
        for (int i = 0; i < w / 2; ++i) {
            const int fy = row(2 * j, h), ly = row(j, h / 2);
            if (r.position.at(2 * i, fy, 3) == 0.0f) continue; // sky
            ++checked;
            if (r.ao.at(2 * i, fy) != r.aoRaw.at(i, ly)) ++differ;
        }
    EXPECT_GT(checked, 2000);
    EXPECT_EQ(differ, 0) << "of " << checked;
}

TEST_F(Upsample, JointBleedsLessAcrossSilhouettesThanBilinear) {
    // Against the same technique at full resolution: near depth discontinuities (a neighbour 5 %
    // nearer or farther) the joint upsample stays closer than the bilinear one, which blends AO of
    // the surface behind into the one in front.
    const int w = 320, h = 180;
    const Rendered full = render("builtin:showcase", with("vbao", "none", "full", "joint"), w, h);
    const Rendered joint = render("builtin:showcase", with("vbao", "none", "half", "joint"), w, h);
    const Rendered bilinear = render("builtin:showcase", with("vbao", "none", "half", "filter"), w, h);
    double ej = 0, eb = 0;
    long n = 0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            const float z = full.depth.at(x, y);
            if (!(z > 0.0f)) continue;
            bool edge = false;
            for (int d = 0; d < 4; ++d) {
                const float zn = full.depth.at(x + (d == 0) - (d == 1), y + (d == 2) - (d == 3));
                edge |= !(zn > 0.0f) || std::abs(zn - z) > 0.05f * z;
            }
            if (!edge) continue;
            ej += std::pow(joint.ao.at(x, y) - full.ao.at(x, y), 2.0);
            eb += std::pow(bilinear.ao.at(x, y) - full.ao.at(x, y), 2.0);
            ++n;
        }
    ASSERT_GT(n, 300);
    ej = std::sqrt(ej / double(n));
    eb = std::sqrt(eb / double(n));
    EXPECT_LT(ej, eb * 0.9) << "edge RMSE to full resolution: joint " << ej << ", bilinear " << eb << " over " << n;
}

// Where nothing reads ao.denoised (a composite view without the error), the composite does the
// joint upsample itself and the upsample pass writes nothing: the same lit frame, one pass fewer.
TEST_F(Upsample, TheCompositeUpsamplesInlineWhereNothingElseReadsTheFullResolutionAo) {
    const Scene scene = loadScene("builtin:showcase");
    for (const char* kind : {"auto", "none", "gaussian", "bilateral"})
        for (const char* res : {"half", "quarter"}) {
            const std::string what = std::string(kind) + " " + res;
            Settings s = with("vbao", kind, res, "joint");
            setParam(s, "skip.fused_upsample", "true");
            auto separate = makeRenderer(scene, s, 160, 90);
            separate->render();
            const Image expected = readBack(separate->texture("composite"), 4);
            auto fused = makeRenderer(scene, s, 160, 90);
            fused->setWanted(std::set<std::string>{"composite"});
            fused->render();
            std::vector<std::string> ran;
            EXPECT_EQ(sentinelsLeft(*fused, &ran), 160L * 90L) << what; // the upsample pass wrote nothing
            EXPECT_FALSE(fused->graph().current("ao.denoised")) << what;
            if (std::string(kind) == "none") { // no filter: the denoise pass has nothing left to do
                EXPECT_EQ(std::find(ran.begin(), ran.end(), "denoise"), ran.end()) << what;
            }
            const Image got = readBack(fused->texture("composite"), 4);
            ASSERT_EQ(got.data.size(), expected.data.size()) << what;
            size_t differ = 0;
            for (size_t i = 0; i < got.data.size(); ++i)
                differ += got.data[i] != expected.data[i];
            EXPECT_EQ(differ, 0u) << what;
            // Wanting ao.denoised again brings its pass back, with the same composite.
            fused->setWanted(std::set<std::string>{"composite", "ao.denoised"});
            fused->render();
            EXPECT_TRUE(fused->graph().current("ao.denoised")) << what;
            const Image again = readBack(fused->texture("composite"), 4);
            EXPECT_EQ(again.data, expected.data) << what;
            const Image ao = readBack(fused->texture("ao.denoised"), 1);
            EXPECT_EQ(ao.data, readBack(separate->texture("ao.denoised"), 1).data) << what;
        }
    // With the setting off, wanting ao.denoised or not (the cursor crossing the image) re-runs nothing.
    {
        auto r = makeRenderer(scene, with("vbao", "auto", "half", "joint"), 160, 90);
        r->setWanted(std::set<std::string>{"composite"});
        r->render();
        r->setWanted(std::set<std::string>{"composite", "ao.denoised"});
        EXPECT_TRUE(r->render().ran().empty());
        r->setWanted(std::set<std::string>{"composite"});
        EXPECT_TRUE(r->render().ran().empty());
    }
    // Temporal accumulation needs ao.denoised as its history, and the setting is off by default:
    // neither is fused (the upsample pass writes over the sentinel).
    Settings t = with("vbao", "auto", "half", "joint");
    setParam(t, "skip.fused_upsample", "true");
    setParam(t, "temporal.enabled", "true");
    for (const Settings& s : {t, with("vbao", "auto", "half", "joint")}) {
        auto r = makeRenderer(scene, s, 160, 90);
        r->setWanted(std::set<std::string>{"composite"});
        r->render();
        EXPECT_EQ(sentinelsLeft(*r), 0L);
    }
}
