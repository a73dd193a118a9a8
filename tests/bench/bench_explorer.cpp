// The explorer's frame times as a user meets them (not a test: it prints figures and asserts
// nothing). The real app UI (AppCore + Dear ImGui + its OpenGL3 backend, tests/app/ui_driver.h)
// on the headless context at the default window's size, 1600x900, in the view it opens in; each
// frame timed on the CPU clock from input to glFinish (UI, every pass the frame runs, the UI's draw).
//  - drag: 24 frames of a left-button drag over the view (the camera orbits; the app renders at
//    its interactive scale while moving);
//  - still: the first frame after the button is released and input settles (every pass at full
//    resolution: what a user waits for after letting go);
//  - idle: a frame where nothing changed.
// After a warm-up drag (it compiles the moving size's shaders), three drags and releases, each
// orbiting on from the last: the still and idle figures are their medians, the drag median and
// max over all their frames (one release alone moved by 20-40 % between runs on a 2-core llvmpipe).
// Each scene with the start preset (or --preset NAME) and with the learnopengl baseline, in the same run.
// --cursor-away: after the release the cursor leaves the image (as when a slider is tweaked next), so
// the per-pixel readout does not ask for every buffer.
// Usage: bench_explorer [--no-reference] [--single] [--cursor-away] [--preset NAME] [SCENE ...] (default: the shared scenes named below).
#include "gl/context.h"
#include "settings/preset.h"
#include "settings/preset_store.h"
#include "ui_driver.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace ssao;

