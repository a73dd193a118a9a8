// The list of AO techniques. Adding one: its folder, one member in technique_settings.h and
// one entry here.
#include "techniques/gtao/technique.h"
#include "techniques/hbao/technique.h"
#include "techniques/kernel/technique.h"
#include "techniques/sao/technique.h"
#include "techniques/technique.h"
#include "techniques/vbao/technique.h"
#include "util/error.h"

namespace ssao {

const std::vector<TechniqueInfo>& techniques() {
    static const std::vector<TechniqueInfo> list = {kernelTechnique(), saoTechnique(), hbaoTechnique(), gtaoTechnique(),
                                                   vbaoTechnique()};
    return list;
}

const TechniqueInfo& findTechnique(const std::string& id) {
    std::string known;
    for (const auto& t : techniques()) {
        if (t.id == id) return t;
        known += (known.empty() ? "" : "|") + t.id;
    }
    throw Error("unknown AO technique '" + id + "' (known: " + known + ")");
}

std::string unphysicalReason(const Settings& s) {
    const TechniqueInfo& t = findTechnique(s.ao.technique);
    return t.unphysical ? t.unphysical(s) : std::string();
}

} // namespace ssao
