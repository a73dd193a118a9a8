#include "view/app/window_app.h"

#include "base/image.h"
#include "gl/context.h"
#include "util/error.h"
#include "util/files.h"

#include <epoxy/gl.h>
// GLFW after epoxy: epoxy provides the GL declarations.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace ssao {

namespace {

std::string g_glfwError;
void onGlfwError(int code, const char* msg) {
    g_glfwError = std::string(msg) + " (" + std::to_string(code) + ")";
}

AppCore* appOf(GLFWwindow* w) {
    return static_cast<AppCore*>(glfwGetWindowUserPointer(w));
}
bool g_screenshotRequested = false; // F12
void keepAwake(GLFWwindow* w) {
    if (AppCore* a = appOf(w)) a->frames().keepAwake();
}

// Installed before ImGui's backend, which chains to them: every input event wakes the loop.
void installWakeCallbacks(GLFWwindow* w) {
    glfwSetCursorPosCallback(w, [](GLFWwindow* win, double, double) { keepAwake(win); });
    glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int, int, int) { keepAwake(win); });
    glfwSetScrollCallback(w, [](GLFWwindow* win, double, double) { keepAwake(win); });
    glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int mods) {
        if (key == GLFW_KEY_F12 && action == GLFW_PRESS) g_screenshotRequested = true;
        // Quit: Ctrl+Q, or Esc when no text field has the keyboard (Esc also leaves a field).
        const bool typing = ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput;
        if (action == GLFW_PRESS && ((key == GLFW_KEY_Q && (mods & GLFW_MOD_CONTROL)) || (key == GLFW_KEY_ESCAPE && !typing)))
            glfwSetWindowShouldClose(win, GLFW_TRUE);
        keepAwake(win);
    });
    glfwSetCharCallback(w, [](GLFWwindow* win, unsigned) { keepAwake(win); });
    glfwSetWindowFocusCallback(w, [](GLFWwindow* win, int) { keepAwake(win); });
    glfwSetCursorEnterCallback(w, [](GLFWwindow* win, int) { keepAwake(win); });
    glfwSetFramebufferSizeCallback(w, [](GLFWwindow* win, int, int) { keepAwake(win); });
    glfwSetWindowRefreshCallback(w, [](GLFWwindow* win) { keepAwake(win); });
    glfwSetDropCallback(w, [](GLFWwindow* win, int n, const char** paths) {
        if (AppCore* a = appOf(win)) a->dropFiles(std::vector<std::string>(paths, paths + n));
    });
}

void screenshot(int w, int h, const std::string& path) {
    Image img{w, h, 3, std::vector<float>(size_t(w) * h * 3)};
    std::vector<unsigned char> px(size_t(w) * h * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, px.data());
    for (int y = 0; y < h; ++y)
        for (int i = 0; i < w * 3; ++i)
            img.data[size_t(y) * w * 3 + i] = float(px[size_t(h - 1 - y) * w * 3 + i]) / 255.0f;
    writePng(img, path);
}

struct GlfwSession {
    GlfwSession() {
        glfwSetErrorCallback(onGlfwError);
        gl::pinMesaForLeakSanitizer();
        if (!glfwInit())
            throw Error(
                "no display: cannot open a window (" + g_glfwError +
                "); use `ssaolab render` for headless output, or run under Xvfb: xvfb-run -a ssaolab");
    }
    ~GlfwSession() { glfwTerminate(); }
};

} // namespace

bool haveDisplay() {
    const char* x = std::getenv("DISPLAY");
    const char* wl = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (wl && *wl);
}

namespace {

GLFWwindow* createWindow(const WindowOptions& o) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE); // HiDPI: window sized in logical pixels
    GLFWwindow* window = glfwCreateWindow(o.width, o.height, "ssaolab", nullptr, nullptr);
    if (!window) throw Error("no GL: cannot create an OpenGL 4.5 core window (" + g_glfwError + ")");
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    gl::installDebugOutput(false);
    return window;
}

void initImGui(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // layout is computed, nothing to persist
    float xs = 1.0f, ys = 1.0f;
    glfwGetWindowContentScale(window, &xs, &ys);
    io.FontGlobalScale = std::max(xs, 1.0f);
    ImGui::StyleColorsDark();
    ImGui::GetStyle().ScaleAllSizes(std::max(xs, 1.0f));
    installWakeCallbacks(window);
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450 core");
}

// The window's loop: sleeps while idle, draws the UI when something changes, saves screenshots and
// writes the frame log.
class FrameLoop {
  public:
    FrameLoop(GLFWwindow* window, AppCore& app, const WindowOptions& o, AppendFile& log)
        : window_(window), app_(app), o_(o), log_(log) {}

