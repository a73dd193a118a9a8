// The SSAO pipeline: gbuffer → ssao → blur → composite. Knows what each pass depends on and
// re-runs only passes whose inputs (settings groups, scene, camera, size, upstream outputs)
// changed since they last ran.
#pragma once
#include "passes/composite_pass.h"
#include "scene/camera.h"
#include "scene/gpu_scene.h"

#include <nlohmann/json_fwd.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ssao {

// Every intermediate buffer a user can look at, in display order.
enum class BufferId { Position, Normal, Depth, Albedo, AoRaw, Ao, Composite, Count };
constexpr int kBufferCount = int(BufferId::Count);
const char* bufferName(BufferId id); // "position", "normal", ... (also the EXR/PNG file stems)

struct PassReport {
    std::string name;
    bool ran = false;
    double gpuMs = -1.0; // GL_TIME_ELAPSED of this frame's run; -1 when skipped
};

struct FrameReport {
    std::vector<PassReport> passes;
    std::vector<std::string> ran() const;
};

class Renderer {
  public:
    explicit Renderer(const std::string& shaderDir);

    void setScene(const Scene& scene);
    void setCamera(const Camera& camera);
    void setSettings(const Settings& settings);
    void setSize(int width, int height);
    // Forces every pass to run on the next frame (e.g. for timing all passes).
    void invalidate() { keys_.clear(); }

    FrameReport render();

    const Settings& settings() const { return settings_; }
    const Camera& camera() const { return camera_; }
    int width() const { return width_; }
    int height() const { return height_; }
    const GBufferPass& gbuffer() const { return gbuffer_; }
    const SsaoPass& ssao() const { return ssao_; }
    const BlurPass& blur() const { return blur_; }
    const CompositePass& composite() const { return composite_; }
    // The texture behind a buffer (depth = linear view distance, R32F).
    const gl::Texture2D& buffer(BufferId id) const;
    gl::ShaderLibrary& shaders() { return shaders_; }
    void drawFullscreen() const { triangle_.draw(); }
    // Version of the scene uploaded last (bumped by setScene).
    unsigned sceneVersion() const { return sceneVersion_; }
    float sceneRadius() const { return scene_ ? scene_->radius() : 1.0f; }

  private:
    std::string keyFor(const Pass& p, const nlohmann::json& settingsJson) const;

    gl::ShaderLibrary shaders_;
    gl::FullscreenTriangle triangle_;
    gl::UniformBuffer frameUbo_;
    std::unique_ptr<GpuScene> scene_;
    unsigned sceneVersion_ = 0;
    Camera camera_;
    Settings settings_;
    int width_ = 0, height_ = 0;

    GBufferPass gbuffer_;
    SsaoPass ssao_{gbuffer_};
    BlurPass blur_{ssao_};
    CompositePass composite_{gbuffer_, blur_};
    std::vector<Pass*> chain_{&gbuffer_, &ssao_, &blur_, &composite_};
    std::map<const Pass*, std::string> keys_;
};

} // namespace ssao
