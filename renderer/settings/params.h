// The parameter table: one row per user-facing setting (key, range, unit, help, when it applies).
// It drives JSON presets, `--set key=value`, the UI, `ssaolab params` and the tests. The table
// is the core rows (gbuffer, ao, denoise, composite) plus each registered technique's rows.
// Defaults are not written here: each row reads its default from Settings{} (settings.h).
#pragma once
#include "settings/settings.h"

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <string>
#include <vector>

namespace ssao {

struct Param {
    enum class Type { Float, Int, Bool, Enum };
    // The row applies only while parameter `key` has one of `values` (e.g. denoise.sigma only
    // for denoise.kind = gaussian); otherwise the UI greys it out and it has no effect.
    struct Condition {
        std::string key;
        std::vector<std::string> values;
    };

    std::string key;   // "group.name"; the group is what a pass declares it reads
    std::string label; // UI label
    Type type = Type::Float;
    double def = 0, min = 0, max = 1; // enum/bool: index; def is filled from Settings{}
    std::string unit;
    std::string help;                 // one line: what changing it does
    std::vector<std::string> choices; // Enum only, in display order; values map by name
    std::vector<Condition> when;      // all must hold for the row to apply
    std::function<double(const Settings&)> get;
    std::function<void(Settings&, double)> set;

    std::string group() const { return key.substr(0, key.find('.')); }
    std::string name() const { return key.substr(key.find('.') + 1); }
    // Text form of a value ("0.5", "true", "hemisphere").
    std::string format(double v) const;
    // Whether `s` holds this parameter's default (compared at the field's own precision).
    bool isDefault(const Settings& s) const;
    bool applies(const Settings& s) const;
    std::string whenText() const; // "ao.radius_mode = world", "" when always
    Param& onlyWhen(const std::string& key, std::vector<std::string> values);
};

// What the settings need of the AO techniques, supplied by their registry
// (techniques/registry.cpp): the settings include no technique code.
struct TechniqueRows {
    std::string id;          // the value of ao.technique
    std::vector<Param> rows; // its rows ("id.*"); the table adds "applies while ao.technique = id"
    bool adaptive = false;   // it takes ao.adaptive (a march or tap count the rule cuts)
    bool deinterleave = false; // it takes ao.deinterleave (TechniqueInfo::deinterleave)
};
const std::vector<TechniqueRows>& registeredTechniques();

const std::vector<Param>& paramTable();
const Param* findParam(const std::string& key);

// Settings{} — every default, the one place they are defined.
Settings defaultSettings();

// Sets `key` from its text form; throws ssao::Error naming the key on unknown key, bad
// syntax, out-of-range or non-finite value.
void setParam(Settings& s, const std::string& key, const std::string& text);
// `--set key=value`.
void applyAssignment(Settings& s, const std::string& assignment);
// Every row that applies holds a finite value within its range (an integer for integer rows, a
// known choice for enums): the one place ranges are checked - the packing functions trust it.
// Throws ssao::Error naming the first key that does not. Renderer::setSettings calls it.
void validateSettings(const Settings& s);

// JSON: {"ao": {"radius": 0.5, ...}, ...}. Presets are patches over defaults; toJson writes
// every key, so write → read round-trips exactly.
nlohmann::json toJson(const Settings& s);
// toJson without the rows that do not apply (e.g. denoise.sigma under box4): what a pass's
// output depends on, so changing an inactive row re-runs nothing.
nlohmann::json toEffectiveJson(const Settings& s);
// Applies a patch; the preset metadata keys (settings/preset.h) at top level are skipped.
void applyJson(Settings& s, const nlohmann::json& patch, const std::string& origin);
Settings loadPreset(const std::string& path); // defaults + the file's patch

bool operator==(const Settings& a, const Settings& b);
inline bool operator!=(const Settings& a, const Settings& b) {
    return !(a == b);
}

} // namespace ssao
