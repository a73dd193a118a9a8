#include "gl/context.h"

#include "util/error.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#ifdef SSAOLAB_SANITIZE
#include <dlfcn.h>
#endif

namespace ssao::gl {

struct HeadlessContext::Impl {
    EGLDisplay dpy = EGL_NO_DISPLAY;
    EGLContext ctx = EGL_NO_CONTEXT;
};

namespace {

bool hasExtension(const char* list, const char* ext) {
    if (!list) return false;
    size_t n = std::strlen(ext);
    for (const char* p = list; (p = std::strstr(p, ext)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

// Creates a 4.5 core context on an initialised display; EGL_NO_CONTEXT on failure.
EGLContext createCoreContext(EGLDisplay dpy) {
    if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
    const EGLint cfgAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig cfg = nullptr;
    EGLint n = 0;
    // Surfaceless contexts may use EGL_NO_CONFIG_KHR; fall back to it when no config is offered.
    if (!eglChooseConfig(dpy, cfgAttribs, &cfg, 1, &n) || n == 0) cfg = nullptr;
    const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_CONTEXT_OPENGL_DEBUG,
                                 EGL_TRUE,
                                 EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, ctxAttribs);
    if (ctx == EGL_NO_CONTEXT) return EGL_NO_CONTEXT;
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        eglDestroyContext(dpy, ctx);
        return EGL_NO_CONTEXT;
    }
    return ctx;
}

bool tryDisplay(EGLDisplay dpy, HeadlessContext* /*unused*/, EGLDisplay& outDpy, EGLContext& outCtx) {
    if (dpy == EGL_NO_DISPLAY) return false;
    EGLint major = 0, minor = 0;
    if (!eglInitialize(dpy, &major, &minor)) return false;
    EGLContext ctx = createCoreContext(dpy);
    if (ctx == EGL_NO_CONTEXT) {
        eglTerminate(dpy);
        return false;
    }
    outDpy = dpy;
    outCtx = ctx;
    return true;
}

} // namespace

// Sanitizer builds only: Mesa keeps some allocations past eglTerminate (its screen, the LLVM JIT)
// and then unloads its driver, after which LeakSanitizer can name none of their frames, so no
// suppression can match them. Loading the driver libraries once more with RTLD_NODELETE keeps them
// mapped to the end: the leaks are then attributed to them and suppressed by name
// (.ci/lsan.supp), while a leak in ssaolab's own code still fails the run.
void pinMesaForLeakSanitizer() {
#ifdef SSAOLAB_SANITIZE
    static const bool pinned = [] {
        for (const char* lib : {"libEGL_mesa.so.0", "/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so",
                                "/usr/lib/x86_64-linux-gnu/dri/kms_swrast_dri.so", "libGLX_mesa.so.0"})
            dlopen(lib, RTLD_NOW | RTLD_NODELETE);
        return true;
    }();
    (void)pinned;
#endif
}

bool eglClientOffersDevices(const char* clientExtensions) {
    // Before this accepted EGL_EXT_device_base, an H200 (driver 580) was reached only through the
    // surfaceless platform NVIDIA's EGL also offers: the same GPU, but never the device platform.
    return hasExtension(clientExtensions, "EGL_EXT_platform_device") &&
           (hasExtension(clientExtensions, "EGL_EXT_device_enumeration") ||
            hasExtension(clientExtensions, "EGL_EXT_device_base"));
}

HeadlessContext::HeadlessContext(EglPlatform platform) : impl_(std::make_unique<Impl>()) {
    pinMesaForLeakSanitizer();
    if (const char* env = std::getenv("SSAOLAB_EGL_PLATFORM")) {
        if (!std::strcmp(env, "surfaceless")) platform = EglPlatform::Surfaceless;
        if (!std::strcmp(env, "device")) platform = EglPlatform::Device;
    }
    const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!clientExts || !hasExtension(clientExts, "EGL_EXT_platform_base"))
        throw Error(
            "no GL: EGL client has no EGL_EXT_platform_base (is libegl1 with Mesa or NVIDIA installed?)");

    // 1. A hardware device (NVIDIA through EGL_EXT_platform_device), skipping Mesa's software one.
    if (platform != EglPlatform::Surfaceless && eglClientOffersDevices(clientExts)) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (eglQueryDevicesEXT(16, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                const char* devExts = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
                if (platform == EglPlatform::Auto && hasExtension(devExts, "EGL_MESA_device_software"))
                    continue;
                EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (tryDisplay(dpy, this, impl_->dpy, impl_->ctx)) {
                    platform_ = "EGL_EXT_platform_device";
                    break;
                }
            }
        }
    }
    // 2. Mesa surfaceless (llvmpipe on a machine without a GPU).
    if (impl_->ctx == EGL_NO_CONTEXT && platform != EglPlatform::Device &&
        hasExtension(clientExts, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay dpy =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (tryDisplay(dpy, this, impl_->dpy, impl_->ctx)) platform_ = "EGL_PLATFORM_SURFACELESS_MESA";
    }
    if (impl_->ctx == EGL_NO_CONTEXT)
        throw Error("no GL: could not create a headless OpenGL 4.5 core context "
                    "(tried EGL_EXT_platform_device and EGL_MESA_platform_surfaceless)");
    if (epoxy_gl_version() < 45) throw Error("no GL: context is older than OpenGL 4.5");
}

HeadlessContext::~HeadlessContext() {
    if (impl_->dpy != EGL_NO_DISPLAY) {
        eglMakeCurrent(impl_->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (impl_->ctx != EGL_NO_CONTEXT) eglDestroyContext(impl_->dpy, impl_->ctx);
        eglTerminate(impl_->dpy);
    }
}

std::string HeadlessContext::renderer() const {
    const GLubyte* r = glGetString(GL_RENDERER);
    return r ? reinterpret_cast<const char*>(r) : "unknown";
}

// ---- Debug output ------------------------------------------------------------------------------

namespace {
std::atomic<int> g_errors{0};
bool g_verbose = false;

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void*) {
    (void)length;
    // Compile errors are reported (with file:line) by the ShaderLibrary's exception instead.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER && !g_verbose) return;
    const bool isError = type == GL_DEBUG_TYPE_ERROR;
    if (isError) ++g_errors;
    if (isError || severity == GL_DEBUG_SEVERITY_HIGH || g_verbose)
        std::fprintf(stderr, "[gl%s] %s (id %u)\n", isError ? " error" : "", message, id);
}
} // namespace

void installDebugOutput(bool verbose) {
    g_verbose = verbose;
    if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS); // errors are reported at the call that caused them
    glDebugMessageCallback(onDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

int glErrorCount() {
    return g_errors.load();
}
void resetGlErrorCount() {
    g_errors = 0;
}

std::string pollGlErrors() {
    std::string first;
    for (GLenum e; (e = glGetError()) != GL_NO_ERROR;) {
        ++g_errors;
        if (first.empty()) first = "glGetError 0x" + hex(e);
    }
    return first;
}

} // namespace ssao::gl
