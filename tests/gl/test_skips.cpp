// Work a frame does not need is skipped, and skipping it changes nothing (skip.* rows): sky pixels,
// meshes outside the view, G-buffer targets nobody reads, and passes whose inputs did not change.
#include "gl_fixture.h"

#include "scene/scene.h"

#include <cmath>

using namespace ssao;
using namespace ssaotest;

namespace {
class Skips : public GlTest {};

double maxAbsDiff(const Image& a, const Image& b, const Image* mask = nullptr) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) return INFINITY;
    double worst = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < a.channels; ++c)
                if (!mask || mask->at(x, y) != 0.0f)
                    worst = std::max(worst, double(std::abs(a.at(x, y, c) - b.at(x, y, c))));
    return worst;
}

double passMs(const FrameReport& f, const std::string& name) {
    for (const auto& p : f.passes)
        if (p.name == name) return p.gpuMs;
    return -1.0;
}
} // namespace

TEST_F(Skips, SkyPixelsCostNothingAndSkippingThemChangesNoGeometryPixel) {
    const Scene scene = loadScene("builtin:showcase");
    for (const std::string tech : {"kernel", "sao", "hbao", "gtao", "vbao"}) {
        Settings s = defaultSettings();
        s.ao.technique = tech;
        auto r = makeRenderer(scene, s, 160, 90);
        r->render();
        const Rendered with = readAll(*r);
        s.skip.sky = false;
        r->setSettings(s);
        r->render();
        const Rendered without = readAll(*r);
        const Image mask = with.position.channel(3);
        EXPECT_EQ(maxAbsDiff(with.aoRaw, without.aoRaw), 0.0) << tech;
        EXPECT_EQ(maxAbsDiff(with.ao, without.ao, &mask), 0.0) << tech;
    }
}
