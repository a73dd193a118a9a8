// An AO technique is a module: a folder under renderer/techniques/ with its settings struct, its
// parameter rows, a pure constants-packing function, its config and pass (the frame-graph wiring)
// and its shader under shaders/techniques/; the module declares what it can do (below). The
// registry (registry.cpp) lists the modules; nothing else outside a technique's folders names it.
#pragma once
#include "base/param.h"
#include "techniques/registry.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ssao {

class Pass;
struct Chain;

// The per-pixel count the adaptive rule (ao.adaptive, shaders/include/adaptive.h) cuts: a march's
// steps per side, or an area sampler's taps.
struct AdaptiveCount {
    int full = 0;
    bool march = true;
};

struct UserTechnique;

struct TechniqueInfo {
    std::string id;      // value of ao.technique, and the group of the technique's rows
    std::string label;   // for the UI
    std::string summary; // one line: what it estimates and where it comes from
    // A user technique (techniques/user/user_technique.h): its file as errors name it, and the
    // hash of the text its passes were made from (a new version gets new passes); "" for a built-in.
    std::string file, version;
    std::shared_ptr<const UserTechnique> user; // the technique itself (null for a built-in)
    std::function<std::vector<Param>()> params; // rows "id.*"
    // Its passes for one chain: together they read gbuffer.* and write the chain's ao.raw.
    std::function<std::vector<std::unique_ptr<Pass>>(const Chain&)> makePasses;
    // Capabilities. Whether these settings read the position pyramid (passes/position_pyramid_pass.h,
    // which the renderer then adds); null = never.
    std::function<bool(const Settings&)> pyramid;
    // The count ao.adaptive cuts for these settings; null = the technique takes no adaptive count.
    std::function<AdaptiveCount(const Settings&)> adaptive;
    // Whether its AO under these settings is the same every frame (no noise, or none that moves
    // with the temporal frame index): temporal accumulation then has nothing to average and reads
    // no history (passes/temporal_accumulator.h); null = never.
    std::function<bool(const Settings&)> staticNoise;
    // Its shader can run over deinterleaved layers (ao.deinterleave, techniques/deinterleave.h): it
    // takes its pixel's noise from noise.glsl's aoNoise and its taps at whole pixels of the frame it
    // is drawn over.
    bool deinterleave = false;
    // Its shader reads the second depth layer (gbuffer.second_layer, passes/second_layer_pass.h)
    // where the settings have it: the row applies to it, and the Front tab tries it as a neighbour.
    bool secondLayer = false;
    // Why these settings are unphysical by design (a seed article's artefact a preset reproduces on
    // purpose), or "" when the technique must hold the physics with them: an open plane unoccluded,
    // a corner darkening toward the wall (tests/gl/test_physics_limits.cpp, `ssaolab stress`).
    std::function<std::string(const Settings&)> unphysical;
    // What denoise.kind = auto runs for it: the denoiser that lowers (never raises) its raw AO's
    // geometry RMSE, edges and interior, on every scene of the denoiser sweep (docs/bench/report.md,
    // "Every configuration"); none where every filter raises it.
    DenoiseSettings denoiser = [] {
        DenoiseSettings d;
        d.kind = DenoiseKind::None;
        return d;
    }();
    // What the tests hold it to: the largest RMSE of its AO along a floor beside a wall against the
    // closed form of cosine-weighted visibility within R = 1 m (tests/gl/closed_form.h), at its
    // defaults (tests/gl/test_techniques.cpp) and at each quality level, its shipped presets
    // included (tests/gl/test_physics_limits.cpp). 0 = not stated, which both tests refuse.
    double cornerBound = 0, levelsCornerBound = 0;
    // `make presets` (.ci/tune-presets.sh, through `ssaolab techniques --levels`): the quality
    // levels shipped as presets ID-LEVEL, each the rows that set it, and the free rows `ssaolab tune`
    // fits at every level (its own float rows: never the radius or the power).
    struct Level {
        std::string name;
        std::vector<std::string> set; // KEY=VALUE
    };
    std::vector<Level> levels;
    std::vector<std::string> tuned;
    // Presets that follow tuned ones (`ssaolab techniques --derived`): `name` takes this technique's
    // rows from preset `from`, with `set` over them; its other keys, name and description stay.
    struct Derived {
        std::string name, from;
        std::vector<std::string> set; // KEY=VALUE of this technique's rows
    };
    std::vector<Derived> derived;
};

// makePasses for a technique that is one pass of type P.
template <class P> std::function<std::vector<std::unique_ptr<Pass>>(const Chain&)> onePass() {
    return [](const Chain& c) {
        std::vector<std::unique_ptr<Pass>> passes;
        passes.push_back(std::make_unique<P>(c));
        return passes;
    };
}

// The built-ins, then the user techniques of the last setUserTechniques. A list stays valid (and
// unchanged) after the set changes: callers may hold it across a change and read the new one next.
const std::vector<TechniqueInfo>& techniques();
// Throws ssao::Error listing the known ids; for a user technique whose file was refused, the reason.
const TechniqueInfo& findTechnique(const std::string& id);
std::vector<std::string> builtinTechniqueIds();
std::vector<std::string> userTechniqueIds(); // "user.NAME", in the order they were set

// Makes `loaded` the user techniques (ids "user.NAME"), in place of the previous set; `refused`
// holds "user.NAME" -> the one-line reason its file was not loaded (FILE:LINE: ...). Each call
// starts a new generation: techniques(), the parameter table and the renderer's passes follow it.
void setUserTechniques(const std::vector<std::shared_ptr<const UserTechnique>>& loaded,
                       const std::vector<std::pair<std::string, std::string>>& refused = {});
// techniquesGeneration() (techniques/registry.h) is 0 until the first call.
const std::vector<std::pair<std::string, std::string>>& refusedUserTechniques();

// The capabilities of `s`'s technique.
std::string unphysicalReason(const Settings& s); // "" when it has none
bool usesPyramid(const Settings& s);
// ao.deinterleave on and in effect: a technique that can, at full resolution, without the position
// pyramid, guard band, back-face layer or normals from depth (what the layers do not hold).
bool deinterleaves(const Settings& s);
// s.denoise, with auto resolved to the technique's own denoiser.
DenoiseSettings effectiveDenoise(const Settings& s);
// The share of the technique's full count that ao.adaptive takes at a pixel whose radius spans
// `radiusPx` pixels (1 without adaptive or for a technique without a count): what the shaders
// compute, from the same function (shaders/include/adaptive.h).
double adaptiveShare(const Settings& s, float radiusPx);

} // namespace ssao
