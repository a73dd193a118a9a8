#include "scene/gpu/gpu_scene.h"

#include "scene/closed_shells.h"
#include "scene/gpu/occlusion_culler.h"

#include "../../../shaders/include/bindings.h"

#include <algorithm>
#include <cstddef>

namespace ssao {

bool outsideFrustum(const Bounds& box, const glm::mat4& viewProj, bool zeroToOneDepth) {
    // Counts, per clip plane, the corners outside it: x < -w, x > w, y < -w, y > w, near, far.
    int out[6] = {0, 0, 0, 0, 0, 0};
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p = box.corner(i);
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

bool beyondNearPlane(const Bounds& box, const glm::mat4& viewProj, bool zeroToOneDepth) {
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p = box.corner(i);
        const glm::vec4 c = viewProj * glm::vec4(p, 1.0f);
        // Strictly inside the near plane's half-space (reversed: z_ndc < 1; standard: z_ndc > -1).
        if (!(zeroToOneDepth ? c.z < c.w : c.z > -c.w)) return false;
    }
    return true;
}

GpuScene::GpuScene(const Scene& scene, bool motionLods) : radius_(scene.bounds.radius()), bounds_(scene.bounds) {
    // Each draw's triangles regrouped as its closed shells face (scene/closed_shells.h), so that a
    // pass can draw the groups with and without face culling; MASK draws are never culled (a
    // cut-out front face shows the back face behind it).
    std::vector<uint32_t> indices(scene.indices.size());
    draws_.reserve(scene.draws.size());
    for (const Draw& d : scene.draws) {
        GpuDraw g;
        g.draw = d;
        const size_t triangles = d.indexCount / 3;
        std::vector<ShellFacing> facing(triangles, ShellFacing::Open);
        if (!d.mask) facing = classifyShells(scene.vertices, scene.indices, d.firstIndex, triangles);
        uint32_t* dst = indices.data() + d.firstIndex;
        for (const ShellFacing group : {ShellFacing::Outward, ShellFacing::Inward, ShellFacing::Open}) {
            for (size_t t = 0; t < triangles; ++t) {
                if (facing[t] != group) continue;
                for (int k = 0; k < 3; ++k) {
                    const uint32_t v = scene.indices[d.firstIndex + 3 * t + size_t(k)];
                    *dst++ = v;
                    const glm::vec3& p = scene.vertices[v].position;
                    g.bounds.add(p);
                    if (group == ShellFacing::Outward) g.outwardBounds.add(p);
                    if (group == ShellFacing::Inward) g.inwardBounds.add(p);
                }
                g.outward += group == ShellFacing::Outward;
                g.inward += group == ShellFacing::Inward;
            }
        }
        // Index counts that are not a multiple of 3 keep their tail (GL ignores it) as before.
        for (uint32_t i = d.firstIndex + uint32_t(3 * triangles); i < d.firstIndex + d.indexCount; ++i)
            indices[i] = scene.indices[i];
        hasMask_ = hasMask_ || d.mask;
        draws_.push_back(g);
    }
    vbo_ = gl::Buffer(scene.vertices.size() * sizeof(Vertex), scene.vertices.data(), 0, "scene-vertices");
    ibo_ = gl::Buffer(indices.size() * sizeof(uint32_t), indices.data(), 0, "scene-indices");
    if (!scene.uvs.empty())
        uvs_ = gl::Buffer(scene.uvs.size() * sizeof(glm::vec2), scene.uvs.data(), 0, "scene-uvs");
    vao_ = gl::VertexArray("scene");
    bindAttributes(vao_.id());
    glVertexArrayElementBuffer(vao_.id(), ibo_.id());
    for (MotionLod& lod : motionLods ? motionLodsFor(scene) : std::vector<MotionLod>{}) {
        LodLevel l;
        l.cell = lod.cell;
        l.triangles = lod.triangles();
        l.ibo = gl::Buffer(lod.indices.size() * sizeof(uint32_t), lod.indices.data(), 0, "scene-indices-lod");
        l.vao = gl::VertexArray("scene-lod");
        bindAttributes(l.vao.id());
        glVertexArrayElementBuffer(l.vao.id(), l.ibo.id());
        l.first = std::move(lod.first), l.count = std::move(lod.count);
        lods_.push_back(std::move(l));
    }
    for (const AlphaTexture& t : scene.alphaTextures) {
        gl::Texture2D tex(t.width, t.height, GL_R8, "mask-alpha");
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage2D(tex.id(), 0, 0, 0, t.width, t.height, GL_RED, GL_UNSIGNED_BYTE, t.alpha.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        alpha_.push_back(std::move(tex));
        alphaWrap_.push_back({int(t.wrapS), int(t.wrapT)});
    }
}

float GpuScene::lodCellPx(int level, const Camera& camera, int height) const {
    float px = 0.0f;
    for (const GpuDraw& g : draws_)
        if (g.bounds.valid()) px = std::max(px, motionLodCellPx(lods_[size_t(level)].cell, g.bounds, camera, height));
    return px;
}

void GpuScene::bindAttributes(GLuint vao) const {
    glVertexArrayVertexBuffer(vao, 0, vbo_.id(), 0, sizeof(Vertex));
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, position));
    glVertexArrayAttribBinding(vao, 0, 0);
    glEnableVertexArrayAttrib(vao, 1);
    glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, normal));
    glVertexArrayAttribBinding(vao, 1, 0);
    // Texture coordinates (MASK draws' cut-outs) from a second buffer, only where a scene has them.
    if (uvs_.id()) {
        glVertexArrayVertexBuffer(vao, 1, uvs_.id(), 0, sizeof(glm::vec2));
        glEnableVertexArrayAttrib(vao, 2);
        glVertexArrayAttribFormat(vao, 2, 2, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(vao, 2, 1);
    }
}

