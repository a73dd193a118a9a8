// The parameter table: one row per user-facing setting (key, default, range, unit, help).
// It drives JSON presets, `--set key=value`, the UI and the tests; adding a parameter is one
// row here plus its use in a pass.
#pragma once
#include "settings/settings.h"

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <string>
#include <vector>

namespace ssao {

struct Param {
    enum class Type { Float, Int, Bool, Enum };
    std::string key;   // "ssao.radius": group.name; the group is the pass that reads it
    std::string label; // UI label
    Type type;
    double def, min, max; // enum/bool: index
    std::string unit;
    std::string help;                 // one line: what changing it does
    std::vector<std::string> choices; // Enum only
    std::function<double(const Settings&)> get;
    std::function<void(Settings&, double)> set;

    std::string group() const { return key.substr(0, key.find('.')); }
    std::string name() const { return key.substr(key.find('.') + 1); }
    // Text form of a value ("0.5", "true", "hemisphere").
    std::string format(double v) const;
    // Whether `s` holds this parameter's default (compared at the field's own precision).
    bool isDefault(const Settings& s) const;
};

const std::vector<Param>& paramTable();
const Param* findParam(const std::string& key);

// Settings with every table default applied.
Settings defaultSettings();

// Sets `key` from its text form; throws ssao::Error naming the key on unknown key, bad
// syntax, out-of-range or non-finite value.
void setParam(Settings& s, const std::string& key, const std::string& text);
// `--set key=value`.
void applyAssignment(Settings& s, const std::string& assignment);

// JSON: {"ssao": {"radius": 0.5, ...}, ...}. Presets are patches over defaults; toJson
// writes every key, so write → read round-trips exactly.
nlohmann::json toJson(const Settings& s);
// Applies a patch; "name", "description" and "camera" at top level are preset metadata (see
// settings/preset.h) and ignored here.
void applyJson(Settings& s, const nlohmann::json& patch, const std::string& origin);
Settings loadPreset(const std::string& path); // defaults + the file's patch

bool operator==(const Settings& a, const Settings& b);
inline bool operator!=(const Settings& a, const Settings& b) {
    return !(a == b);
}

} // namespace ssao
