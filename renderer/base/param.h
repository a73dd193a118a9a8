// A row of the parameter table (settings/params.h): one user-facing setting, how to read and write
// it in Settings, when it applies. The row type sits below the techniques so each builds its own
// rows (base/param_rows.h); the table that joins them is settings/params.cpp.
#pragma once
#include "base/shared_settings.h"

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

    std::string key;   // "group.name"; a user technique's "user.NAME.name" has the group "user.NAME"
    std::string label; // UI label
    Type type = Type::Float;
    double def = 0, min = 0, max = 1; // enum/bool: index; def is filled from Settings{}
    std::string unit;
    std::string help;                 // one line: what changing it does
    std::vector<std::string> choices; // Enum only, in display order; values map by name
    std::vector<Condition> when;      // all must hold for the row to apply
    std::function<double(const Settings&)> get;
    std::function<void(Settings&, double)> set;

    std::string group() const { return key.substr(0, key.rfind('.')); }
    std::string name() const { return key.substr(key.rfind('.') + 1); }
    // Text form of a value ("0.5", "true", "hemisphere").
    std::string format(double v) const;
    // Whether `s` holds this parameter's default (compared at the field's own precision).
    bool isDefault(const Settings& s) const;
    bool applies(const Settings& s) const;
    std::string whenText() const; // "ao.radius_mode = world", "" when always
    Param& onlyWhen(const std::string& key, std::vector<std::string> values);
};

// What the parameter table needs of the AO techniques, supplied by their registry
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