DrawStats GpuScene::draw(const ScenePrograms& programs, const DrawOptions& o) const {
    DrawStats st;
    const LodLevel* lod = o.lod >= 0 && o.lod < lodLevels() ? &lods_[size_t(o.lod)] : nullptr;
    st.lod = lod ? o.lod : -1;
    GLuint boundVao = lod ? lod->vao.id() : vao_.id();
    glBindVertexArray(boundVao);
    OcclusionCuller* occ = o.occlusion && o.viewProj ? o.occlusion : nullptr;
    std::vector<size_t> waiting; // skip.occluded: draws whose box is tested first
    // Opaque draws first, then MASK draws with the program that cuts them out.
    for (int pass = 0; pass < 2; ++pass) {
        const bool mask = pass == 1;
        if (mask && !hasMask_) break;
        glUseProgram(mask ? programs.mask : programs.opaque);
        for (size_t di = 0; di < draws_.size(); ++di) {
            const GpuDraw& g = draws_[di];
            if (g.draw.mask != mask) continue;
            if (o.frustumCull && o.viewProj && outsideFrustum(g.bounds, *o.viewProj, o.zeroToOneDepth)) {
                ++st.culled;
                st.trianglesCulled += g.draw.indexCount / 3;
                continue;
            }
            if (occ && occ->deferred(di)) {
                waiting.push_back(di);
                continue;
            }
            if (occ) occ->beginDraw(di);
            drawOne(di, programs, o, boundVao, st);
            if (occ) occ->endDraw();
        }
    }
    if (occ && !waiting.empty()) {
        std::vector<Bounds> boxes;
        for (size_t di : waiting)
            boxes.push_back(draws_[di].bounds);
        const std::vector<bool> shown = occ->testBoxes(boxes, *o.viewProj, o.zeroToOneDepth);
        st.boxesTested += occ->tested();
        glBindVertexArray(boundVao);
        for (int pass = 0; pass < 2; ++pass) {
            const bool mask = pass == 1;
            bool bound = false;
            for (size_t k = 0; k < waiting.size(); ++k) {
                const size_t di = waiting[k];
                if (draws_[di].draw.mask != mask) continue;
                if (!shown[k]) {
                    ++st.occluded;
                    const LodLevel* level = levelFor(di, o); // what it would have drawn
                    st.trianglesOccluded += level ? level->count[di] / 3 : draws_[di].draw.indexCount / 3;
                    continue;
                }
                if (!bound) glUseProgram(mask ? programs.mask : programs.opaque), bound = true;
                occ->beginDraw(di);
                drawOne(di, programs, o, boundVao, st);
                occ->endDraw();
            }
        }
    }
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    return st;
}

