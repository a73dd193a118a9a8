// The registry's face to the parameter table (settings/params.cpp): each technique's rows and
// capabilities, with no technique code - the one header of techniques/ the settings include
// besides the settings structs (tests/cpu/test_layering.cpp). Defined in techniques/registry.cpp.
#pragma once
#include "base/param.h"

#include <string>
#include <vector>

namespace ssao {

// What the parameter table (settings/params.cpp) needs of the AO techniques, from their registry
// (techniques/registry.cpp).
struct TechniqueRows {
    std::string id;          // the value of ao.technique
    std::vector<Param> rows; // its rows ("id.*"); the table adds "applies while ao.technique = id"
    bool adaptive = false;   // it takes ao.adaptive (a march or tap count the rule cuts)
    bool deinterleave = false; // it takes ao.deinterleave (TechniqueInfo::deinterleave)
    bool secondLayer = false;  // it reads gbuffer.second_layer (TechniqueInfo::secondLayer)
    std::string file, version; // a user technique's file and its hash; "" for a built-in
};
const std::vector<TechniqueRows>& registeredTechniques();
// Which set of techniques registeredTechniques() holds: it changes when the user techniques do
// (techniques/technique.h setUserTechniques), and the parameter table is rebuilt from it.
unsigned techniquesGeneration();
// Why the user technique `id` is not registered (its file was refused: "FILE:LINE: ..."), or "".
std::string refusedTechniqueReason(const std::string& id);

} // namespace ssao
