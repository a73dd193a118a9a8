#include "techniques/deinterleave.h"

#include <string>
#include <vector>

namespace ssao {

namespace {
constexpr int kTargets = 8;                 // colour targets a split draw writes (the GL minimum)
constexpr GLint kFirstLayerLocation = 0;    // deinterleave.frag: uFirstLayer
constexpr GLint kLayerSizeLocation = 0;     // reinterleave.frag: uLayerSize
constexpr GLint kLayerCellLocation = SSAO_LOC_AO_LAYER_CELL; // noise.glsl (AO_DEINTERLEAVED): uAoLayerCell
} // namespace

gpu::FrameConstants Deinterleaver::layerFrame(const gpu::FrameConstants& frame, glm::ivec2 layer) {
    gpu::FrameConstants f = frame;
    f.viewport = glm::vec4(float(layer.x), float(layer.y), 1.0f / float(layer.x), 1.0f / float(layer.y));
    // A layer texel is 4 frame pixels in both directions: pixels per unit = the frame's / 4.
    f.proj[1][1] *= frame.viewport.y / (float(kSide) * float(layer.y));
    return f;
}

glm::vec2 Deinterleaver::frameUv(glm::vec2 layerUv, int l, int w, int h) {
    const glm::ivec2 size = layerSize(w, h), c = cell(l);
    // Texel x of the layer (centre x + 0.5) is pixel 4x + i of the frame (centre 4x + i + 0.5).
    const glm::vec2 texel = layerUv * glm::vec2(size) - 0.5f;
    return (texel * float(kSide) + glm::vec2(c) + 0.5f) / glm::vec2(float(w), float(h));
}

bool Deinterleaver::Layers::fits(int w_, int h_, GLenum pf, GLenum nf, bool n) const {
    return atlas && w == w_ && h == h_ && positionFormat == pf && (!n || (hasNormals && normalFormat == nf));
}

void Deinterleaver::ensure(int w, int h, GLenum positionFormat, GLenum normalFormat, bool normals) {
    if (cur_.fits(w, h, positionFormat, normalFormat, normals)) return;
    std::swap(cur_, spare_);
    if (cur_.fits(w, h, positionFormat, normalFormat, normals)) return;
    Layers& L = cur_;
    const glm::ivec2 size = layerSize(w, h);
    for (int k = 0; k < 2; ++k) {
        std::vector<const gl::Texture2D*> pos, nrm;
        for (int t = 0; t < kTargets; ++t) {
            const size_t l = size_t(k * kTargets + t);
            L.positions[l] = gl::Texture2D(size.x, size.y, positionFormat, "ao.deinterleaved.position." + std::to_string(l));
            pos.push_back(&L.positions[l]);
            if (normals) {
                L.normals[l] = gl::Texture2D(size.x, size.y, normalFormat, "ao.deinterleaved.normal." + std::to_string(l));
                nrm.push_back(&L.normals[l]);
            }
        }
        L.positionFbo[size_t(k)] = gl::Framebuffer(pos, nullptr, "ao.deinterleave.position");
        L.normalFbo[size_t(k)] = normals ? gl::Framebuffer(nrm, nullptr, "ao.deinterleave.normal") : gl::Framebuffer();
    }
    L.atlas = gl::Texture2D(size.x * kSide, size.y * kSide, GL_R32F, "ao.deinterleaved.atlas");
    L.atlasFbo = gl::Framebuffer({&L.atlas}, nullptr, "ao.deinterleaved.atlas");
    L.w = w, L.h = h, L.positionFormat = positionFormat, L.normalFormat = normalFormat, L.hasNormals = normals;
}

void Deinterleaver::split(GLuint splitProgram, const gl::Texture2D& positions, const gl::Texture2D* normals,
                          const gpu::FrameConstants& frame, const std::function<void()>& drawFullscreen) {
    ensure(positions.width(), positions.height(), positions.format(), normals ? normals->format() : 0, normals != nullptr);
    saveFrame();
    if (!frameUbo_) frameUbo_ = gl::UniformBuffer(sizeof(gpu::FrameConstants), "ao.deinterleaved.frame");
    frame_ = layerFrame(frame, layerSize(cur_.w, cur_.h));
    frameUbo_.upload(&frame_, sizeof frame_);
    glUseProgram(splitProgram);
    for (int source = 0; source < (normals ? 2 : 1); ++source) {
        (source == 0 ? positions : *normals).bind(SSAO_TEX_VIEW_SOURCE);
        for (int k = 0; k < 2; ++k) {
            (source == 0 ? cur_.positionFbo : cur_.normalFbo)[size_t(k)].bind();
            glUniform1i(kFirstLayerLocation, k * kTargets);
            drawFullscreen();
        }
    }
}

void Deinterleaver::bindLayer(int l, GLuint program) {
    cur_.positions[size_t(l)].bind(SSAO_TEX_POSITION);
    if (cur_.hasNormals) cur_.normals[size_t(l)].bind(SSAO_TEX_NORMAL);
    frameUbo_.bind(SSAO_UBO_FRAME);
    // Looked up, not assumed: a variant that takes no noise (noise none) has no such uniform, and
    // setting an inactive location is an error on some drivers. Per call (16 a frame), not cached by
    // program name: a hot reload may hand a new program an old one's name.
    const glm::ivec2 c = cell(l);
    if (glGetProgramResourceLocation(program, GL_UNIFORM, "uAoLayerCell") == kLayerCellLocation)
        glProgramUniform2f(program, kLayerCellLocation, float(c.x), float(c.y));
}

void Deinterleaver::drawLayers(GLuint program, const std::function<void()>& drawFullscreen) {
    const glm::ivec2 size = layerSize(cur_.w, cur_.h);
    glBindFramebuffer(GL_FRAMEBUFFER, cur_.atlasFbo.id());
    glUseProgram(program);
    for (int l = 0; l < kLayers; ++l) {
        const glm::ivec2 c = cell(l);
        glViewport(c.x * size.x, c.y * size.y, size.x, size.y);
        bindLayer(l, program);
        drawFullscreen();
    }
}

void Deinterleaver::merge(GLuint mergeProgram, const std::function<void()>& drawFullscreen) {
    glUseProgram(mergeProgram);
    cur_.atlas.bind(SSAO_TEX_AO);
    const glm::ivec2 size = layerSize(cur_.w, cur_.h);
    glUniform2i(kLayerSizeLocation, size.x, size.y);
    drawFullscreen();
}

void Deinterleaver::saveFrame() {
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, SSAO_UBO_FRAME, &savedFrameUbo_);
}

void Deinterleaver::restoreFrame() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, SSAO_UBO_FRAME, GLuint(savedFrameUbo_));
}

} // namespace ssao
