#include "scene/gpu_scene.h"

#include "../../shaders/include/bindings.h"

#include <cstddef>

namespace ssao {

bool outsideFrustum(const Bounds& box, const glm::mat4& viewProj, bool zeroToOneDepth) {
    // Counts, per clip plane, the corners outside it: x < -w, x > w, y < -w, y > w, near, far.
    int out[6] = {0, 0, 0, 0, 0, 0};
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                          (i & 4) ? box.max.z : box.min.z);
        const glm::vec4 c = viewProj * glm::vec4(p, 1.0f);
        out[0] += c.x < -c.w, out[1] += c.x > c.w;
        out[2] += c.y < -c.w, out[3] += c.y > c.w;
        out[4] += zeroToOneDepth ? c.z > c.w : c.z < -c.w; // nearer than near (reversed: z_ndc > 1)
        out[5] += zeroToOneDepth ? c.z < 0.0f : c.z > c.w; // beyond far
    }
    for (int k : out)
        if (k == 8) return true;
    return false;
}

GpuScene::GpuScene(const Scene& scene) : draws_(scene.draws), radius_(scene.bounds.radius()) {
    drawBounds_.resize(draws_.size());
    for (size_t d = 0; d < draws_.size(); ++d)
        for (uint32_t i = draws_[d].firstIndex; i < draws_[d].firstIndex + draws_[d].indexCount; ++i)
            drawBounds_[d].add(scene.vertices[scene.indices[i]].position);
    vbo_ = gl::Buffer(scene.vertices.size() * sizeof(Vertex), scene.vertices.data(), 0, "scene-vertices");
    ibo_ = gl::Buffer(scene.indices.size() * sizeof(uint32_t), scene.indices.data(), 0, "scene-indices");
    vao_ = gl::VertexArray("scene");
    const GLuint vao = vao_.id();
    glVertexArrayVertexBuffer(vao, 0, vbo_.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, ibo_.id());
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, position));
    glVertexArrayAttribBinding(vao, 0, 0);
    glEnableVertexArrayAttrib(vao, 1);
    glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, normal));
    glVertexArrayAttribBinding(vao, 1, 0);
    // Texture coordinates (MASK draws' cut-outs) from a second buffer, only where a scene has them.
    if (!scene.uvs.empty()) {
        uvs_ = gl::Buffer(scene.uvs.size() * sizeof(glm::vec2), scene.uvs.data(), 0, "scene-uvs");
        glVertexArrayVertexBuffer(vao, 1, uvs_.id(), 0, sizeof(glm::vec2));
        glEnableVertexArrayAttrib(vao, 2);
        glVertexArrayAttribFormat(vao, 2, 2, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(vao, 2, 1);
    }
    for (const AlphaTexture& t : scene.alphaTextures) {
        gl::Texture2D tex(t.width, t.height, GL_R8, "mask-alpha");
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage2D(tex.id(), 0, 0, 0, t.width, t.height, GL_RED, GL_UNSIGNED_BYTE, t.alpha.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        alpha_.push_back(std::move(tex));
        alphaWrap_.push_back({int(t.wrapS), int(t.wrapT)});
    }
    for (const Draw& d : draws_)
        hasMask_ = hasMask_ || d.mask;
}

DrawStats GpuScene::draw(const ScenePrograms& programs, const glm::mat4* cullViewProj, bool zeroToOneDepth) const {
    DrawStats st;
    glBindVertexArray(vao_.id());
    // Opaque draws first, then MASK draws with the program that cuts them out.
    for (int pass = 0; pass < 2; ++pass) {
        const bool mask = pass == 1;
        if (mask && !hasMask_) break;
        glUseProgram(mask ? programs.mask : programs.opaque);
        for (size_t i = 0; i < draws_.size(); ++i) {
            const Draw& d = draws_[i];
            if (d.mask != mask) continue;
            if (cullViewProj && outsideFrustum(drawBounds_[i], *cullViewProj, zeroToOneDepth)) {
                ++st.culled;
                st.trianglesCulled += d.indexCount / 3;
                continue;
            }
            if (programs.colorLocation >= 0) glUniform4fv(programs.colorLocation, 1, &d.baseColor.x);
            if (mask) { // alpha_mask.glsl: uAlphaTest (location 1), uAlphaWrap (2), the texture
                const bool tex = d.alphaTexture >= 0;
                glUniform4f(1, d.alphaCutoff, d.baseColor.w, tex ? 1.0f : 0.0f, 0.0f);
                const glm::ivec2 wrap = tex ? alphaWrap_[size_t(d.alphaTexture)] : glm::ivec2(0);
                glUniform2i(2, wrap.x, wrap.y);
                if (tex) alpha_[size_t(d.alphaTexture)].bind(SSAO_TEX_SCENE_ALPHA);
            }
            glDrawElements(GL_TRIANGLES, GLsizei(d.indexCount), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(size_t(d.firstIndex) * sizeof(uint32_t)));
            ++st.draws;
            st.triangles += d.indexCount / 3;
        }
    }
    return st;
}

} // namespace ssao
