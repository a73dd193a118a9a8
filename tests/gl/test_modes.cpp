// Every value of every parameter: finite, in [0,1], and it changes the image it claims to change
// (a mode with no effect is a bug) - except the skip switches, which must change nothing. The list comes from the parameter table, so a new row is
// swept without editing this file.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"

#include "scene/scene.h"

#include <cmath>
#include <set>

using namespace ssao;
using namespace ssaotest;

namespace {
class Modes : public GlTest {};

// Makes `p` apply: each condition's key set to its first allowed value (recursively).
void makeApply(Settings& s, const Param& p) {
    for (const auto& c : p.when) {
        const Param* q = findParam(c.key);
        ASSERT_NE(q, nullptr) << c.key;
        makeApply(s, *q);
        setParam(s, c.key, c.values.front());
    }
}

std::vector<double> valuesToTry(const Param& p) {
    if (p.type == Param::Type::Enum || p.type == Param::Type::Bool) {
        std::vector<double> v;
        for (double i = p.min; i <= p.max; i += 1.0)
            v.push_back(i);
        return v;
    }
    return {p.min, p.max};
}

struct Images {
    Image gbuffer, raw, ao, composite, mask;
};
Images renderImages(Renderer& r, const Settings& s) {
    r.setSettings(s);
    do // temporal accumulation: all of its frames
        r.render();
    while (r.accumulating());
    Image g = readBack(r.texture("gbuffer.position"), 3), n = readBack(r.texture("gbuffer.normal"), 3);
    g.data.insert(g.data.end(), n.data.begin(), n.data.end());
    return {g, readBack(r.texture("ao.raw"), 1), readBack(r.texture("ao.denoised"), 1),
            readBack(r.texture("composite"), 3), readBack(r.texture("gbuffer.position"), 4).channel(3)};
}

bool differ(const Image& a, const Image& b) {
    return a.width != b.width || a.data != b.data;
}
} // namespace

TEST_F(Modes, EveryValueOfEveryParameterIsFiniteAndChangesTheImage) {
    const Scene scene = loadScene("builtin:showcase");
    auto r = makeRenderer(scene, defaultSettings(), 96, 54);
    int tried = 0;
    // Limits that only bind beyond this test's scale (a 96x54 frame has no 1024-pixel radius): one of
    // their extremes must change the image, not both.
    const std::set<std::string> limits = {"hbao.max_radius_px"};
    // Rows that only act once the camera moves (a still frame cannot show them): test_temporal.cpp's
    // moving-camera tests show what the plane tolerance and the memory in motion do.
    const std::set<std::string> movingOnly = {"temporal.plane_tolerance", "temporal.moving_frames"};
    // Rows that choose another route to the same frame on a still camera: the single-pass second
    // layer reprojects the previous frame, which is this one (test_second_layer.cpp moves the camera).
    const std::set<std::string> sameWhenStill = {"gbuffer.second_layer_build"};
    for (const Param& p : paramTable()) {
        Settings base = defaultSettings();
        makeApply(base, p);
        // The position pyramid only serves taps >= 16 px away: give those rows a radius that reaches.
        if (p.key.size() > 8 && p.key.substr(p.key.size() - 8) == ".pyramid") base.ao.radiusScene = 0.3f;
        // The guard band (taps off the frame), the back layer (the bitmask's thickness) and the second
        // layer (what the depth buffer hides) act on the horizon techniques' taps, not on the kernel.
        const bool band = p.key == "gbuffer.guard_band_px" || p.key == "gbuffer.back_faces" ||
                          p.key.rfind("gbuffer.second_layer", 0) == 0;
        if (band) base.ao.technique = "vbao";
        const Images ref = renderImages(*r, base);
        int changedLimit = 0;
        for (double v : valuesToTry(p)) {
            Settings s = base;
            p.set(s, v);
            if (s == base) continue; // the default itself
            const std::string what = p.key + "=" + p.format(v);
            const Images out = renderImages(*r, s);
            EXPECT_TRUE(finiteInRange(out.raw, 0.0f, 1.0f)) << what;
            EXPECT_TRUE(finiteInRange(out.ao, 0.0f, 1.0f)) << what;
            // The composite group shades, the G-buffer group stores (fp32 and fp16 normals can give the
            // same AO), the denoise group filters; every other group changes the AO itself.
            if (movingOnly.count(p.key)) {
                // finite and in range is all a still frame can check
            } else if (sameWhenStill.count(p.key)) {
                EXPECT_EQ(maxAbsDiff(out.raw, ref.raw), 0.0) << what << " changed a still frame";
            } else if (p.group() == "skip") {
                // A skip is exact: the same image, only less work (to float rounding: another shader
                // variant may contract a multiply-add differently).
                EXPECT_EQ(maxAbsDiff(out.gbuffer, ref.gbuffer), 0.0) << what << " changed the G-buffer";
                EXPECT_LT(maxAbsDiff(out.raw, ref.raw), 1e-6) << what << " changed the raw AO";
                EXPECT_LT(maxAbsDiff(out.ao, ref.ao, &ref.mask), 1e-6) << what << " changed the AO";
                EXPECT_LT(maxAbsDiff(out.composite, ref.composite), 1e-5) << what << " changed the composite";
            } else if (band) {
                // Positions beyond the frame: the G-buffer itself is the same, the AO near the edges not.
                EXPECT_EQ(maxAbsDiff(out.gbuffer, ref.gbuffer), 0.0) << what;
                EXPECT_TRUE(differ(out.raw, ref.raw)) << what << " changed nothing";
            } else if (limits.count(p.key))
                changedLimit += differ(out.raw, ref.raw) || differ(out.ao, ref.ao);
            else if (p.group() == "gbuffer")
                EXPECT_TRUE(differ(out.gbuffer, ref.gbuffer)) << what << " changed nothing";
            else if (p.group() == "composite")
                EXPECT_TRUE(differ(out.composite, ref.composite)) << what << " changed nothing";
            else if (p.group() == "denoise" || p.group() == "temporal")
                EXPECT_TRUE(differ(out.ao, ref.ao)) << what << " changed nothing";
            else
                EXPECT_TRUE(differ(out.raw, ref.raw)) << what << " changed nothing";
            ++tried;
        }
        if (limits.count(p.key)) {
            EXPECT_GE(changedLimit, 1) << p.key << " never changed the image";
        }
    }
    EXPECT_GT(tried, 40);
}

TEST_F(Modes, EveryKernelDenoiseSeparableCombinationShowsOcclusion) {
    for (KernelShape k : {KernelShape::Hemisphere, KernelShape::Sphere})
        for (DenoiseKind d : {DenoiseKind::None, DenoiseKind::Box4, DenoiseKind::Gaussian})
            for (bool sep : {false, true}) {
                Settings s = defaultSettings();
                s.kernel.shape = k;
                s.denoise.kind = d;
                s.kernel.separable = sep;
                Rendered r = render("builtin:showcase", s, 160, 90);
                const std::string what = std::string(k == KernelShape::Sphere ? "sphere" : "hemisphere") +
                                         "/denoise" + std::to_string(int(d)) + (sep ? "/separable" : "");
                EXPECT_TRUE(finiteInRange(r.aoRaw, 0.0f, 1.0f)) << what << " ao.raw";
                EXPECT_TRUE(finiteInRange(r.ao, 0.0f, 1.0f)) << what << " ao.denoised";
                Image mask = r.position.channel(3);
                EXPECT_LT(stats(r.aoRaw, &mask).min, 0.8) << what << ": the showcase has occluded corners";
            }
}
