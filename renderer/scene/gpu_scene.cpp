#include "scene/gpu_scene.h"

#include <cstddef>

namespace ssao {

GpuScene::GpuScene(const Scene& scene) : draws_(scene.draws), radius_(scene.bounds.radius()) {
    GLuint ids[2];
    glCreateBuffers(2, ids);
    vbo_ = gl::BufferHandle(ids[0]);
    ibo_ = gl::BufferHandle(ids[1]);
    glNamedBufferStorage(vbo_.id(), GLsizeiptr(scene.vertices.size() * sizeof(Vertex)), scene.vertices.data(),
                         0);
    glNamedBufferStorage(ibo_.id(), GLsizeiptr(scene.indices.size() * sizeof(uint32_t)), scene.indices.data(),
                         0);
    gl::label(GL_BUFFER, vbo_.id(), "scene-vertices");
    gl::label(GL_BUFFER, ibo_.id(), "scene-indices");

    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    vao_ = gl::VertexArrayHandle(vao);
    glVertexArrayVertexBuffer(vao, 0, vbo_.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, ibo_.id());
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, position));
    glVertexArrayAttribBinding(vao, 0, 0);
    glEnableVertexArrayAttrib(vao, 1);
    glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, normal));
    glVertexArrayAttribBinding(vao, 1, 0);
    gl::label(GL_VERTEX_ARRAY, vao, "scene");
}

void GpuScene::draw(GLint colorLocation) const {
    glBindVertexArray(vao_.id());
    for (const auto& d : draws_) {
        glUniform4fv(colorLocation, 1, &d.baseColor.x);
        glDrawElements(GL_TRIANGLES, GLsizei(d.indexCount), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(size_t(d.firstIndex) * sizeof(uint32_t)));
    }
}

} // namespace ssao
