#include "cli/headless_runner.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"

#include "scene/view_fit.h"
#include "util/error.h"
#include "util/paths.h"
#include "util/unique_suffix.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>

namespace ssao {

HeadlessRunner::HeadlessRunner(const Options& o)
    : shaderDir_(o.shaderDir.empty() ? shaderRoot() : o.shaderDir) {
    gl::installDebugOutput(o.verboseGl);
    glRenderer_ = context_.renderer();
    glPlatform_ = context_.platform();
    gl::resetGlErrorCount();
    if (const char* force = std::getenv(kForceGlErrorEnv); force && std::string(force) == "1")
        glEnable(GL_TEXTURE_2D); // not a capability in a core profile: GL_INVALID_ENUM
}

namespace {
double frameTimeLimit = HeadlessRunner::kDefaultFrameTimeLimit; // seconds; set once, before any run
} // namespace

void HeadlessRunner::setFrameTimeLimit(double seconds) {
    frameTimeLimit = seconds;
}

std::unique_ptr<Renderer> HeadlessRunner::makeRenderer(int w, int h) const {
    auto r = std::make_unique<Renderer>(shaderDir_);
    r->setSize(w, h);
    r->setFrameTimeLimit(frameTimeLimit);
    return r;
}

void HeadlessRunner::checkGl(const std::string& during) const {
    const std::string first = gl::pollGlErrors();
    const int n = gl::glErrorCount();
    if (n > 0)
        throw Error("OpenGL reported " + std::to_string(n) + " error(s) " + during +
                    (first.empty() ? "" : " (" + first + ")"));
}

Image HeadlessRunner::readFinite(const Renderer& r, const std::string& buffer, const std::string& during) const {
    const Resource& res = r.resource(buffer);
    Image img = readBack(res.texture, res.desc.channels);
    long bad = 0;
    for (float v : img.data)
        bad += std::isfinite(v) ? 0 : 1;
    if (bad > 0)
        throw Error(std::to_string(bad) + " non-finite values in " + buffer + " " + during);
    return img;
}

Scene loadNamedScene(const std::string& spec) {
    Scene s = loadScene(spec);
    if (spec.rfind("builtin:", 0) != 0) s.name = std::filesystem::path(spec).stem().string();
    return s;
}

std::vector<Scene> loadNamedScenes(std::vector<std::string>& specs) {
    namespace fs = std::filesystem;
    std::vector<std::string> kept, files, builtins;
    std::set<std::string> seen;
    for (const auto& spec : specs) {
        const bool builtin = spec.rfind("builtin:", 0) == 0;
        std::error_code ec;
        fs::path abs = builtin ? fs::path(spec) : fs::absolute(spec, ec);
        if (ec) abs = spec;
        abs = abs.lexically_normal();
        fs::path key = builtin ? abs : fs::weakly_canonical(abs, ec); // links resolved: one file, one scene
        if (ec || key.empty()) key = abs;
        if (!seen.insert(key.string()).second) continue;
        kept.push_back(spec);
        (builtin ? builtins : files).push_back(abs.generic_string());
    }
    const std::vector<std::string> names = shortestUniqueSuffixes(files, builtins);
    std::vector<Scene> scenes;
    size_t file = 0;
    for (const auto& spec : kept) {
        scenes.push_back(loadScene(spec));
        if (spec.rfind("builtin:", 0) != 0) scenes.back().name = names[file++];
    }
    specs = kept;
    return scenes;
}

Camera defaultCamera(const Scene& s) {
    return s.camera.value_or(frameBounds(s.bounds));
}

} // namespace ssao
