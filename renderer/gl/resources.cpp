#include "gl/resources.h"

#include "util/error.h"

#include <algorithm>

namespace ssao::gl {

Texture2D::Texture2D(int width, int height, GLenum internalFormat, const std::string& name, int levels)
    : w_(width), h_(height), levels_(std::max(levels, 1)), fmt_(internalFormat) {
    if (width <= 0 || height <= 0) throw Error("texture '" + name + "' has an empty size");
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    h_id_ = TextureHandle(id);
    glTextureStorage2D(id, levels_, internalFormat, width, height);
    // Point sampling everywhere: G-buffer data must not be interpolated across edges
    // (XeGTAO: "linear filtering of depth causes unwanted interpolation"), nor across levels.
    setFilter(GL_NEAREST);
    if (levels_ > 1) glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    setWrap(GL_CLAMP_TO_EDGE);
    label(GL_TEXTURE, id, name);
}

void Texture2D::setFilter(GLenum minMag) {
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, minMag);
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, minMag);
}

void Texture2D::setWrap(GLenum wrap) {
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, wrap);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, wrap);
}

std::vector<float> Texture2D::readFloats(int components) const {
    static const GLenum formats[] = {0, GL_RED, GL_RG, GL_RGB, GL_RGBA};
    std::vector<float> out(static_cast<size_t>(w_) * h_ * components);
    GLenum fmt = (fmt_ == GL_DEPTH_COMPONENT32F || fmt_ == GL_DEPTH_COMPONENT24) ? GL_DEPTH_COMPONENT
                                                                                 : formats[components];
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(id(), 0, fmt, GL_FLOAT, static_cast<GLsizei>(out.size() * sizeof(float)), out.data());
    return out;
}

glm::vec4 Texture2D::readTexel(int x, int yFromTop) const {
    glm::vec4 v(0.0f);
    if (x < 0 || yFromTop < 0 || x >= w_ || yFromTop >= h_) return v;
    const bool depth = fmt_ == GL_DEPTH_COMPONENT32F || fmt_ == GL_DEPTH_COMPONENT24;
    glGetTextureSubImage(id(), 0, x, h_ - 1 - yFromTop, 0, 1, 1, 1, depth ? GL_DEPTH_COMPONENT : GL_RGBA,
                         GL_FLOAT, depth ? sizeof(float) : sizeof v, &v);
    return v;
}

Framebuffer::Framebuffer(const std::vector<const Texture2D*>& colors, const Texture2D* depth,
                         const std::string& name) {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    h_ = FramebufferHandle(id);
    std::vector<GLenum> bufs;
    for (size_t i = 0; i < colors.size(); ++i) {
        glNamedFramebufferTexture(id, GLenum(GL_COLOR_ATTACHMENT0 + i), colors[i]->id(), 0);
        bufs.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
        width_ = colors[i]->width();
        height_ = colors[i]->height();
    }
    if (depth) {
        glNamedFramebufferTexture(id, GL_DEPTH_ATTACHMENT, depth->id(), 0);
        width_ = depth->width();
        height_ = depth->height();
    }
    glNamedFramebufferDrawBuffers(id, GLsizei(bufs.size()), bufs.data());
    GLenum status = glCheckNamedFramebufferStatus(id, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error("framebuffer '" + name + "' is incomplete (status 0x" + hex(status) + ")");
    label(GL_FRAMEBUFFER, id, name);
}

Framebuffer::Framebuffer(const Texture2D& color, int level, const std::string& name)
    : width_(std::max(color.width() >> level, 1)), height_(std::max(color.height() >> level, 1)) {
    if (level < 0 || level >= color.levels()) throw Error("framebuffer '" + name + "': no such MIP level");
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    h_ = FramebufferHandle(id);
    glNamedFramebufferTexture(id, GL_COLOR_ATTACHMENT0, color.id(), level);
    const GLenum status = glCheckNamedFramebufferStatus(id, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error("framebuffer '" + name + "' is incomplete (status 0x" + hex(status) + ")");
    label(GL_FRAMEBUFFER, id, name);
}

Framebuffer Framebuffer::withoutAttachments(int width, int height, const std::string& name) {
    Framebuffer f;
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    f.h_ = FramebufferHandle(id);
    glNamedFramebufferParameteri(id, GL_FRAMEBUFFER_DEFAULT_WIDTH, width);
    glNamedFramebufferParameteri(id, GL_FRAMEBUFFER_DEFAULT_HEIGHT, height);
    f.width_ = width, f.height_ = height;
    label(GL_FRAMEBUFFER, id, name);
    return f;
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, id());
    glViewport(0, 0, width_, height_);
}

void RenderTarget::ensure(int width, int height, GLenum internalFormat, const std::string& name) {
    if (fbo_ && tex_.width() == width && tex_.height() == height && tex_.format() == internalFormat) return;
    fbo_ = Framebuffer();
    tex_ = Texture2D(width, height, internalFormat, name);
    fbo_ = Framebuffer({&tex_}, nullptr, name);
}

Buffer::Buffer(std::size_t bytes, const void* data, GLbitfield flags, const std::string& name) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    h_ = BufferHandle(id);
    glNamedBufferStorage(id, GLsizeiptr(bytes), data, flags);
    label(GL_BUFFER, id, name);
}

VertexArray::VertexArray(const std::string& name) {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    h_ = VertexArrayHandle(id);
    label(GL_VERTEX_ARRAY, id, name);
}

UniformBuffer::UniformBuffer(std::size_t bytes, const std::string& name) : size_(bytes) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    h_ = BufferHandle(id);
    glNamedBufferStorage(id, GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
    label(GL_BUFFER, id, name);
}

void UniformBuffer::upload(const void* data, std::size_t bytes) {
    if (bytes > size_) throw Error("uniform buffer upload larger than the buffer");
    glNamedBufferSubData(h_.id(), 0, GLsizeiptr(bytes), data);
}

Sampler::Sampler(GLenum minMag, GLenum wrap, const std::string& name) {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    h_ = SamplerHandle(id);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(minMag));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, GLint(minMag));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GLint(wrap));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GLint(wrap));
    label(GL_SAMPLER, id, name);
}

GpuTimer::GpuTimer() {
    GLuint id = 0;
    glCreateQueries(GL_TIME_ELAPSED, 1, &id);
    q_ = QueryHandle(id);
}

void GpuTimer::begin() {
    glBeginQuery(GL_TIME_ELAPSED, q_.id());
}

void GpuTimer::end() {
    glEndQuery(GL_TIME_ELAPSED);
    pending_ = true;
}

double GpuTimer::resultMs() {
    if (pending_) {
        GLuint64 ns = 0;
        glGetQueryObjectui64v(q_.id(), GL_QUERY_RESULT, &ns);
        lastMs_ = double(ns) * 1e-6;
        pending_ = false;
    }
    return lastMs_;
}

FullscreenTriangle::FullscreenTriangle() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    vao_ = VertexArrayHandle(id);
    label(GL_VERTEX_ARRAY, id, "fullscreen-triangle");
}

void FullscreenTriangle::draw() const {
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

} // namespace ssao::gl
