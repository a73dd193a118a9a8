#include "measure/sweep.h"

#include "settings/params.h"
#include "settings/preset.h"
#include "settings/preset_store.h"
#include "techniques/technique.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/paths.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>

namespace ssao {

bool isRadiusKey(const std::string& key) {
    for (const auto& k : radiusKeys())
        if (k == key) return true;
    return false;
}

namespace {

std::string valueText(const nlohmann::json& v) {
    return v.is_string() ? v.get<std::string>() : v.dump();
}

// Applies {"key": value} (values as JSON scalars) through the parameter table's parser.
void applyKeys(Settings& s, const nlohmann::json& keys, const std::string& where) {
    if (!keys.is_object()) throw Error(where + ": expected an object of \"key\": value");
    for (auto& [k, v] : keys.items()) {
        if (isRadiusKey(k))
            throw Error(where + ": '" + k +
                        "' is the radius, which the bench sets (the reference's R); use "
                        "--radius-scene");
        if (!v.is_primitive() || v.is_null())
            throw Error(where + ": '" + k + "' needs a number, bool or string");
        try {
            setParam(s, k, valueText(v));
        } catch (const Error& e) {
            throw Error(where + ": " + e.what());
        }
    }
}

// Labels name parameters by their full key ("ao.resolution=half denoise.kind=none"): a short name
// ("kind=none") did not say which group it belonged to.
std::string labelOf(const nlohmann::json& keys) {
    std::string l;
    for (auto& [k, v] : keys.items())
        l += (l.empty() ? "" : " ") + k + "=" + valueText(v);
    return l.empty() ? "defaults" : l;
}

} // namespace

namespace {
// A text field of the sweep file: absent → `fallback`, anything but a string → an error naming it
// (nlohmann's value() would throw its own type_error, naming neither the file nor the key).
std::string textField(const nlohmann::json& j, const char* key, const std::string& fallback, const std::string& where) {
    if (!j.contains(key)) return fallback;
    if (!j[key].is_string()) throw Error(where + ": '" + key + "' must be a string");
    return j[key].get<std::string>();
}
} // namespace

namespace {

// Builds the configurations of one sweep file: the baseline, each group's combinations, every
// technique at its defaults; a configuration equal to an earlier one is kept once.
class SweepBuilder {
  public:
    SweepBuilder(const std::string& origin, const std::string& presetDir, size_t maxConfigs)
        : origin_(origin), store_(PresetStore::standard(presetDir)), maxConfigs_(maxConfigs) {}

    void base(const nlohmann::json& b) {
        if (!b.is_object()) throw Error(origin_ + ": base: expected {\"preset\": ..., \"set\": {...}}");
        const std::string preset = textField(b, "preset", "", origin_ + ": base");
        if (!preset.empty()) {
            base_ = open(preset);
            resetRadius(base_);
        }
        if (b.contains("set")) {
            applyKeys(base_, b["set"], origin_ + ": base.set");
            baseKeys_ = b["set"];
        }
    }

    // The baseline first, so every later row can be read against it: any preset (learnopengl, the
    // seed article's, by default).
    void baseline(const std::string& preset) {
        BenchConfig c;
        c.label = preset + " (baseline)";
        c.group = "baseline";
        c.settings = open(preset);
        resetRadius(c.settings); // the bench's radius, like every configuration
        c.keys = {{"preset", preset}};
        c.baseline = true;
        add(c);
    }

    void group(const nlohmann::json& g, size_t gi) {
        if (!g.is_object()) throw Error(origin_ + ": group " + std::to_string(gi + 1) + " must be an object");
        const std::string gname = textField(g, "name", "group " + std::to_string(gi + 1), origin_);
        const std::string where = origin_ + ": group '" + gname + "'";
        for (auto& [k, v] : g.items())
            if (k != "name" && k != "preset" && k != "set" && k != "vary")
                throw Error(where + ": unknown key '" + k + "' (name, preset, set, vary)");
        Settings gs = base_;
        nlohmann::json gkeys = baseKeys_;
        if (g.contains("preset")) { // the group starts from a preset instead of the base
            if (!g["preset"].is_string()) throw Error(where + ".preset: expected a preset name");
            gs = open(g["preset"].get<std::string>());
            resetRadius(gs);
            gkeys = {{"preset", g["preset"]}};
        }
        if (g.contains("set")) {
            applyKeys(gs, g["set"], where + ".set");
            gkeys.update(g["set"]);
        }
        combinations(gname, where, gs, gkeys, axes(g, where));
    }

    // Every technique at its defaults: one added later is never missing from the front.
    void techniqueDefaults() {
        for (const auto& t : techniques()) {
            BenchConfig c;
            c.group = "technique defaults";
            c.settings = base_;
            setParam(c.settings, "ao.technique", t.id);
            c.keys = {{"ao.technique", t.id}};
            c.label = t.id + " defaults";
            add(c);
        }
    }

    std::vector<BenchConfig> configs;
    std::vector<std::string> warnings;

  private:
    // A preset's settings; its warnings kept for the command to print.
    Settings open(const std::string& preset) {
        Preset p = store_.open(preset);
        for (const std::string& w : p.warnings)
            if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
        return p.settings;
    }

