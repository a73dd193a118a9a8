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

} // namespace ssao
