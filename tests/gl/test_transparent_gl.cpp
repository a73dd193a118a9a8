// CornellBox's glass sphere (BLEND) through the GL renderer: with --transparent opaque the frame is
// bit for bit the one ssaolab drew before transparency was handled (a hash of the frame the build
// before it wrote, assets/golden/cornell_opaque.json); skipped, the floor under the sphere reads as
// open as the reference says, no longer shaded by glass.
#include "gl_fixture.h"

#include "reference/embree_scene.h"
#include "reference/reference_ao.h"
#include "scene/load/gltf_loader.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

using namespace ssao;
using namespace ssaotest;

namespace {
class TransparentGl : public GlTest {};
struct ModeScope {
    Transparent saved = transparentMode();
    ~ModeScope() { setTransparentMode(saved); }
};
// FNV-1a of an image's float bits, as hex.
std::string fnv(const Image& img) {
    uint64_t h = 1469598103934665603ull;
    for (float f : img.data) {
        uint32_t u;
        std::memcpy(&u, &f, 4);
        for (int k = 0; k < 4; ++k)
            h = (h ^ ((u >> (8 * k)) & 0xFF)) * 1099511628211ull;
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)h);
    return buf;
}
Scene cornell(Transparent t) {
    setTransparentMode(t);
    return loadGltf(std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf");
}
} // namespace

TEST_F(TransparentGl, OpaqueIsTheFrameOfBeforeAndSkipOpensTheFloorUnderTheSphere) {
    ModeScope scope;
    const int w = 160, h = 90;
    const Settings s = preset("learnopengl"); // a seed's reproduction: fixed settings, world radius 0.5
    const Scene opaque = cornell(Transparent::Opaque), skip = cornell(Transparent::Skip);
    auto ro = makeRenderer(opaque, s, w, h);
    ro->render();
    const Rendered a = readAll(*ro);
    const nlohmann::json golden =
        nlohmann::json::parse(std::ifstream(std::string(SSAOLAB_ASSET_DIR) + "/golden/cornell_opaque.json"));
    EXPECT_EQ(fnv(a.depth), golden["gbuffer.depth"].get<std::string>()) << "the G-buffer moved";
    EXPECT_EQ(fnv(a.aoRaw), golden["ao.raw"].get<std::string>()) << "the AO moved";
    EXPECT_EQ(fnv(a.ao), golden["ao.denoised"].get<std::string>()) << "the denoised AO moved";

    // Skipped: the bitmask at the scene's default radius (5 % of the diagonal), 320x180.
    Settings sv = defaultSettings();
    sv.ao.technique = "vbao";
    const int w2 = 320, h2 = 180;
    auto rs = makeRenderer(skip, sv, w2, h2);
    rs->render();
    const Rendered b = readAll(*rs);
    auto ro2 = makeRenderer(opaque, sv, w2, h2);
    ro2->render();
    const Rendered a2 = readAll(*ro2);
    EmbreeScene to(opaque), ts(skip);
    const float R = sv.ao.radiusScene * 2.0f * skip.bounds.radius();
    const ReferenceImage refO = traceReference(to, a2.camera, w2, h2, {R, 256});
    const ReferenceImage refS = traceReference(ts, b.camera, w2, h2, {R, 256});
    // The sphere's footprint: pixels that see the same surface either way (the floor and walls
    // around and under it) whose reference opens up by more than 0.1 without the sphere.
    long n = 0;
    double aoSkip = 0, aoOpaque = 0, errSkip = 0, errOpaque = 0;
    for (size_t i = 0; i < refS.ao.size(); ++i) {
        if (!(refS.geometry[i] > 0) || std::abs(refS.depth[i] - refO.depth[i]) > 1e-4f * refS.depth[i]) continue;
        if (refS.ao[i] < refO.ao[i] + 0.1f) continue;
        ++n;
        aoSkip += b.ao.data[i], aoOpaque += a2.ao.data[i];
        errSkip += std::abs(b.ao.data[i] - refS.ao[i]), errOpaque += std::abs(a2.ao.data[i] - refS.ao[i]);
    }
    ASSERT_GT(n, 20) << "the sphere shades the floor in the opaque reference";
    std::printf("CornellBox %dx%d, vbao: %ld pixels the glass sphere shaded; AO there %.3f skipped vs %.3f "
                "opaque; |AO - skip reference| %.3f vs %.3f\n",
                w2, h2, n, aoSkip / n, aoOpaque / n, errSkip / n, errOpaque / n);
    EXPECT_GT(aoSkip, aoOpaque) << "brighter without the sphere";
    EXPECT_LT(errSkip, errOpaque) << "closer to what the reference says of the open floor";
    EXPECT_TRUE(finiteInRange(b.ao, 0.0f, 1.0f));
}
