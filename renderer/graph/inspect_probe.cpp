#include "graph/inspect_probe.h"

#include "../../shaders/include/bindings.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstring>
#include <vector>

namespace ssao {

namespace {
constexpr size_t kBytes = sizeof(gpu::InspectHeader) + SSAO_INSPECT_MAX_TAPS * sizeof(gpu::InspectTap);
}

namespace {
struct ProbeState { // restores what run() changes, whatever happens in between
    ~ProbeState() {
        glDisable(GL_SCISSOR_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
};
} // namespace

void InspectProbe::run(glm::ivec2 pixel, glm::ivec2 size, const std::function<void()>& draw,
                       PixelInspection& out) {
    if (!ssbo_) ssbo_ = gl::Buffer(kBytes, nullptr, GL_DYNAMIC_STORAGE_BIT, "inspector.record");
    if (!fbo_ || fboSize_ != size) {
        // No attachments: the fragment shader runs for its side effects only.
        fbo_ = gl::Framebuffer::withoutAttachments(size.x, size.y, "inspector.probe");
        fboSize_ = size;
    }
    const glm::ivec2 glPixel(pixel.x, size.y - 1 - pixel.y); // GL window coordinates: origin bottom-left
    gpu::InspectHeader head{};
    head.pixelCount = {glPixel.x, glPixel.y, 0, 0};
    glNamedBufferSubData(ssbo_.id(), 0, sizeof head, &head);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSAO_SSBO_INSPECT, ssbo_.id());
    {
        ProbeState restore;
        fbo_.bind(); // and its viewport
        glEnable(GL_SCISSOR_TEST);
        glScissor(glPixel.x, glPixel.y, 1, 1);
        draw();
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<unsigned char> bytes(kBytes);
    glGetNamedBufferSubData(ssbo_.id(), 0, GLsizeiptr(kBytes), bytes.data());
    std::memcpy(&head, bytes.data(), sizeof head);
    out = PixelInspection{};
    out.pixel = pixel;
    out.geometry = head.pixelCount.w != 0;
    out.ao = head.result.x;
    out.occlusion = head.result.y;
    out.normaliser = head.result.z;
    out.radius = head.result.w;
    out.position = glm::vec3(head.position);
    out.normal = glm::vec3(head.normal);
    const int recorded = head.pixelCount.z;
    out.truncated = recorded > SSAO_INSPECT_MAX_TAPS;
    const gpu::InspectTap* taps = reinterpret_cast<const gpu::InspectTap*>(bytes.data() + sizeof head);
    for (int i = 0; i < std::min(recorded, SSAO_INSPECT_MAX_TAPS); ++i) {
        InspectTap t;
        t.viewPos = glm::vec3(taps[i].posContribution);
        t.contribution = taps[i].posContribution.w;
        t.uv = glm::vec2(taps[i].uvStateSet);
        const int state = int(taps[i].uvStateSet.z);
        t.state = TapState(state & (SSAO_TAP_BACK_LAYER - 1));
        t.backLayer = (state & SSAO_TAP_BACK_LAYER) != 0;
        t.secondLayer = (state & SSAO_TAP_SECOND_LAYER) != 0;
        t.set = int(taps[i].uvStateSet.w);
        out.taps.push_back(t);
    }
}

} // namespace ssao
