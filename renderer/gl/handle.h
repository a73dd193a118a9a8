// Move-only RAII ownership of OpenGL object names (Fwog style): every GL object in ssaolab is
// owned by exactly one of these, so nothing leaks and nothing is deleted twice.
#pragma once
#include <epoxy/gl.h>

#include <string>
#include <utility>

namespace ssao::gl {

template <void (*Delete)(GLuint)> class Handle {
  public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    void reset() {
        if (id_ != 0) Delete(id_);
        id_ = 0;
    }
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }

  private:
    GLuint id_ = 0;
};

namespace detail {
inline void deleteTexture(GLuint id) {
    glDeleteTextures(1, &id);
}
inline void deleteBuffer(GLuint id) {
    glDeleteBuffers(1, &id);
}
inline void deleteFramebuffer(GLuint id) {
    glDeleteFramebuffers(1, &id);
}
inline void deleteVertexArray(GLuint id) {
    glDeleteVertexArrays(1, &id);
}
inline void deleteProgram(GLuint id) {
    glDeleteProgram(id);
}
inline void deleteShader(GLuint id) {
    glDeleteShader(id);
}
inline void deleteQuery(GLuint id) {
    glDeleteQueries(1, &id);
}
inline void deleteSampler(GLuint id) {
    glDeleteSamplers(1, &id);
}
} // namespace detail

using TextureHandle = Handle<detail::deleteTexture>;
using BufferHandle = Handle<detail::deleteBuffer>;
using FramebufferHandle = Handle<detail::deleteFramebuffer>;
using VertexArrayHandle = Handle<detail::deleteVertexArray>;
using ProgramHandle = Handle<detail::deleteProgram>;
using ShaderHandle = Handle<detail::deleteShader>;
using QueryHandle = Handle<detail::deleteQuery>;
using SamplerHandle = Handle<detail::deleteSampler>;

// Names the object for debuggers and for KHR_debug messages.
inline void label(GLenum identifier, GLuint id, const std::string& name) {
    glObjectLabel(identifier, id, static_cast<GLsizei>(name.size()), name.c_str());
}

} // namespace ssao::gl
