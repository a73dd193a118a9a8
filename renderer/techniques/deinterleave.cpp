#include "techniques/deinterleave.h"

#include <string>
#include <vector>

namespace ssao {

namespace {
constexpr int kTargets = 8;                 // colour targets a split draw writes (the GL minimum)
constexpr GLint kFirstLayerLocation = 0;    // deinterleave.frag: uFirstLayer
constexpr GLint kAtlasLayerLocation = 0;    // reinterleave.frag: uLayerSize
constexpr GLint kLayerCellLocation = SSAO_LOC_AO_LAYER_CELL; // noise.glsl (AO_DEINTERLEAVED): uAoLayerCell
} // namespace

gpu::FrameConstants Deinterleaver::layerFrame(const gpu::FrameConstants& frame, glm::ivec2 layer) {
    gpu::FrameConstants f = frame;
    f.viewport = glm::vec4(float(layer.x), float(layer.y), 1.0f / float(layer.x), 1.0f / float(layer.y));
    return f;
}

glm::vec2 Deinterleaver::frameUv(glm::vec2 layerUv, int l, int w, int h) {
    const glm::ivec2 size = layerSize(w, h), c = cell(l);
    // Texel x of the layer (centre x + 0.5) is pixel 4x + i of the frame (centre 4x + i + 0.5).
    const glm::vec2 texel = layerUv * glm::vec2(size) - 0.5f;
    return (texel * float(kSide) + glm::vec2(c) + 0.5f) / glm::vec2(float(w), float(h));
}

void Deinterleaver::ensure(int w, int h, GLenum positionFormat, GLenum normalFormat, bool normals) {
    if (w == w_ && h == h_ && positionFormat == positionFormat_ && (!normals || normalFormat == normalFormat_) &&
        (haveNormals_ || !normals))
        return;
    const glm::ivec2 size = layerSize(w, h);
    for (int k = 0; k < 2; ++k) {
        std::vector<const gl::Texture2D*> pos, nrm;
        for (int t = 0; t < kTargets; ++t) {
            const int l = k * kTargets + t;
            positions_[size_t(l)] = gl::Texture2D(size.x, size.y, positionFormat, "ao.deinterleaved.position." + std::to_string(l));
            pos.push_back(&positions_[size_t(l)]);
            if (normals) {
                normals_[size_t(l)] = gl::Texture2D(size.x, size.y, normalFormat, "ao.deinterleaved.normal." + std::to_string(l));
                nrm.push_back(&normals_[size_t(l)]);
            }
        }
        positionFbo_[size_t(k)] = gl::Framebuffer(pos, nullptr, "ao.deinterleave.position");
        normalFbo_[size_t(k)] = normals ? gl::Framebuffer(nrm, nullptr, "ao.deinterleave.normal") : gl::Framebuffer();
    }
    atlas_ = gl::Texture2D(size.x * kSide, size.y * kSide, GL_R32F, "ao.deinterleaved.atlas");
    atlasFbo_ = gl::Framebuffer({&atlas_}, nullptr, "ao.deinterleaved.atlas");
    if (!frameUbo_) frameUbo_ = gl::UniformBuffer(sizeof(gpu::FrameConstants), "ao.deinterleaved.frame");
    w_ = w, h_ = h, positionFormat_ = positionFormat, normalFormat_ = normalFormat, haveNormals_ = normals;
}

void Deinterleaver::split(GLuint splitProgram, const gl::Texture2D& positions, const gl::Texture2D* normals,
                          const gpu::FrameConstants& frame, const std::function<void()>& drawFullscreen) {
    ensure(positions.width(), positions.height(), positions.format(), normals ? normals->format() : 0, normals != nullptr);
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, SSAO_UBO_FRAME, &savedFrameUbo_);
    frame_ = layerFrame(frame, layerSize(w_, h_));
    frameUbo_.upload(&frame_, sizeof frame_);
    glUseProgram(splitProgram);
    for (int source = 0; source < (normals ? 2 : 1); ++source) {
        (source == 0 ? positions : *normals).bind(SSAO_TEX_VIEW_SOURCE);
        for (int k = 0; k < 2; ++k) {
            (source == 0 ? positionFbo_ : normalFbo_)[size_t(k)].bind();
            glUniform1i(kFirstLayerLocation, k * kTargets);
            drawFullscreen();
        }
    }
}

void Deinterleaver::bindLayer(int l, GLuint program) {
    positions_[size_t(l)].bind(SSAO_TEX_POSITION);
    if (haveNormals_) normals_[size_t(l)].bind(SSAO_TEX_NORMAL);
    frameUbo_.bind(SSAO_UBO_FRAME);
    // Looked up, not assumed: a variant that takes no noise (noise none) has no such uniform, and
    // setting an inactive location is an error on some drivers.
    const glm::ivec2 c = cell(l);
    if (glGetProgramResourceLocation(program, GL_UNIFORM, "uAoLayerCell") == kLayerCellLocation)
        glProgramUniform2f(program, kLayerCellLocation, float(c.x), float(c.y));
}

void Deinterleaver::drawLayers(GLuint program, const std::function<void()>& drawFullscreen) {
    const glm::ivec2 size = layerSize(w_, h_);
    glBindFramebuffer(GL_FRAMEBUFFER, atlasFbo_.id());
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
    atlas_.bind(SSAO_TEX_AO);
    const glm::ivec2 size = layerSize(w_, h_);
    glUniform2i(kAtlasLayerLocation, size.x, size.y);
    drawFullscreen();
}

void Deinterleaver::restoreFrame() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, SSAO_UBO_FRAME, GLuint(savedFrameUbo_));
}

} // namespace ssao