    using Axes = std::vector<std::pair<std::string, nlohmann::json>>;

    Axes axes(const nlohmann::json& g, const std::string& where) const {
        Axes out;
        if (!g.contains("vary")) return out;
        if (!g["vary"].is_object()) throw Error(where + ".vary: expected {\"key\": [values]}");
        for (auto& [k, v] : g["vary"].items()) {
            if (v == "all") { // every choice of a choice row: ao.technique needs no list to keep
                const Param* p = findParam(k);
                if (!p || p->type != Param::Type::Enum)
                    throw Error(where + ".vary: '" + k + "': \"all\" needs a parameter with choices");
                out.emplace_back(k, nlohmann::json(p->choices));
                continue;
            }
            if (!v.is_array() || v.empty())
                throw Error(where + ".vary: '" + k + "' needs a non-empty list, or \"all\" for every choice");
            out.emplace_back(k, v);
        }
        return out;
    }

    // Odometer over the axes' lists. The combinations are counted before any is made: lists of
    // equal values multiply into duplicates that the distinct-configuration cap never sees.
    void combinations(const std::string& gname, const std::string& where, const Settings& gs,
                      const nlohmann::json& gkeys, const Axes& axes) {
        double total = 1;
        for (const auto& a : axes)
            total *= double(a.second.size());
        if (total > double(maxConfigs_))
            throw Error(where + ".vary: " + std::to_string((unsigned long long)std::min(total, 1e18)) +
                        " combinations, more than " + std::to_string(maxConfigs_));
        std::vector<size_t> idx(axes.size(), 0);
        for (;;) {
            BenchConfig c;
            c.group = gname;
            c.settings = gs;
            c.keys = gkeys;
            for (size_t a = 0; a < axes.size(); ++a) {
                nlohmann::json one = {{axes[a].first, axes[a].second[idx[a]]}};
                applyKeys(c.settings, one, where + ".vary");
                c.keys.update(one);
            }
            c.label = labelOf(c.keys);
            add(c);
            size_t a = 0;
            while (a < axes.size() && ++idx[a] == axes[a].second.size())
                idx[a++] = 0;
            if (a == axes.size()) break;
        }
    }

    // Two configurations that render alike are one: `vbao defaults` is `ao.technique=vbao
    // denoise.kind=none` (auto resolves to the technique's own denoiser).
    static std::string identity(const Settings& s) {
        Settings e = s;
        e.denoise = effectiveDenoise(s);
        return toEffectiveJson(e).dump();
    }

    void add(BenchConfig c) {
        const auto [at, fresh] = seen_.emplace(identity(c.settings), configs.size());
        if (!fresh) {
            std::vector<std::string>& names = configs[at->second].aliases;
            if (c.label != configs[at->second].label && names.size() < kMaxAliases &&
                std::find(names.begin(), names.end(), c.label) == names.end())
                names.push_back(c.label);
            return;
        }
        if (configs.size() >= maxConfigs_)
            throw Error(origin_ + ": more than " + std::to_string(maxConfigs_) + " configurations");
        configs.push_back(std::move(c));
    }

    std::string origin_;
    PresetStore store_;
    size_t maxConfigs_;
    Settings base_ = defaultSettings();
    nlohmann::json baseKeys_ = nlohmann::json::object();
    std::map<std::string, size_t> seen_; // identity -> index in configs
};

} // namespace

Sweep parseSweep(const nlohmann::json& j, const std::string& origin, const std::string& presetDir,
                 size_t maxConfigs, const std::string& baseline) {
    if (!j.is_object()) throw Error(origin + ": a sweep is a JSON object");
    for (auto& [k, v] : j.items())
        if (k != "name" && k != "description" && k != "base" && k != "groups")
            throw Error(origin + ": unknown key '" + k + "' (name, description, base, groups)");
    Sweep sw;
    sw.name = textField(j, "name", "sweep", origin);
    sw.description = textField(j, "description", "", origin);
    SweepBuilder b(origin, presetDir, maxConfigs);
    if (j.contains("base")) b.base(j["base"]);
    b.baseline(baseline);
    if (j.contains("groups")) {
        const auto& groups = j["groups"];
        if (!groups.is_array()) throw Error(origin + ": groups: expected an array");
        for (size_t gi = 0; gi < groups.size(); ++gi)
            b.group(groups[gi], gi);
    }
    b.techniqueDefaults();
    sw.configs = std::move(b.configs);
    sw.warnings = std::move(b.warnings);
    return sw;
}

Sweep loadSweep(const std::string& nameOrPath, const std::string& presetDir, const std::string& baseline) {
    const std::string path = nameOrPath == "builtin" ? assetRoot() + "/bench/sweep_builtin.json" : nameOrPath;
    // A regular file only (a FIFO would block for ever), nesting bounded before it is parsed or
    // copied (200 000 nested lists once crashed the copy before any validation).
    return parseSweep(readJsonFile(path, "sweep"), "sweep " + path, presetDir, 2000, baseline);
}

} // namespace ssao
