// The one display mapping, on the GPU: depth and position views are readable on real scenes,
// AO keeps its physical [0,1], NaN shows magenta, false colour is viridis.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"

#include "display/view_painter.h"
#include "scene/scene.h"

#include <cmath>
#include <set>

using namespace ssao;
using namespace ssaotest;

namespace {
class Views : public GlTest {};

// Readability of a view over geometry pixels, per channel: how many grey levels it uses and how
// spread they are (the old mapping used one level: 100 % white on CornellBox).
struct Spread {
    int levels = 0;
    double stddev = 0;
};
Spread spread(const Image& view, const Image& mask, int c) {
    std::set<int> levels;
    double s = 0, s2 = 0, n = 0;
    for (int y = 0; y < view.height; ++y)
        for (int x = 0; x < view.width; ++x) {
            if (!(mask.at(x, y) > 0.0f)) continue;
            const double g = view.at(x, y, c);
            levels.insert(int(std::lround(g * 255.0)));
            s += g, s2 += g * g, n += 1;
        }
    const double mean = s / n;
    return {int(levels.size()), std::sqrt(std::max(0.0, s2 / n - mean * mean))};
}
} // namespace

TEST_F(Views, DepthAndPositionViewsAreReadableOnRealScenes) {
    for (const char* rel : {"CornellBox/cornellBox.gltf", "2CylinderEngine/2CylinderEngine.gltf",
                            "ShaderBall/shader_ball.gltf", "Lantern/Lantern.gltf"}) {
        const std::string path = std::string(SSAOLAB_SCENES_DIR) + "/" + rel;
        auto r = makeRenderer(loadScene(path), defaultSettings(), 256, 144);
        r->render();
        ViewPainter painter;
        gl::RenderTarget view;
        const Image mask = readBack(r->texture("gbuffer.depth"), 1);
        for (const char* buffer : {"gbuffer.depth", "gbuffer.position", "gbuffer.zbuffer"}) {
            const DisplayRange range = painter.paint(r->resource(buffer), r->resource("gbuffer.depth"), {},
                                                     view, r->shaders(), r->triangle());
            EXPECT_TRUE(range.fitted) << rel << " " << buffer;
            const Image img = readBack(view.texture(), 3);
            const int channels = std::string(buffer) == "gbuffer.position" ? 3 : 1;
            for (int c = 0; c < channels; ++c) {
                const Spread g = spread(img, mask, c);
                std::printf("%-38s %-16s ch%d range %.4g..%.4g: %3d grey levels, sd %.2f\n", rel, buffer, c,
                            range.lo[c], range.hi[c], g.levels, g.stddev);
                EXPECT_GE(g.levels, 40) << rel << " " << buffer << " channel " << c << ": not washed out";
                EXPECT_GT(g.stddev, 0.1) << rel << " " << buffer << " channel " << c << ": not flat grey";
            }
        }
        // AO keeps its physical range unless asked to fit.
        const DisplayRange ao = painter.paint(r->resource("ao.raw"), r->resource("gbuffer.depth"), {}, view,
                                              r->shaders(), r->triangle());
        EXPECT_FALSE(ao.fitted);
        EXPECT_EQ(ao.lo.x, 0.0f);
        EXPECT_EQ(ao.hi.x, 1.0f);
    }
}

TEST_F(Views, NanIsMagentaAndFalseColourIsViridis) {
    Resource src, mask;
    src.desc.name = "test.values";
    src.desc.display = ssao::Display::Unit;
    src.texture = gl::Texture2D(4, 1, GL_R32F, "test.values");
    const float values[4] = {0.0f, 1.0f, NAN, 0.5f};
    glTextureSubImage2D(src.texture.id(), 0, 0, 0, 4, 1, GL_RED, GL_FLOAT, values);
    mask.desc.name = "test.mask";
    mask.texture = gl::Texture2D(4, 1, GL_R32F, "test.mask");
    const float ones[4] = {1, 1, 1, 1};
    glTextureSubImage2D(mask.texture.id(), 0, 0, 0, 4, 1, GL_RED, GL_FLOAT, ones);
    mask.version = 1;
    gl::ShaderLibrary shaders(SSAOLAB_SHADER_DIR);
    gl::FullscreenTriangle tri;
    ViewPainter painter;
    gl::RenderTarget view;
    painter.paint(src, mask, ViewStyle{false, true}, view, shaders, tri);
    const Image img = readBack(view.texture(), 3);
    EXPECT_NEAR(img.at(0, 0, 0), 0.267f, 0.01f); // viridis(0): dark purple
    EXPECT_NEAR(img.at(0, 0, 2), 0.329f, 0.01f);
    EXPECT_NEAR(img.at(1, 0, 0), 0.992f, 0.01f); // viridis(1): yellow
    EXPECT_NEAR(img.at(1, 0, 1), 0.906f, 0.01f);
    EXPECT_EQ(img.at(2, 0, 0), 1.0f); // NaN: magenta
    EXPECT_EQ(img.at(2, 0, 1), 0.0f);
    EXPECT_EQ(img.at(2, 0, 2), 1.0f);
    painter.paint(src, mask, ViewStyle{}, view, shaders, tri);
    EXPECT_NEAR(readBack(view.texture(), 3).at(3, 0, 1), 0.5f, 0.01f); // grey: value as is
}

// The app fits a range from ~65k texels picked on the GPU (display/fit_samples.h) instead of reading
// the whole buffer back: the same texels, so the same range as the PNG previews' fit of the whole
// read-back image, to the bit, for every buffer of the frame (reduced-resolution AO included, whose
// geometry mask is at another size), at sizes where the fit strides and where it does not.
TEST_F(Views, GpuPickedFitEqualsTheFitOfTheWholeReadBack) {
    for (const char* rel : {"CornellBox/cornellBox.gltf", "2CylinderEngine/2CylinderEngine.gltf"})
        for (const glm::ivec2 size : {glm::ivec2(333, 201), glm::ivec2(640, 360), glm::ivec2(200, 100)}) {
            Settings s = defaultSettings();
            s.ao.resolution = AoResolution::Half;
            auto r = makeRenderer(loadScene(std::string(SSAOLAB_SCENES_DIR) + "/" + rel), s, size.x, size.y);
            r->render();
            ViewPainter painter;
            gl::RenderTarget view;
            const Resource& mask = r->resource("gbuffer.depth");
            int fitted = 0;
            for (const Resource* res : r->buffers()) {
                const ViewStyle style{true, false}; // fit every buffer, not only depth and positions
                const Image raw = readBack(res->texture, std::max(1, res->desc.channels));
                const DisplayRange whole = painter.paint(*res, mask, style, view, r->shaders(), r->triangle(), &raw);
                const DisplayRange picked = painter.paint(*res, mask, style, view, r->shaders(), r->triangle());
                const std::string what = std::string(rel) + " " + res->desc.name + " " + std::to_string(size.x);
                EXPECT_EQ(picked.fitted, whole.fitted) << what;
                for (int c = 0; c < 3; ++c) {
                    EXPECT_EQ(picked.lo[c], whole.lo[c]) << what << " channel " << c;
                    EXPECT_EQ(picked.hi[c], whole.hi[c]) << what << " channel " << c;
                }
                fitted += whole.fitted;
            }
            EXPECT_GE(fitted, 5) << rel; // depth, positions, z-buffer, the AO at both stages...
        }
}
