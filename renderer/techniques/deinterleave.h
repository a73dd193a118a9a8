// Deinterleaved ("cache-aware") AO, ao.deinterleave: Bavoil & Jansen 2013 ("Particle Shadows &
// Cache-Efficient Post-Processing", GTC) as NVIDIA's gl_ssao and HBAO+ do it. The G-buffer's
// positions and normals are split into 16 layers of a quarter of the size each, layer (i, j)
// holding pixels (4x + i, 4y + j); the technique's own shader runs over each layer with one jitter
// for the whole layer (its noise taken at the layer's cell of a 4x4 tile: shaders/include/noise.glsl
// AO_DEINTERLEAVED), so neighbouring lanes read neighbouring texels of a small texture with the
// same offsets; the 16 results are interleaved back into ao.raw.
// What it changes: every tap lands on a 4-pixel grid of the full frame (its offset is whole layer
// pixels), and the first step is at least 4 pixels away. gl_ssao measured 1.9x for HBAO on a
// Quadro M6000; on llvmpipe neighbouring lanes gain little from sharing cache lines
// (docs/bench/skips.md).
#pragma once
#include "gl/resources.h"

#include "../../shaders/include/bindings.h"

#include <glm/glm.hpp>

#include <array>
#include <functional>

namespace ssao {

class Deinterleaver {
  public:
    static constexpr int kSide = 4, kLayers = kSide * kSide;

    // Layer size of a w x h frame: ceil(w / 4) x ceil(h / 4) (texels past the frame are sky).
    static glm::ivec2 layerSize(int w, int h) { return {(w + kSide - 1) / kSide, (h + kSide - 1) / kSide}; }
    // Layer l's cell of the 4x4 tile (i, j): it holds pixels (4x + i, 4y + j), x and y from the left
    // and bottom (GL window coordinates).
    static glm::ivec2 cell(int layer) { return {layer % kSide, layer / kSide}; }
    // The frame block a layer's draw reads: the same camera, the layer's size as the viewport, and
    // proj[1][1] scaled so that a length in pixels (framePixelsPerUnit: proj[1][1] viewport.y / 2)
    // is a quarter of the frame's exactly, though the layer is ceil(h / 4) tall.
    static gpu::FrameConstants layerFrame(const gpu::FrameConstants& frame, glm::ivec2 layer);
    // A uv of layer `l` (its texel centres at (x + 0.5) / layer size) as a uv of the w x h frame.
    static glm::vec2 frameUv(glm::vec2 layerUv, int l, int w, int h);

    // Splits `positions` (and `normals`, when given) of the frame `frame` describes into the
    // layers: two draws of 8 targets each per texture (shaders/passes/deinterleave.frag, whose
    // program `splitProgram` is). Remembers the frame block bound before, for restoreFrame().
    void split(GLuint splitProgram, const gl::Texture2D& positions, const gl::Texture2D* normals,
               const gpu::FrameConstants& frame, const std::function<void()>& drawFullscreen);
    // Binds layer l's positions (and normals) at SSAO_TEX_POSITION (SSAO_TEX_NORMAL), its frame
    // block at SSAO_UBO_FRAME and its cell at the AO shaders' uAoLayerCell uniform of `program`
    // (the layers of the last split(): the inspector's replay).
    void bindLayer(int l, GLuint program);
    // Remembers the frame block bound now, for restoreFrame() (split() does it itself).
    void saveFrame();
    // Draws `program` (the technique's AO_DEINTERLEAVED variant) over every layer into the atlas:
    // layer (i, j) in the tile (i, j) of a 4x4 grid of layer-sized tiles.
    void drawLayers(GLuint program, const std::function<void()>& drawFullscreen);
    // Writes the atlas back into the bound target, pixel (x, y) from its layer's texel
    // (shaders/passes/reinterleave.frag); `mergeProgram` is that shader's program.
    void merge(GLuint mergeProgram, const std::function<void()>& drawFullscreen);
    // Binds the frame block saved by split() or saveFrame() (the layers' draws replace it).
    void restoreFrame() const;

  private:
    // The layers of one frame size: the app's moving and still frames take turns at two sizes, so
    // the set of the other size is kept (`spare_`) rather than made anew (graph/frame_graph.h).
    struct Layers {
        std::array<gl::Texture2D, kLayers> positions, normals;
        std::array<gl::Framebuffer, 2> positionFbo, normalFbo;
        gl::Texture2D atlas; // R32F, 4 x 4 layers
        gl::Framebuffer atlasFbo;
        int w = 0, h = 0;
        GLenum positionFormat = 0, normalFormat = 0;
        bool hasNormals = false;
        bool fits(int w, int h, GLenum positionFormat, GLenum normalFormat, bool normals) const;
    };
    void ensure(int w, int h, GLenum positionFormat, GLenum normalFormat, bool normals);
    Layers cur_, spare_;
    gl::UniformBuffer frameUbo_;
    gpu::FrameConstants frame_{};
    GLint savedFrameUbo_ = 0;
};

} // namespace ssao
