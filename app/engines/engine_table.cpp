#include "engines/engine_table.h"

#include "util/closest_name.h"
#include "util/error.h"
#include "util/files.h"
#include "util/json_file.h"
#include "util/paths.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

namespace fs = std::filesystem;

namespace ssao {

namespace {

constexpr size_t kMaxTableBytes = size_t(1) << 20;
constexpr size_t kMaxTables = 64;

std::string textField(const nlohmann::json& j, const char* key, const std::string& where) {
    if (!j.contains(key) || !j[key].is_string() || j[key].get<std::string>().empty())
        throw Error(where + ": \"" + key + "\" must be a non-empty string");
    return j[key].get<std::string>();
}

// A name the snippet writes as code (the pass's variable, a property path, a setter and its key):
// JavaScript identifiers joined by '.', nothing else.
std::string codeName(const nlohmann::json& j, const char* key, const std::string& where) {
    const std::string s = textField(j, key, where);
    bool start = true;
    for (char c : s) {
        const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == '$';
        if (c == '.' && !start) { start = true; continue; }
        if (!letter && (start || c < '0' || c > '9')) throw Error(where + ": \"" + key + "\" must be JavaScript identifiers joined by '.'");
        start = false;
    }
    if (start) throw Error(where + ": \"" + key + "\" must be JavaScript identifiers joined by '.'");
    return s;
}

// "call_always": { "setter": { "key": true | number } }: what the setter's call always carries.
// Keys are identifiers and values JSON booleans or finite numbers, so the snippet writes them as code.
std::vector<std::pair<std::string, std::vector<std::pair<std::string, std::string>>>> readCallAlways(const nlohmann::json& s,
                                                                                                  const std::string& where) {
    std::vector<std::pair<std::string, std::vector<std::pair<std::string, std::string>>>> out;
    if (!s.contains("call_always")) return out;
    if (!s["call_always"].is_object()) throw Error(where + ": \"call_always\" must be an object");
    for (const auto& [call, args] : s["call_always"].items()) {
        codeName(nlohmann::json{{"call", call}}, "call", where + " call_always");
        if (!args.is_object()) throw Error(where + ": call_always " + call + " must be an object");
        std::vector<std::pair<std::string, std::string>> kv;
        for (const auto& [key, v] : args.items()) {
            codeName(nlohmann::json{{"key", key}}, "key", where + " call_always " + call);
            if (v.is_boolean()) kv.emplace_back(key, v.get<bool>() ? "true" : "false");
            else if (v.is_number() && std::isfinite(v.get<double>())) kv.emplace_back(key, v.dump());
            else throw Error(where + ": call_always " + call + "." + key + " must be a boolean or a finite number");
        }
        out.emplace_back(call, std::move(kv));
    }
    return out;
}

double numberOf(const nlohmann::json& v, EngineParam::Type type, const std::string& where) {
    if (type == EngineParam::Type::Boolean) {
        if (!v.is_boolean()) throw Error(where + " must be true or false");
        return v.get<bool>() ? 1.0 : 0.0;
    }
    if (!v.is_number() || !std::isfinite(v.get<double>())) throw Error(where + " must be a finite number");
    const double d = v.get<double>();
    if (type == EngineParam::Type::Integer && d != std::floor(d)) throw Error(where + " must be an integer");
    return d;
}

EngineParam::Type typeOf(const std::string& s, const std::string& where) {
    if (s == "number") return EngineParam::Type::Number;
    if (s == "integer") return EngineParam::Type::Integer;
    if (s == "boolean") return EngineParam::Type::Boolean;
    throw Error(where + ": type '" + s + "' is not number, integer or boolean");
}

EngineParam::Role roleOf(const std::string& s, const std::string& where) {
    if (s == "shape") return EngineParam::Role::Shape;
    if (s == "cost") return EngineParam::Role::Cost;
    if (s == "fixed") return EngineParam::Role::Fixed;
    throw Error(where + ": role '" + s + "' is not shape, cost or fixed");
}

void readWrite(EngineParam& p, const nlohmann::json& row, const std::string& where) {
    const nlohmann::json& w = row.contains("write") ? row["write"] : nlohmann::json();
    if (!w.is_object()) throw Error(where + ": \"write\" must be an object (path, call and key, or constructor_arg)");
    if (w.contains("path")) p.writePath = codeName(w, "path", where + " write");
    if (w.contains("call")) p.writeCall = codeName(w, "call", where + " write"), p.writeKey = codeName(w, "key", where + " write");
    if (w.contains("constructor_arg")) {
        if (!w["constructor_arg"].is_number_unsigned()) throw Error(where + ": constructor_arg must be an index");
        p.constructorArg = w["constructor_arg"].get<int>();
    }
    if (int(!p.writePath.empty()) + int(!p.writeCall.empty()) + int(p.constructorArg >= 0) != 1)
        throw Error(where + ": \"write\" needs exactly one of path, call (with key) or constructor_arg");
}

void readSearch(EngineParam& p, const nlohmann::json& row, const std::string& where) {
    if (!row.contains("search")) {
        if (p.role == EngineParam::Role::Shape) throw Error(where + ": a shape parameter needs a \"search\" range");
        return;
    }
    const nlohmann::json& s = row["search"];
    if (p.role != EngineParam::Role::Shape) throw Error(where + ": only shape parameters are searched");
    if (p.type == EngineParam::Type::Boolean) throw Error(where + ": a boolean is not searched");
    if (!s.is_object() || !s.contains("range") || !s["range"].is_array() || s["range"].size() != 2)
        throw Error(where + ": \"search\" needs \"range\": [lo, hi]");
    p.searchLo = numberOf(s["range"][0], EngineParam::Type::Number, where + " search range");
    p.searchHi = numberOf(s["range"][1], EngineParam::Type::Number, where + " search range");
    p.relative = s.value("relative", false);
    if (s.contains("per_radius")) {
        if (!s["per_radius"].is_number_integer() || std::abs(s["per_radius"].get<int>()) != 1)
            throw Error(where + ": \"per_radius\" is 1 (a length: x R) or -1 (x 1 / R)");
        p.perRadius = s["per_radius"].get<int>();
    }
    if (p.relative && p.perRadius) throw Error(where + ": a search is relative to the make-peers value or per R, not both");
    p.log = s.value("log", false);
    if (!(p.searchLo < p.searchHi) || (p.log && p.searchLo <= 0))
        throw Error(where + ": the search range must be lo < hi (lo > 0 on a log grid)");
}

EngineParam readParam(const nlohmann::json& row, const std::string& file) {
    if (!row.is_object()) throw Error(file + ": every parameter must be an object");
    EngineParam p;
    p.name = textField(row, "name", file + " parameter");
    const std::string where = file + " parameter " + p.name;
    p.type = typeOf(textField(row, "type", where), where);
    p.role = roleOf(textField(row, "role", where), where);
    p.unit = textField(row, "unit", where);
    textField(row, "read", where);
    if (!row.contains("default")) throw Error(where + ": no \"default\"");
    p.defaultValue = numberOf(row["default"], p.type, where + " default");
    if (p.type != EngineParam::Type::Boolean) {
        if (!row.contains("range")) throw Error(where + ": no \"range\" (null when the engine documents none)");
        const nlohmann::json& r = row["range"];
        if (r.is_null()) {
            if (p.role != EngineParam::Role::Fixed) throw Error(where + ": a " + textField(row, "role", where) + " parameter needs a range");
        } else {
            if (!r.is_array() || r.size() != 2) throw Error(where + ": \"range\" must be [lo, hi] or null");
            p.range = std::make_pair(numberOf(r[0], p.type, where + " range"), numberOf(r[1], p.type, where + " range"));
            if (!(p.range->first <= p.range->second)) throw Error(where + ": the range's lo is above its hi");
            if (p.defaultValue < p.range->first || p.defaultValue > p.range->second)
                throw Error(where + ": the default lies outside its range");
        }
        textField(row, "range_source", where);
    }
    readWrite(p, row, where);
    readSearch(p, row, where);
    if (row.contains("scales_with_budget")) {
        if (!row["scales_with_budget"].is_boolean()) throw Error(where + ": \"scales_with_budget\" must be true or false");
        p.scalesWithBudget = row["scales_with_budget"].get<bool>();
        if (p.scalesWithBudget && (p.role != EngineParam::Role::Cost || p.type == EngineParam::Type::Boolean || p.defaultValue <= 0))
            throw Error(where + ": only a positive numeric cost parameter scales with the budget");
    }
    p.row = row;
    return p;
}

} // namespace

const EngineParam* EngineTable::find(const std::string& name) const {
    for (const EngineParam& p : params)
        if (p.name == name) return &p;
    return nullptr;
}

std::string enginePeersDir() {
    return dataRoot() + "/tools/peers"; // the source tree and an installation alike
}

std::vector<std::string> engineNames() {
    std::vector<std::string> names;
    for (const std::string& f : listFilesInside(enginePeersDir(), "engines", "engine tables", kMaxTables))
        if (fs::path(f).extension() == ".json" && fs::path(f).parent_path() == "engines") names.push_back(fs::path(f).stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

EngineTable loadEngineTable(const std::string& path) {
    const nlohmann::json j = readJsonFile(path, "engine table");
    if (!j.is_object()) throw Error("engine table " + path + " must be a JSON object");
    EngineTable t;
    t.file = path;
    t.engine = textField(j, "engine", path);
    t.title = textField(j, "title", path);
    t.package = textField(j, "package", path);
    t.version = textField(j, "version", path);
    t.peer = textField(j, "peer", path);
    t.page = j.contains("page") ? textField(j, "page", path) : "peers.html";
    if (t.page != "peers.html" && t.page != "babylon.html" && t.page != "playcanvas.html" && t.page != "filament.html")
        throw Error(path + ": \"page\" is '" + t.page +
                    "', not one of the harness's pages (peers.html, babylon.html, playcanvas.html, filament.html)");
    textField(j, "docs", path);
    if (!j.contains("snippet") || !j["snippet"].is_object()) throw Error(path + ": no \"snippet\" object");
    t.variable = codeName(j["snippet"], "variable", path + " snippet");
    if (j["snippet"].contains("setup") && j["snippet"]["setup"].is_array())
        for (const auto& line : j["snippet"]["setup"])
            if (line.is_string()) t.setup.push_back(line.get<std::string>());
    t.callAlways = readCallAlways(j["snippet"], path + " snippet");
    if (!j.contains("parameters") || !j["parameters"].is_array() || j["parameters"].empty())
        throw Error(path + ": \"parameters\" must be a non-empty array");
    std::set<std::string> seen;
    for (const auto& row : j["parameters"]) {
        t.params.push_back(readParam(row, path));
        if (!seen.insert(t.params.back().name).second) throw Error(path + ": parameter " + t.params.back().name + " is listed twice");
    }
    return t;
}

EngineTable findEngine(const std::string& name) {
    const std::vector<std::string> names = engineNames();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        std::string list;
        for (const std::string& n : names)
            list += (list.empty() ? "" : ", ") + n;
        throw Error("--engine " + name + " is not an engine ssaolab runs" + didYouMean(name, names) + " (engines: " + list + ")");
    }
    return loadEngineTable(enginePeersDir() + "/engines/" + name + ".json");
}

std::map<std::string, double> shippedValues(const EngineTable& t) {
    std::map<std::string, double> out;
    for (const EngineParam& p : t.params)
        if (p.role != EngineParam::Role::Fixed && p.row.contains("harness")) out[p.name] = p.defaultValue;
    return out;
}

std::string engineRangeText(const EngineParam& p) {
    if (p.type == EngineParam::Type::Boolean) return "true or false";
    if (!p.range) return "any";
    char b[96];
    std::snprintf(b, sizeof b, "[%.9g, %.9g]", p.range->first, p.range->second);
    return b;
}

double checkedEngineValue(const EngineParam& p, const nlohmann::json& v, const std::string& where) {
    const std::string range = engineRangeText(p);
    if (p.type == EngineParam::Type::Boolean) {
        if (!v.is_boolean()) throw Error(where + " must be true or false");
        return v.get<bool>() ? 1.0 : 0.0;
    }
    const bool integer = p.type == EngineParam::Type::Integer;
    if (!v.is_number() || !std::isfinite(v.get<double>()))
        throw Error(where + " must be " + (integer ? "an integer" : "a finite number") + " in " + range);
    const double d = v.get<double>();
    if (integer && d != std::floor(d)) throw Error(where + " must be an integer in " + range);
    if (p.range && (d < p.range->first || d > p.range->second)) {
        char b[64];
        std::snprintf(b, sizeof b, "%.9g", d);
        throw Error(where + " = " + b + " is outside " + p.name + "'s range " + range);
    }
    return d;
}

nlohmann::json engineValueJson(const EngineParam& p, double v) {
    if (p.type == EngineParam::Type::Boolean) return v != 0.0;
    if (p.type == EngineParam::Type::Integer) {
        if (!(std::fabs(v) <= 9007199254740992.0)) throw Error(p.name + " is not an integer JavaScript holds exactly");
        return static_cast<long long>(std::llround(v));
    }
    return v;
}

} // namespace ssao
