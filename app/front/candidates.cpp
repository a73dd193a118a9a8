#include "front/candidates.h"

#include "measure/bench_run.h"
#include "settings/params.h"
#include "settings/preset.h"
#include "techniques/technique.h"
#include "util/error.h"

#include <set>

namespace ssao {

Settings withRadiusOf(Settings chosen, const Settings& current) {
    for (const auto& key : radiusKeys())
        if (const Param* p = findParam(key)) p->set(chosen, p->get(current));
    return chosen;
}

std::vector<Candidate> frontCandidates(const Settings& current, const PresetStore& store, float radius,
                                       const std::string& baseline) {
    std::vector<Candidate> out;
    std::set<std::string> seen;
    auto add = [&](const std::string& label, const std::string& origin, const Settings& s, bool isBase, bool isCur) {
        Settings r = withRadius(s, radius);
        if (!seen.insert(toEffectiveJson(r).dump()).second) {
            for (auto& c : out) // the current settings may equal a preset: flag it, keep the preset's name
                if (isCur && toEffectiveJson(c.settings) == toEffectiveJson(r)) c.current = true;
            return;
        }
        out.push_back({label, origin, r, isBase, isCur});
    };
    const PresetEntry* base = store.find(baseline);
    if (!base || !base->builtin) throw Error("front panel: no shipped preset '" + baseline + "' to compare with");
    add(baseline, "preset", store.load(baseline).settings, true, false);
    add("current", "current", current, false, true);
    // The current settings' neighbours: one row changed at a time.
    auto neighbours = [&](const std::string& key) {
        const Param* p = findParam(key);
        if (!p || p->type != Param::Type::Enum || !p->applies(current)) return;
        for (size_t i = 0; i < p->choices.size(); ++i) {
            if (p->choices[i] == "custom") continue; // the ladder's named rungs only
            Settings s = current;
            p->set(s, double(i));
            add("current + " + key + "=" + p->choices[i], "neighbour", s, false, false);
        }
    };
    neighbours("ao.resolution");
    neighbours("denoise.kind");
    neighbours(current.ao.technique + ".quality");
    // The second depth layer, for a technique that reads it.
    if (const Param* layer = findParam("gbuffer.second_layer"); layer && layer->applies(current) && !current.gbuffer.secondLayer) {
        Settings s = current;
        s.gbuffer.secondLayer = true;
        add("current + gbuffer.second_layer=true", "neighbour", s, false, false);
    }
    for (const auto& e : store.entries())
        if (e.builtin) add(e.name, "preset", store.load(e.name).settings, false, false);
    // Each user technique at its header's defaults, on the current settings' other choices.
    for (const std::string& id : userTechniqueIds()) {
        Settings s = current;
        setParam(s, "ao.technique", id);
        for (const Param& p : paramTable())
            if (p.group() == id) p.set(s, p.def);
        add(id, "user technique", s, false, false);
    }
    return out;
}

} // namespace ssao
