#include "renderer.h"

#include "settings/params.h"
#include "ssao/constants.h"
#include "util/error.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace ssao {

std::vector<std::string> FrameReport::ran() const {
    std::vector<std::string> out;
    for (const auto& p : passes)
        if (p.ran) out.push_back(p.name);
    return out;
}

Renderer::Renderer(const std::string& shaderDir)
    : shaders_(shaderDir), frameUbo_(sizeof(gpu::FrameConstants), "frame.constants"),
      settings_(defaultSettings()) {
    // llvmpipe answers the first GL_TIME_ELAPSED query around a context's first drawing with
    // the time since boot (seen: 2.4e6 ms). One tiny clear inside a query up front keeps every
    // reported pass time real.
    gl::RenderTarget scratch;
    scratch.ensure(1, 1, GL_R8, "timer-warm-up");
    gl::GpuTimer warmUp;
    warmUp.begin();
    scratch.bind();
    glClear(GL_COLOR_BUFFER_BIT);
    warmUp.end();
    warmUp.resultMs();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::setScene(const Scene& scene) {
    scene_ = std::make_unique<GpuScene>(scene);
    ++sceneVersion_;
}

void Renderer::setCamera(const Camera& camera) {
    validateCamera(camera);
    camera_ = camera;
}

void Renderer::setSettings(const Settings& settings) {
    settings_ = settings;
}

void Renderer::setSize(int width, int height) {
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
        throw Error("size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is outside 1x1..16384x16384");
    width_ = width;
    height_ = height;
}

std::string Renderer::keyFor(const Pass& p, const nlohmann::json& settingsJson) const {
    char buf[512];
    std::string key = std::to_string(width_) + "x" + std::to_string(height_);
    for (const auto& g : p.settingGroups())
        key += "|" + settingsJson.at(g).dump();
    if (p.readsScene()) key += "|scene" + std::to_string(sceneVersion_);
    if (p.readsCamera()) {
        const Camera& c = camera_;
        std::snprintf(buf, sizeof buf, "|cam%a,%a,%a,%a,%a,%a,%a,%a,%a,%a,%a,%a", c.eye.x, c.eye.y, c.eye.z,
                      c.target.x, c.target.y, c.target.z, c.up.x, c.up.y, c.up.z, c.fovYDeg, c.nearZ, c.farZ);
        key += buf;
    }
    for (const Pass* in : p.inputs())
        key += "|" + std::string(in->name()) + std::to_string(in->version());
    return key;
}

const char* bufferName(BufferId id) {
    static const char* names[] = {"position", "normal", "depth", "albedo", "ao_raw", "ao", "composite"};
    return names[int(id)];
}

const gl::Texture2D& Renderer::buffer(BufferId id) const {
    switch (id) {
    case BufferId::Position:
        return gbuffer_.position();
    case BufferId::Normal:
        return gbuffer_.normal();
    case BufferId::Depth:
        return gbuffer_.linearDepth();
    case BufferId::Albedo:
        return gbuffer_.albedo();
    case BufferId::AoRaw:
        return ssao_.aoRaw();
    case BufferId::Ao:
        return blur_.ao();
    default:
        return composite_.color();
    }
}

FrameReport Renderer::render() {
    if (!scene_) throw Error("renderer: no scene set");
    if (width_ <= 0) throw Error("renderer: no size set");
    const gpu::FrameConstants fc = packFrameConstants(camera_, width_, height_, scene_->radius());
    frameUbo_.upload(&fc, sizeof fc);
    frameUbo_.bind(SSAO_UBO_FRAME);

    FrameInputs in{settings_, *scene_, camera_, width_, height_, shaders_, triangle_};
    const nlohmann::json settingsJson = toJson(settings_); // once per frame, shared by every key
    FrameReport report;
    for (Pass* p : chain_) {
        // Upstream passes run earlier in the chain, so their versions are final by now.
        std::string key = keyFor(*p, settingsJson);
        PassReport r{p->name()};
        auto it = keys_.find(p);
        if (it == keys_.end() || it->second != key) {
            glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, p->name());
            p->timer().begin();
            p->run(in);
            p->timer().end();
            glPopDebugGroup();
            p->markRan();
            keys_[p] = std::move(key);
            r.ran = true;
        }
        report.passes.push_back(r);
    }
    for (size_t i = 0; i < chain_.size(); ++i)
        if (report.passes[i].ran) report.passes[i].gpuMs = chain_[i]->timer().resultMs();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return report;
}

} // namespace ssao
