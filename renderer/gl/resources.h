// Small typed GL objects built on Handle: textures, framebuffers, buffers, timers.
#pragma once
#include "gl/handle.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace ssao::gl {

class Texture2D {
  public:
    Texture2D() = default;
    // `levels` > 1: a MIP chain (level i is max(1, size >> i)), sampled nearest within a level.
    Texture2D(int width, int height, GLenum internalFormat, const std::string& name, int levels = 1);
    int width() const { return w_; }
    int levels() const { return levels_; }
    int height() const { return h_; }
    GLenum format() const { return fmt_; }
    GLuint id() const { return h_id_.id(); }
    explicit operator bool() const { return bool(h_id_); }
    void setFilter(GLenum minMag);
    void setWrap(GLenum wrap);
    void bind(GLuint unit) const { glBindTextureUnit(unit, id()); }
    // Reads the texture back as `components` floats per texel, rows bottom-to-top (GL order).
    std::vector<float> readFloats(int components) const;
    // One texel (x from the left, y from the top of the image) as RGBA floats.
    glm::vec4 readTexel(int x, int yFromTop) const;

  private:
    TextureHandle h_id_;
    int w_ = 0, h_ = 0, levels_ = 1;
    GLenum fmt_ = 0;
};

class Framebuffer {
  public:
    Framebuffer() = default;
    // colour attachments in order (location 0..n-1); depth may be null.
    Framebuffer(const std::vector<const Texture2D*>& colors, const Texture2D* depth, const std::string& name);
    // One colour attachment: MIP `level` of `color` (the viewport is that level's size).
    Framebuffer(const Texture2D& color, int level, const std::string& name);
    // No attachments (GL 4.3): a w x h target whose fragment shader runs for its side effects only.
    static Framebuffer withoutAttachments(int width, int height, const std::string& name);
    GLuint id() const { return h_.id(); }
    void bind() const;
    explicit operator bool() const { return bool(h_); }

  private:
    FramebufferHandle h_;
    int width_ = 0, height_ = 0; // of the attachments: the viewport bind() sets
};

// One colour texture with its framebuffer: the output of a full-screen pass.
class RenderTarget {
  public:
    // (Re)creates the texture and framebuffer when size or format differ from the current ones.
    void ensure(int width, int height, GLenum internalFormat, const std::string& name);
    const Texture2D& texture() const { return tex_; }
    void bind() const { fbo_.bind(); }

  private:
    Texture2D tex_;
    Framebuffer fbo_;
};

// A buffer object with immutable storage (vertex, index or shader-storage data); `data` may be null.
class Buffer {
  public:
    Buffer() = default;
    Buffer(std::size_t bytes, const void* data, GLbitfield flags, const std::string& name);
    GLuint id() const { return h_.id(); }
    explicit operator bool() const { return bool(h_); }

  private:
    BufferHandle h_;
};

// A vertex array object (attribute formats and the element buffer).
class VertexArray {
  public:
    VertexArray() = default;
    explicit VertexArray(const std::string& name);
    GLuint id() const { return h_.id(); }
    explicit operator bool() const { return bool(h_); }

  private:
    VertexArrayHandle h_;
};

class UniformBuffer {
  public:
    UniformBuffer() = default;
    UniformBuffer(std::size_t bytes, const std::string& name);
    void upload(const void* data, std::size_t bytes);
    void bind(GLuint binding) const { glBindBufferBase(GL_UNIFORM_BUFFER, binding, h_.id()); }
    explicit operator bool() const { return bool(h_); }

  private:
    BufferHandle h_;
    std::size_t size_ = 0;
};

// A sampler object (filtering and wrap for one texture unit, whatever the texture's own state).
class Sampler {
  public:
    Sampler() = default;
    Sampler(GLenum minMag, GLenum wrap, const std::string& name);
    void bind(GLuint unit) const { glBindSampler(unit, h_.id()); }
    static void unbind(GLuint unit) { glBindSampler(unit, 0); }
    explicit operator bool() const { return bool(h_); }

  private:
    SamplerHandle h_;
};

// GL_TIME_ELAPSED query around one pass; result read when the frame is done.
class GpuTimer {
  public:
    GpuTimer();
    void begin();
    void end();
    // Blocks until available; milliseconds of the last begin/end pair, or -1 if never run.
    double resultMs();

  private:
    QueryHandle q_;
    bool pending_ = false;
    double lastMs_ = -1.0;
};

// A VAO with no attributes: full-screen passes generate their triangle from gl_VertexID.
class FullscreenTriangle {
  public:
    FullscreenTriangle();
    void draw() const;

  private:
    VertexArrayHandle vao_;
};

} // namespace ssao::gl
