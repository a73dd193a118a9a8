// The child process of tests/gl/test_frame_time_limit.cpp: renders one frame of a user technique
// whose shader never ends, with the per-frame time limit given as its argument (0: none). Its own
// program with its own EGL context, because a context stuck in such a frame cannot be torn down.
#include "gl/context.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"
#include "renderer.h"
#include "scene/scene.h"
#include "settings/params.h"
#include "techniques/technique.h"
#include "techniques/user/user_source.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>

namespace {
// A body the compiler cannot prove finite (i wraps only after 2^31 steps) whose every step is
// costly: llvmpipe ends any outermost loop, with the loops inside it, after 65535 iterations, so
// only the cost of a step keeps it running there (on a GPU it never ends). One loop: many would
// keep LLVM's loop analysis busy in the compile instead of the frame.
std::shared_ptr<const ssao::UserTechnique> endless() {
    std::string text = "/*ssaolab\ninterface = 1;\n*/\n"
                       "float ssaoUserAo() {\n"
                       "    float x = 0.0;\n"
                       "    for (int i = 0; i >= 0; i += int(ssaoRadius() > -1.0)) {\n";
    for (int step = 0; step < 64; ++step)
        text += "        x = sin(x * 1.3 + float(i));\n";
    text += "    }\n    return x;\n}\n";
    return std::make_shared<ssao::UserTechnique>(ssao::loadUserTechnique(text, "mine/endless.ao.glsl", ssao::builtinTechniqueIds()));
}
} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: hang_child LIMIT_SECONDS\n");
        return 2;
    }
    try {
        ssao::gl::HeadlessContext context;
        const ssao::Scene scene = ssao::loadScene("builtin:showcase");
        ssao::Renderer r(SSAOLAB_SHADER_DIR);
        r.setSize(320, 180);
        r.setScene(scene);
        r.setCamera(scene.camera.value_or(ssao::frameBounds(scene.bounds)));
        ssao::setUserTechniques({endless()});
        ssao::Settings s = ssao::defaultSettings();
        s.ao.technique = "user.endless";
        r.setSettings(s);
        r.setFrameTimeLimit(std::atof(argv[1]));
        std::printf("rendering the endless frame\n");
        std::fflush(stdout);
        r.render();
        ssao::readBack(r.texture("ao.raw"), 1);
        std::printf("the endless frame ended\n");
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hang_child: %s\n", e.what());
        return 3;
    }
}
