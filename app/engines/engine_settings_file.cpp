#include "engines/engine_settings_file.h"

#include "engines/engine_snippet.h"
#include "util/error.h"
#include "util/json_file.h"

#include <cmath>
#include <cstdio>
#include <optional>

namespace ssao {

namespace {

// The most a fitted factor may be: a tune starts inside the row's search range and widens a wall
// only as far as the table's range holds on its views (commands/tune/box_search.h).
constexpr double kMaxFactor = 1e6;

// The fitted factor of a search entry ({"x_R": 1.5}): none when absent; else a finite number in
// [0, kMaxFactor] (above 0 where the search is in log steps).
std::optional<double> factorOf(const nlohmann::json& search, const EngineParam& p, const char* key, const std::string& where) {
    if (!search.is_object() || !search.contains(p.name) || !search[p.name].is_object() || !search[p.name].contains(key))
        return std::nullopt;
    const nlohmann::json& x = search[p.name][key];
    char range[96];
    std::snprintf(range, sizeof range, "%s0, %.9g]", p.log ? "(" : "[", kMaxFactor);
    const std::string field = where + ": search." + p.name + "." + key;
    if (!x.is_number() || !std::isfinite(x.get<double>())) throw Error(field + " must be a finite number in " + range);
    const double d = x.get<double>();
    if (d < 0 || (p.log && d <= 0) || d > kMaxFactor) {
        char v[48];
        std::snprintf(v, sizeof v, "%.9g", d);
        throw Error(field + " = " + v + " is outside what a tune can fit, " + range);
    }
    return d;
}

} // namespace

TunedEngine parseTunedEngine(const nlohmann::json& j, const std::string& file) {
    const std::string what = "tuned engine settings " + file;
    if (!j.is_object() || !j.contains("engine") || !j["engine"].is_string() || !j.contains("settings") || !j["settings"].is_object())
        throw Error(what + ": not a `ssaolab tune --engine --out` file (no \"engine\" and \"settings\")");
    TunedEngine t{findEngine(j["engine"].get<std::string>()), file, {}, {}, {}};
    const std::string version = j.contains("version") && j["version"].is_string() ? j["version"].get<std::string>() : "";
    if (version != t.table.version)
        throw Error(what + ": tuned " + t.table.package + " " + (version.empty() ? "(no version)" : version) +
                    "; the installed table is for " + t.table.version + " (tune it again)");
    const nlohmann::json search = j.contains("search") ? j["search"] : nlohmann::json();
    if (!search.is_null() && !search.is_object()) throw Error(what + ": \"search\" must be an object");
    auto add = [&](const nlohmann::json& values, const std::string& field, EngineParam::Role role) {
        for (const auto& [name, v] : values.items()) {
            const EngineParam* p = t.table.find(name);
            if (!p || p->role != role)
                throw Error(what + ": " + field + "." + name + " is not a " + (role == EngineParam::Role::Cost ? "cost" : "shape or cost") +
                            " parameter of " + t.table.engine);
            const std::string where = what + ": " + field + "." + name;
            // A fit relative to the view or per R is its factor (checked as a tune can fit it);
            // the value beside it is the first training view's, which the engine's GUI range need not
            // hold (a length in a small scene's units): checked as a value of its type only.
            const auto x = p->relative ? factorOf(search, *p, "x_make_peers_value", what) : std::nullopt;
            const auto r = p->perRadius ? factorOf(search, *p, p->perRadius == 1 ? "x_R" : "x_1_over_R", what) : std::nullopt;
            if (x || r) {
                EngineParam typeOnly = *p;
                typeOnly.range.reset();
                checkedEngineValue(typeOnly, v, where);
            }
            if (x)
                t.scale[name] = *x;
            else if (r)
                t.perRadius[name] = {*r, p->perRadius};
            else
                t.values[name] = checkedEngineValue(*p, v, where);
        }
    };
    for (const auto& [name, v] : j["settings"].items()) {
        const EngineParam* p = t.table.find(name);
        add(nlohmann::json{{name, v}}, "settings", p && p->role == EngineParam::Role::Cost ? EngineParam::Role::Cost : EngineParam::Role::Shape);
    }
    if (j.contains("cost_settings")) {
        const nlohmann::json& c = j["cost_settings"];
        if (!c.is_object() || (c.contains("values") && !c["values"].is_object()))
            throw Error(what + ": \"cost_settings\" must be an object whose \"values\" is an object");
        if (c.contains("values")) add(c["values"], "cost_settings.values", EngineParam::Role::Cost);
    }
    return t;
}

TunedEngine readTunedEngine(const std::string& file) {
    return parseTunedEngine(readJsonFile(file, "tuned engine settings"), file);
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
