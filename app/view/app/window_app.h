// The interactive explorer in a GLFW window (OpenGL 4.5 core + Dear ImGui).
#pragma once
#include "view/app/app_core.h"

#include <string>

namespace ssao {

struct WindowOptions {
    AppOptions app;
    int width = 1600, height = 900; // window size in screen coordinates
    int frames = 0;                 // > 0: draw this many frames, then exit (tests, screenshots)
    std::string screenshot;         // with frames: PNG of the last frame
    std::string frameLog;           // if set: one line per drawn frame (ms, render size, moving, passes)
};

// True when a window can plausibly open (an X11 or Wayland display is set).
bool haveDisplay();
// Runs until the window closes (or `frames` are drawn). Throws ssao::Error when no window can open.
int runWindowApp(const WindowOptions& o);

} // namespace ssao
