#include "settings/applicability.h"

#include <algorithm>

namespace ssao {

namespace {

std::string joined(const std::vector<std::string>& values) {
    std::string out;
    for (const auto& v : values)
        out += (out.empty() ? "" : "|") + v;
    return out;
}

// The mode a radius row belongs to: the one value of its only condition, on ao.radius_mode.
std::string radiusModeOf(const Param& p) {
    if (p.when.size() != 1 || p.when[0].key != "ao.radius_mode" || p.when[0].values.size() != 1) return "";
    return p.when[0].values[0];
}

bool contains(const std::vector<std::string>& list, const std::string& v) {
    return std::find(list.begin(), list.end(), v) != list.end();
}

} // namespace

std::string inapplicableReason(const Param& p, const Settings& s) {
    for (const Param::Condition& c : p.when) {
        const Param* other = findParam(c.key);
        if (!other) return c.key + " (unknown)";
        const std::string v = other->format(other->get(s));
        if (!contains(c.values, v)) return c.key + " = " + joined(c.values) + " (here " + v + ")";
        if (const std::string up = inapplicableReason(*other, s); !up.empty()) return up;
    }
    return "";
}

std::vector<std::string> inapplicableKeys(const Settings& s, const std::vector<std::string>& keys) {
    std::vector<std::string> out, seen;
    for (const std::string& k : keys) {
        const Param* p = findParam(k);
        if (!p || contains(seen, k)) continue;
        seen.push_back(k);
        if (const std::string why = inapplicableReason(*p, s); !why.empty())
            out.push_back(k + " has no effect: it applies only when " + why);
    }
    return out;
}

AssignmentCheck checkAssignments(const Settings& s, const std::vector<std::string>& keys) {
    AssignmentCheck r{s, {}};
    const Param* mode = findParam("ao.radius_mode");
    if (mode && !contains(keys, mode->key)) {
        // The last radius assigned decides the mode: "--set ao.radius=2" means a world radius of 2.
        for (auto k = keys.rbegin(); k != keys.rend(); ++k) {
            const Param* p = findParam(*k);
            const std::string want = p ? radiusModeOf(*p) : "";
            if (want.empty()) continue;
            const std::string was = mode->format(mode->get(r.settings));
            if (want != was) {
                setParam(r.settings, mode->key, want);
                r.warnings.push_back(*k + ": ao.radius_mode switched from " + was + " to " + want +
                                     ", the mode in which " + *k + " applies");
            }
            break;
        }
    }
    for (const std::string& w : inapplicableKeys(r.settings, keys))
        r.warnings.push_back(w);
    return r;
}

std::vector<std::string> applyAssignments(Settings& s, const std::vector<std::string>& assignments) {
    std::vector<std::string> keys;
    for (const std::string& a : assignments) {
        applyAssignment(s, a);
        keys.push_back(a.substr(0, a.find('=')));
    }
    AssignmentCheck c = checkAssignments(s, keys);
    s = c.settings;
    for (std::string& w : c.warnings)
        w = "--set " + w;
    return c.warnings;
}

std::vector<std::string> inapplicablePresetKeys(const Settings& s, const std::set<std::string>& keys) {
    // Complete: at least half the table's rows (a hand-written patch names a few; rows added since
    // the file was written leave a complete one complete).
    const bool complete = keys.size() * 2 >= paramTable().size();
    std::vector<std::string> chosen;
    for (const std::string& k : keys) {
        const Param* p = findParam(k);
        if (p && (!complete || !p->isDefault(s))) chosen.push_back(k);
    }
    return inapplicableKeys(s, chosen);
}

} // namespace ssao
