// A pass is a small class with declared inputs: the settings groups it reads, whether it reads
// the scene/camera, and the passes whose outputs it samples. The renderer re-runs a pass only
// when one of those changed (filament's frame-graph idea, reduced to what ssaolab needs).
#pragma once
#include "gl/resources.h"
#include "gl/shader_library.h"
#include "settings/settings.h"

#include <string>
#include <vector>

namespace ssao {

class GpuScene;
struct Camera;

struct FrameInputs {
    const Settings& settings;
    const GpuScene& scene;
    const Camera& camera;
    int width, height;
    gl::ShaderLibrary& shaders;
    const gl::FullscreenTriangle& triangle;
};

class Pass {
  public:
    virtual ~Pass() = default;
    virtual const char* name() const = 0;
    virtual std::vector<std::string> settingGroups() const = 0; // parameter-table groups read
    virtual bool readsScene() const { return false; }
    virtual bool readsCamera() const { return false; }
    virtual std::vector<const Pass*> inputs() const { return {}; }
    // (Re)creates outputs as needed and renders. Called only when an input changed.
    virtual void run(const FrameInputs& in) = 0;

    // Bumped each time the pass runs; downstream passes key on it.
    unsigned version() const { return version_; }
    void markRan() { ++version_; }
    gl::GpuTimer& timer() { return timer_; }

  private:
    unsigned version_ = 0;
    gl::GpuTimer timer_;
};

} // namespace ssao
