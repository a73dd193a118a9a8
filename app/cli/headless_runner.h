// One headless run, shared by every command that renders without a window (render, bench, tune,
// stress, skips): the EGL context with KHR_debug output installed, renderers on the shader
// folder, and the scenes with the names and default cameras the reports use. A GL error or a
// non-finite output ends the command with one `ssaolab: error:` line (an ssao::Error naming what
// was being done), so no command writes numbers measured on a broken frame.
#pragma once
#include "base/image.h"
#include "gl/context.h"
#include "renderer.h"
#include "scene/scene.h"

#include <memory>
#include <string>
#include <vector>

namespace ssao {

class HeadlessRunner {
  public:
    struct Options {
        std::string shaderDir; // "" = the installed or source tree's shaders/
        bool verboseGl = false; // log every KHR_debug message, not only errors
    };
    explicit HeadlessRunner(const Options& o);
    HeadlessRunner() : HeadlessRunner(Options{}) {}

    const std::string& glRenderer() const { return glRenderer_; }
    const std::string& glPlatform() const { return glPlatform_; }
    // A renderer on this context (several may coexist: stress judges an open plane beside its
    // scene), sized w x h.
    std::unique_ptr<Renderer> makeRenderer(int w, int h) const;
    // Throws naming the GL errors the driver reported since the context was made, and `during`.
    void checkGl(const std::string& during) const;
    // Reads `buffer` back (its data channels) and throws naming it, and `during`, if any value is
    // NaN or infinite.
    Image readFinite(const Renderer& r, const std::string& buffer, const std::string& during) const;

    // Every renderer made from now on stops the process with one error line when a frame's GL
    // work takes longer than `seconds` (Renderer::setFrameTimeLimit; the global --frame-time-limit).
    static constexpr double kDefaultFrameTimeLimit = 60.0;
    static void setFrameTimeLimit(double seconds);

    // Test hook: SSAOLAB_TEST_GL_ERROR=1 in the environment makes the runner raise one GL error
    // right after it starts, so tests can check that every command fails on it.
    static constexpr const char* kForceGlErrorEnv = "SSAOLAB_TEST_GL_ERROR";

  private:
    gl::HeadlessContext context_;
    std::string shaderDir_, glRenderer_, glPlatform_;
};

// A scene for a command: loaded (ssao::Error on bad input), named as the reports name it - a
// file by its stem ("cornellBox"), a built-in by its spec ("builtin:corner").
Scene loadNamedScene(const std::string& spec);
// Scenes measured side by side: each once (a file by its resolved path, a built-in by its spec),
// no two with one name - builtin:NAME, a file by the shortest end of its path that no other has
// ("cornellBox", or "a/scene.gltf" beside "b/scene.gltf"). `specs` keeps the first of each.
std::vector<Scene> loadNamedScenes(std::vector<std::string>& specs);
// The scene's own camera (the file's first, or a built-in's designed view), else one framing it.
Camera defaultCamera(const Scene& s);

} // namespace ssao
