// An AO technique is a module: a folder under renderer/techniques/ with its settings struct,
// its parameter rows, a pure constants-packing function, its pass (the frame-graph wiring) and
// its shader under shaders/techniques/. The registry (registry.cpp) lists the modules.
#pragma once
#include "settings/params.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ssao {

class Pass;
struct Branch;

struct TechniqueInfo {
    std::string id;      // value of ao.technique, and the group of the technique's rows
    std::string label;   // for the UI
    std::string summary; // one line: what it estimates and where it comes from
    std::function<std::vector<Param>()> params; // rows "id.*"
    // Its passes for one chain: together they read gbuffer.* and write the chain's ao.raw
    // (a helper image only that pass reads, like the position pyramid, stays inside it; one that
    // several passes share would be a pass of its own, wired by declarations).
    std::function<std::vector<std::unique_ptr<Pass>>(const Branch&)> makePasses;
    // Why these settings are unphysical by design (a seed article's artefact a preset reproduces on
    // purpose), or "" when the technique must hold the physics with them: an open plane unoccluded,
    // a corner darkening toward the wall (tests/gl/test_physics_limits.cpp, `ssaolab stress`).
    std::function<std::string(const Settings&)> unphysical;
};

// TechniqueInfo::unphysical of `s`'s technique ("" when it has none).
std::string unphysicalReason(const Settings& s);

// makePasses for a technique that is one pass of type P (every technique so far).
template <class P> std::function<std::vector<std::unique_ptr<Pass>>(const Branch&)> onePass() {
    return [](const Branch& b) {
        std::vector<std::unique_ptr<Pass>> passes;
        passes.push_back(std::make_unique<P>(b));
        return passes;
    };
}

const std::vector<TechniqueInfo>& techniques();
// Throws ssao::Error listing the known ids.
const TechniqueInfo& findTechnique(const std::string& id);

} // namespace ssao
