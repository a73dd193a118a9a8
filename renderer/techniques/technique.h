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
    // (prefilters, mip chains or deinterleaving are passes of their own, wired by declarations).
    std::function<std::vector<std::unique_ptr<Pass>>(const Branch&)> makePasses;
};

const std::vector<TechniqueInfo>& techniques();
// Throws ssao::Error listing the known ids.
const TechniqueInfo& findTechnique(const std::string& id);

} // namespace ssao