namespace {
struct Times {
    double still = 0, dragMedian = 0, dragMax = 0, idle = 0;
    int stillW = 0, stillH = 0, dragW = 0, dragH = 0;
    std::string passes, movingPasses; // GPU ms of each pass, full size and moving (the app's timer queries)
};

double timed(ssaotest::UiDriver& ui, float x, float y, bool down) {
    const auto t0 = std::chrono::steady_clock::now();
    ui.frame(x, y, down);
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

Times measure(const std::string& scene, const std::string& preset, bool reference, bool single, bool away) {
    AppOptions o;
    o.scene = scene;
    o.preset = preset;
    o.reference = reference;
    ssaotest::UiDriver ui(o, 1600, 900);
    if (single) ui.app().view().mode = ViewMode::Single; // the composite alone, enlarged
    ui.settle();
    ImVec4 v(0, 0, 0, 0); // the largest view on screen (the grid's first, or the single view)
    for (const auto& [key, r] : ui.app().view().widgetRects)
        if (key.rfind("view#", 0) == 0 && (r.z - r.x) * (r.w - r.y) > (v.z - v.x) * (v.w - v.y)) v = r;
    const float cx = (v.x + v.z) * 0.5f, cy = (v.y + v.w) * 0.5f;
    // Where the cursor rests after the release: on the image, or just beside it.
    const float rx = away ? (v.x > 8.0f ? v.x - 4.0f : v.z + 4.0f) : cx + 150.0f, ry = away ? cy : cy + 24.0f;
    Times t;
    constexpr int kRounds = 4; // the first round warms shaders of the moving size and is not counted
    std::vector<double> stills, idles, drags;
    for (int round = 0; round < kRounds; ++round) {
        ui.frame(cx, cy, false);
        ui.frame(cx, cy, true);
        std::vector<double> drag;
        for (int i = 1; i <= 24; ++i) drag.push_back(timed(ui, cx + 6.0f * float(i), cy + 1.0f * float(i), true));
        t.dragW = ui.app().renderer().width(), t.dragH = ui.app().renderer().height();
        drag.erase(drag.begin()); // the press frame renders the last still size
        ui.frame(cx + 150.0f, cy + 24.0f, false);
        ui.frame(rx, ry, false); // not timed: the still frames follow (the app settles after 0.25 s)
        // Frames with no input until the app renders at full resolution: the still frame is the
        // slowest of them (the one that re-runs every pass at full size).
        double still = 0;
        for (int i = 0; i < 200 && (ui.app().frames().interacting() || i < 3); ++i)
            still = std::max(still, timed(ui, rx, ry, false));
        for (int i = 0; i < 3; ++i) still = std::max(still, timed(ui, rx, ry, false));
        t.stillW = ui.app().renderer().width(), t.stillH = ui.app().renderer().height();
        const double idle = timed(ui, rx, ry, false);
        if (round == 0) continue;
        stills.push_back(still), idles.push_back(idle);
        drags.insert(drags.end(), drag.begin(), drag.end());
    }
    t.still = median(stills), t.idle = median(idles);
    t.dragMedian = median(drags);
    t.dragMax = *std::max_element(drags.begin(), drags.end());
    for (bool moving : {false, true})
        for (const auto& [pass, runs] : ui.app().frames().timing(moving).ms) {
            std::string& out = moving ? t.movingPasses : t.passes;
            char b[64];
            std::snprintf(b, sizeof b, "%s%s %.1f", out.empty() ? "" : ", ", pass.c_str(),
                          ui.app().frames().timing(moving).average(pass));
            out += b;
        }
    return t;
}
} // namespace

int main(int argc, char** argv) {
    bool reference = true, single = false, away = false;
    std::string startPreset = kStartPreset; // --preset: another candidate for the first frame
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--no-reference")
            reference = false;
        else if (a == "--single")
            single = true;
        else if (a == "--cursor-away")
            away = true;
        else if (a == "--preset") {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "bench_explorer: --preset needs a preset name\n");
                return 2;
            }
            startPreset = argv[++i];
        }
        else if (a.rfind("-", 0) == 0) { // not a scene: it was taken for one, and the fallback timed
            std::fprintf(stderr, "bench_explorer: unknown option '%s' (usage: bench_explorer [--no-reference] "
                                 "[--single] [--cursor-away] [--preset NAME] [SCENE ...])\n", a.c_str());
            return 2;
        } else if (!std::filesystem::exists(a) && a.rfind("builtin:", 0) != 0) {
            std::fprintf(stderr, "bench_explorer: no scene file '%s'\n", a.c_str());
            return 2;
        } else
            scenes.push_back(a);
    }
    if (scenes.empty())
        for (const char* s : {"CornellBox/cornellBox.gltf", "FlightHelmet/FlightHelmet.gltf", "Lantern/Lantern.gltf",
                              "ShaderBall/shader_ball.gltf", "2CylinderEngine/2CylinderEngine.gltf",
                              "ReciprocatingSaw/ReciprocatingSaw.gltf"})
            scenes.push_back(std::string(SSAOLAB_SCENES_DIR) + "/" + s);
    try {
        PresetStore::standard().open(startPreset); // an unknown name stops here, before any timing
        gl::HeadlessContext ctx;
        std::printf("GL renderer: %s via %s; window 1600x900, %s view; reference %s; cursor %s\n",
                    ctx.renderer().c_str(), ctx.platform().c_str(), single ? "single" : "grid (as the app opens)",
                    reference ? "on (tracing in the background, as the app opens)" : "off",
                    away ? "beside the image after the release" : "on the image");
        std::printf("| scene | preset | still ms (size) | drag ms median / max (size) | idle ms | still x baseline | drag x baseline | GPU ms per pass: still | moving |\n");
        std::printf("|---|---|---:|---:|---:|---:|---:|---|---|\n");
        for (const std::string& scene : scenes) {
            const Times base = measure(scene, "learnopengl", reference, single, away);
            const Times start = measure(scene, startPreset, reference, single, away);
            const std::string name = std::filesystem::path(scene).stem().string();
            for (const auto& [preset, t] : {std::pair<std::string, Times>{startPreset, start}, {"learnopengl", base}})
                std::printf("| %s | %s | %.1f (%dx%d) | %.1f / %.1f (%dx%d) | %.1f | %.2f | %.2f | %s | %s |\n",
                            name.c_str(), preset.c_str(), t.still, t.stillW, t.stillH, t.dragMedian, t.dragMax, t.dragW,
                            t.dragH, t.idle, t.still / base.still, t.dragMedian / base.dragMedian, t.passes.c_str(),
                            t.movingPasses.c_str());
            std::fflush(stdout);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_explorer: %s\n", e.what());
        return 1;
    }
    return 0;
}
