// A technique that is one constant block and one shader (techniques/ao_pass.h OneBlockPass): its
// registry entry from its Module (ao_pass.h lists what a Module gives).
#pragma once
#include "techniques/ao_pass.h"
#include "techniques/technique.h"

namespace ssao {

// The part of a Module every one-block technique shares: its settings block (a TechniqueSettings
// member with `noise` and `pyramid`) and its one pure pack function; the technique adds only its
// shader and its pyramid's MIP offset.
template <class Block, class Consts, Block TechniqueSettings::*Member, Consts (*Pack)(const Block&, const gpu::AoCommon&)>
struct BlockModule {
    using Constants = Consts;
    static AoNoise noise(const Settings& s) { return (s.*Member).noise; }
    static bool pyramid(const Settings& s) { return (s.*Member).pyramid; }
    static Constants pack(const Settings& s, const gpu::AoCommon& c) { return Pack(s.*Member, c); }
};

template <class Module>
TechniqueInfo oneBlockTechnique(std::string id, std::string label, std::string summary,
                                std::function<std::vector<Param>()> params) {
    TechniqueInfo t;
    t.id = std::move(id), t.label = std::move(label), t.summary = std::move(summary);
    t.params = std::move(params);
    t.makePasses = onePass<OneBlockPass<Module>>();
    t.pyramid = [](const Settings& s) { return Module::pyramid(s); };
    t.staticNoise = [](const Settings& s) { return Module::noise(s) == AoNoise::None; };
    return t;
}

} // namespace ssao