const GpuScene::LodLevel* GpuScene::levelFor(size_t di, const DrawOptions& o) const {
    if (o.lod < 0 || o.lod >= lodLevels()) return nullptr;
    for (int l = 0; o.lodView && l < o.lod; ++l) // coarsest first: the first whose cell fits
        if (motionLodCellPx(lods_[size_t(l)].cell, draws_[di].bounds, *o.lodView, o.lodProjY, o.lodOrthographic,
                            o.lodHeight) <= 1.0f)
            return &lods_[size_t(l)];
    return &lods_[size_t(o.lod)];
}

void GpuScene::drawOne(size_t di, const ScenePrograms& programs, const DrawOptions& o, GLuint& boundVao,
                       DrawStats& st) const {
    const GpuDraw& g = draws_[di];
    const Draw& d = g.draw;
    auto issue = [&](uint32_t firstTriangle, uint32_t count, GLenum cull) {
        if (count == 0) return;
        if (cull) glEnable(GL_CULL_FACE), glCullFace(cull);
        else glDisable(GL_CULL_FACE);
        glDrawElements(GL_TRIANGLES, GLsizei(3 * count), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>((size_t(d.firstIndex) + 3 * size_t(firstTriangle)) * sizeof(uint32_t)));
        if (cull) st.trianglesFaceCulled += count;
    };
    if (programs.colorLocation >= 0) glUniform4fv(programs.colorLocation, 1, &d.baseColor.x);
    if (d.mask) { // alpha_mask.glsl: uAlphaTest (location 1), uAlphaWrap (2), the texture
        const bool tex = d.alphaTexture >= 0;
        glUniform4f(1, d.alphaCutoff, d.baseColor.w, tex ? 1.0f : 0.0f, 0.0f);
        const glm::ivec2 wrap = tex ? alphaWrap_[size_t(d.alphaTexture)] : glm::ivec2(0);
        glUniform2i(2, wrap.x, wrap.y);
        if (tex) alpha_[size_t(d.alphaTexture)].bind(SSAO_TEX_SCENE_ALPHA);
    }
    ++st.draws; // one per draw, however many calls its groups take
    if (const LodLevel* level = levelFor(di, o)) { // the clustered copy: one call, no face culling
        st.lodCoarser += level != &lods_[size_t(o.lod)];
        if (level->vao.id() != boundVao) glBindVertexArray(boundVao = level->vao.id());
        const uint32_t first = level->first[di], count = level->count[di];
        st.triangles += count / 3;
        if (count)
            glDrawElements(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(size_t(first) * sizeof(uint32_t)));
        return;
    }
    const uint32_t triangles = d.indexCount / 3;
    st.triangles += triangles;
    const bool faces = o.hiddenFaces && o.viewProj;
    const bool back = faces && g.outward && beyondNearPlane(g.outwardBounds, *o.viewProj, o.zeroToOneDepth);
    const bool front = faces && g.inward && beyondNearPlane(g.inwardBounds, *o.viewProj, o.zeroToOneDepth);
    // Outward | Inward | Open, each group culled where it may be; neighbours drawn alike
    // go in one call (no shell to cull: one call, as without them).
    const uint32_t first[3] = {0, g.outward, g.outward + g.inward};
    const uint32_t count[3] = {g.outward, g.inward, triangles - g.outward - g.inward};
    const GLenum cull[3] = {GLenum(back ? GL_BACK : 0), GLenum(front ? GL_FRONT : 0), 0};
    for (int k = 0; k < 3;) {
        int end = k + 1;
        uint32_t n = count[k];
        while (end < 3 && cull[end] == cull[k]) n += count[end++];
        issue(first[k], n, cull[k]);
        k = end;
    }
}

} // namespace ssao
