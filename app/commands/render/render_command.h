// `ssaolab render`: headless render of one scene with one settings set into an output folder.
#pragma once
#include "scene/camera.h"
#include "scene/camera_path.h"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ssao {

struct RenderOptions {
    std::string scene;             // empty: the preset's scene, else builtin:showcase
    std::string preset;            // file path, or a name (seed presets, then the user's)
    std::vector<std::string> sets; // key=value
    std::string size;              // empty: the preset's size, else 1280x720
    std::string camera;            // eye,target[,up[,fov[,near,far]]]
    std::string clip;              // fit | fixed (empty: the camera's own setting)
    std::string projection;        // perspective | orthographic (empty: the camera's own)
    std::string depth;             // standard | reversed (empty: the camera's own)
    std::string out = "out";
    std::string shaderDir; // default: the installation's (or source tree's) shaders/
    std::string presetDir; // user presets (default: as the app)
    int timingFrames = 3;  // extra frames, all passes forced, averaged for gpu_ms
    bool fitRange = false, falseColor = false;
    bool reference = false;        // also trace the reference AO and write the error
    int referenceRays = 512;       // rays per pixel
    std::string referenceVariant = "visibility";
    bool noCache = false;          // trace even when the reference cache has this view
    int oracleLayers = 1;          // the screen-space oracle's depth layers (2: a deep G-buffer)
    double oracleThickness = 1.0;  // its surfaces' thickness, x R (inf: a height field)
    int oracleGuard = 0;           // pixels its G-buffer holds beyond each edge
    std::vector<std::string> score; // AO images of the same view made elsewhere, judged alike
    bool motion = false;           // also score the AO along a camera path (measure/motion_measure.h)
    CameraPathSpec motionPath;
    bool verboseGl = false;
    bool quiet = false;
};

void addRenderOptions(CLI::App& cmd, RenderOptions& o);
// Throws ssao::Error on any problem; returns the process exit code.
int runRender(const RenderOptions& o);

} // namespace ssao
