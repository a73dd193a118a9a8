// `ssaolab render`: headless render of one scene with one settings set into an output folder.
#pragma once
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ssao {

struct RenderOptions {
    std::string scene = "builtin:showcase";
    std::string preset;            // file path, or a name under assets/presets/
    std::vector<std::string> sets; // key=value
    std::string size = "1280x720";
    std::string camera; // eye,target[,up[,fov[,near,far]]]
    std::string out = "out";
    std::string shaderDir; // default: the source tree's shaders/
    int timingFrames = 3;  // extra frames, all passes forced, averaged for gpu_ms
    bool verboseGl = false;
    bool quiet = false;
};

void addRenderOptions(CLI::App& cmd, RenderOptions& o);
// Throws ssao::Error on any problem; returns the process exit code.
int runRender(const RenderOptions& o);

// Resolves a preset argument: an existing path, or NAME → assets/presets/NAME.json.
std::string resolvePreset(const std::string& arg);

} // namespace ssao