    void run() {
        double lastShaderCheck = glfwGetTime();
        while (!glfwWindowShouldClose(window_)) {
            const bool idle = o_.frames == 0 && !app_.frames().busy();
            // Idle costs nothing: sleep until an event (or a periodic check for edited shaders).
            idle ? glfwWaitEventsTimeout(0.5) : glfwPollEvents();
            // Shader files are checked at most twice a second, not on every busy frame.
            if (const double now = glfwGetTime(); now - lastShaderCheck >= 0.5) {
                lastShaderCheck = now;
                app_.pollShaderReload();
            }
            if (o_.frames == 0 && !app_.frames().busy()) continue;
            if (drawFrame()) break;
        }
    }

  private:
    // Returns true after the last frame of --frames N.
    bool drawFrame() {
        const auto t0 = std::chrono::steady_clock::now();
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        app_.drawUi();
        ImGui::Render();
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(window_, &fw, &fh);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fw, fh);
        clearUiBackground();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        ++frame_;
        if (g_screenshotRequested) f12Screenshot(fw, fh);
        const bool last = o_.frames > 0 && frame_ >= o_.frames;
        if (last && !o_.screenshot.empty()) screenshot(fw, fh, o_.screenshot);
        if (!last) glfwSwapBuffers(window_);
        const float ms = std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - t0).count();
        app_.frames().noteFrameMs(ms);
        if (log_.isOpen()) logFrame(ms);
        return last;
    }

    // F12: the window as the user sees it, into the current folder, under the next free name
    // (screenshots of earlier sessions are never overwritten).
    void f12Screenshot(int fw, int fh) {
        g_screenshotRequested = false;
        static int shots = 0;
        std::string name;
        do
            name = "ssaolab-screenshot-" + std::to_string(++shots) + ".png";
        while (std::filesystem::exists(name));
        try {
            screenshot(fw, fh, name);
            app_.setStatus("saved " + name, false);
        } catch (const std::exception& e) {
            app_.setStatus(e.what(), true);
        }
    }

    void logFrame(float ms) {
        const FrameDriver& f = app_.frames();
        const bool rendered = f.framesRendered() != renderedBefore_;
        renderedBefore_ = f.framesRendered();
        std::ostringstream line;
        line << frame_ << " " << ms << " " << app_.renderer().width() << " " << app_.renderer().height() << " "
             << (f.renderedInteractive() ? 1 : 0) << " " << (rendered ? 1 : 0) << " ";
        if (rendered)
            for (const auto& p : f.lastReport().ran())
                line << p << ",";
        line << "\n";
        log_.write(line.str()); // a full disk ends the session with its error, not a silent stop
    }

    GLFWwindow* window_;
    AppCore& app_;
    const WindowOptions& o_;
    AppendFile& log_;
    int frame_ = 0, renderedBefore_ = 0;
};

} // namespace

int runWindowApp(const WindowOptions& o) {
    // Before any window: a frame log that cannot be written is refused without a display.
    AppendFile log;
    if (!o.frameLog.empty()) {
        log = AppendFile(o.frameLog, "frame log");
        log.write("# frame ms(CPU, UI + render + swap) render_w render_h moving rendered passes_run\n");
    }
    GlfwSession glfw;
    GLFWwindow* window = createWindow(o);
    initImGui(window);
    int rc = 0;
    {
        AppOptions appOptions = o.app;
        // The reference's worker thread wakes the sleeping loop when a snapshot or progress step is
        // ready (glfwPostEmptyEvent may be called from any thread; AppCore joins it before glfwTerminate).
        appOptions.wake = [] { glfwPostEmptyEvent(); };
        AppCore app(appOptions);
        if (!app.startupError().empty()) {
            const std::string line = oneLine(app.startupError());
            std::fprintf(stderr, "ssaolab: error: %s\n", line.c_str());
            rc = 1; // the window stays open on the built-in scene; the exit status still says it failed
        }
        glfwSetWindowUserPointer(window, &app);
        FrameLoop(window, app, o, log).run();
        log.close();
        gl::pollGlErrors();
        if (gl::glErrorCount() > 0) {
            std::fprintf(stderr, "ssaolab: error: OpenGL reported %d error(s) during the session\n",
                         gl::glErrorCount());
            rc = 1;
        }
        glfwSetWindowUserPointer(window, nullptr);
    } // AppCore (and every GL object) released while the context is still current
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    return rc;
}

} // namespace ssao
