#include "engines/engine_settings_file.h"

#include "engines/engine_snippet.h"
#include "util/error.h"
#include "util/json_file.h"

#include <cmath>
#include <optional>

namespace ssao {

namespace {

// The fitted factor of a search entry ({"x_R": 1.5}); none when absent or not a finite number
// (positive unless `signedOk`: a bias per R may be 0).
std::optional<double> factorOf(const nlohmann::json& search, const std::string& name, const char* key, bool signedOk) {
    if (!search.is_object() || !search.contains(name) || !search[name].is_object()) return std::nullopt;
    const nlohmann::json& s = search[name];
    if (!s.contains(key) || !s[key].is_number()) return std::nullopt;
    const double x = s[key].get<double>();
    return std::isfinite(x) && (signedOk || x > 0) ? std::optional<double>(x) : std::nullopt;
}

double valueOf(const nlohmann::json& v, const EngineParam& p, const std::string& where) {
    if (p.type == EngineParam::Type::Boolean) {
        if (!v.is_boolean()) throw Error(where + " must be true or false");
        return v.get<bool>() ? 1.0 : 0.0;
    }
    if (!v.is_number() || !std::isfinite(v.get<double>())) throw Error(where + " must be a finite number");
    return v.get<double>();
}

} // namespace

TunedEngine readTunedEngine(const std::string& file) {
    const nlohmann::json j = readJsonFile(file, "tuned engine settings");
    const std::string what = "tuned engine settings " + file;
    if (!j.is_object() || !j.contains("engine") || !j["engine"].is_string() || !j.contains("settings") || !j["settings"].is_object())
        throw Error(what + ": not a `ssaolab tune --engine --out` file (no \"engine\" and \"settings\")");
    TunedEngine t{findEngine(j["engine"].get<std::string>()), file, {}, {}, {}};
    const std::string version = j.contains("version") && j["version"].is_string() ? j["version"].get<std::string>() : "";
    if (version != t.table.version)
        throw Error(what + ": tuned " + t.table.package + " " + (version.empty() ? "(no version)" : version) +
                    "; the installed table is for " + t.table.version + " (tune it again)");
    const nlohmann::json search = j.contains("search") ? j["search"] : nlohmann::json();
    auto add = [&](const nlohmann::json& values, const std::string& field) {
        for (const auto& [name, v] : values.items()) {
            const EngineParam* p = t.table.find(name);
            if (!p || p->role == EngineParam::Role::Fixed)
                throw Error(what + ": " + field + "." + name + " is not a shape or cost parameter of " + t.table.engine);
            const double value = valueOf(v, *p, what + ": " + field + "." + name);
            if (const auto x = p->relative ? factorOf(search, name, "x_make_peers_value", false) : std::nullopt)
                t.scale[name] = *x;
            else if (const auto r = p->perRadius ? factorOf(search, name, p->perRadius == 1 ? "x_R" : "x_1_over_R", true) : std::nullopt)
                t.perRadius[name] = {*r, p->perRadius};
            else
                t.values[name] = value;
        }
    };
    add(j["settings"], "settings");
    if (j.contains("cost_settings") && j["cost_settings"].is_object() && j["cost_settings"].contains("values") &&
        j["cost_settings"]["values"].is_object())
        add(j["cost_settings"]["values"], "cost_settings.values");
    return t;
}

std::map<std::string, double> jobValues(const EngineTable& table,
                                        const std::map<std::string, std::pair<double, int>>& perRadius,
                                        const std::map<std::string, double>& values, double radius) {
    std::map<std::string, double> out;
    auto put = [&](const std::string& name, double x) {
        const EngineParam* p = table.find(name);
        if (!p) throw Error(table.engine + " has no parameter " + name);
        out[name] = exportedValue(p->type == EngineParam::Type::Integer ? std::round(x) : x);
    };
    for (const auto& [name, f] : perRadius)
        put(name, f.first * std::pow(radius, f.second));
    for (const auto& [name, v] : values)
        put(name, v);
    return out;
}

} // namespace ssao
