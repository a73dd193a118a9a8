#include "cli/scene_options.h"

#include "cli/headless_runner.h"
#include "util/error.h"
#include "renderer.h"

#include <CLI/CLI.hpp>

namespace ssao {

void addLensOptions(CLI::App& cmd, std::string& projection, std::string& depth) {
    cmd.add_option("--projection", projection,
                   "perspective (default) or orthographic (spans what the fov sees at the target's distance)")
        ->check(CLI::IsMember({"perspective", "orthographic"}));
    cmd.add_option("--depth", depth,
                   "depth buffer mapping: reversed (default: reversed-Z float, any far/near, far may be inf) "
                   "or standard (OpenGL's [-1, 1])")
        ->check(CLI::IsMember({"standard", "reversed"}));
}

void applyCameraOptions(Camera& c, const std::string& clip, const std::string& projection,
                        const std::string& depth) {
    if (clip == "fit") c.clip = ClipMode::Fit;
    if (clip == "fixed") c.clip = ClipMode::Fixed;
    if (!projection.empty()) c.projectionKind = parseProjection(projection);
    if (!depth.empty()) c.depth = parseDepthMode(depth);
}

void addStartCameraOption(CLI::App& cmd, std::string& camera) {
    cmd.add_option("--camera", camera,
                   "the first viewpoint, eye,target[,up[,fov_deg[,near,far]]] in the scene file's coordinates (as "
                   "render takes it); the other views orbit about it (default: the scene's own camera)")
        ->type_name("EYE,TARGET...");
}

Camera startCamera(const std::string& cameraOption, const Scene& scene) {
    const Camera base = defaultCamera(scene);
    return cameraOption.empty() ? base : parseCamera(cameraOption, base, scene.origin);
}

void parseSizeOption(const std::string& s, int& w, int& h) {
    // Digits only, at most 6 a side: sscanf's %d wraps 4294967396 to 100 without a word.
    const size_t x = s.find('x');
    auto side = [&](size_t from, size_t to, int& out) {
        if (to <= from || to - from > 6) return false;
        for (size_t i = from; i < to; ++i)
            if (s[i] < '0' || s[i] > '9') return false;
        out = std::stoi(s.substr(from, to - from));
        return true;
    };
    if (x == std::string::npos || !side(0, x, w) || !side(x + 1, s.size(), h))
        throw Error("--size '" + s + "': expected WIDTHxHEIGHT, e.g. 1280x720");
    try {
        checkRenderSize(w, h);
    } catch (const Error& e) {
        throw Error("--size '" + s + "': " + e.what());
    }
}

} // namespace ssao
