// Headless OpenGL 4.5 core context through EGL: a real GPU via EGL_EXT_platform_device when one
// exists, else Mesa's surfaceless platform (llvmpipe). Debug output is routed to the log and
// every GL error is counted, so a run can fail when the driver complained.
#pragma once
#include <memory>
#include <string>

namespace ssao::gl {

enum class EglPlatform { Auto, Device, Surfaceless };

// Sanitizer builds: keeps Mesa's driver libraries mapped until exit so LeakSanitizer can name (and
// .ci/lsan.supp suppress) the allocations Mesa keeps past eglTerminate. Does nothing otherwise.
void pinMesaForLeakSanitizer();

// Whether an EGL client extension string offers the device platform with device enumeration:
// EGL_EXT_platform_device and either EGL_EXT_device_enumeration (Mesa) or EGL_EXT_device_base
// (enumeration plus query in one; NVIDIA's driver lists only this). Pure.
bool eglClientOffersDevices(const char* clientExtensions);

class HeadlessContext {
  public:
    explicit HeadlessContext(EglPlatform platform = EglPlatform::Auto);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    std::string renderer() const; // GL_RENDERER
    std::string platform() const { return platform_; }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string platform_;
};

// KHR_debug: installs the callback on the current context. Errors are counted (see below);
// with `verbose` every message is logged to stderr, else only errors and high severity.
void installDebugOutput(bool verbose);
// GL errors reported (debug callback + glGetError) since the last reset.
int glErrorCount();
void resetGlErrorCount();
// Polls glGetError, adds to the count and returns the first error text ("" if none).
std::string pollGlErrors();

} // namespace ssao::gl
