#include "settings/params.h"

#include "settings/core_rows.h"
#include "settings/preset.h"
#include "techniques/registry.h"
#include "util/closest_name.h"
#include "util/error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>

namespace ssao {

namespace {

using T = Param::Type;

std::vector<Param> buildTable() {
    std::vector<Param> table = coreParamRows();
    // Technique rows go after the ao group, each applying only while its technique is chosen.
    auto at = table.begin();
    while (at != table.end() && at->group() != "denoise")
        ++at;
    std::vector<Param> tech;
    for (const auto& info : registeredTechniques())
        for (Param p : info.rows) {
            p.when.insert(p.when.begin(), Param::Condition{"ao.technique", {info.id}});
            tech.push_back(std::move(p));
        }
    table.insert(at, tech.begin(), tech.end());
    const Settings defaults{};
    for (Param& p : table)
        p.def = p.get(defaults); // the struct initialisers are the one source of defaults
    return table;
}

double parseNumber(const Param& p, const std::string& text) {
    double v = 0;
    if (!parseDecimal(text, v)) throw Error(p.key + ": '" + text + "' is not a number");
    return v;
}

void checkValue(const Param& p, double v, const std::string& shown) {
    if (!std::isfinite(v)) throw Error(p.key + ": value " + shown + " is not finite");
    if (p.type == T::Int && v != std::floor(v))
        throw Error(p.key + ": value " + shown + " is not an integer");
    // A float row holds a float: compare at its precision (1e-4 stored is 0.000099999997).
    const bool below = p.type == T::Float ? float(v) < float(p.min) : v < p.min;
    const bool above = p.type == T::Float ? float(v) > float(p.max) : v > p.max;
    if (below || above)
        throw Error(p.key + ": value " + shown + " is out of range [" + p.format(p.min) + ", " +
                    p.format(p.max) + "]" + (p.unit.empty() ? "" : " " + p.unit));
}

void checkAndSet(const Param& p, Settings& s, double v, const std::string& shown) {
    checkValue(p, v, shown);
    p.set(s, v);
}

std::string choiceList(const Param& p) {
    std::string out;
    for (auto& c : p.choices)
        out += (out.empty() ? "" : "|") + c;
    return out;
}

// The table of the registry's current generation of techniques (techniques/technique.h), with its
// index by key and its keys (for "did you mean" on a mistyped one). Tables of earlier generations
// are kept, so a row a caller holds stays valid when a user technique changes.
struct Table {
    unsigned generation = 0;
    std::vector<Param> rows;
    std::map<std::string, const Param*> index;
    std::vector<std::string> keys;
};

const Table& currentTable() {
    static std::mutex mutex;
    static std::vector<std::unique_ptr<Table>> kept;
    static std::atomic<const Table*> current{nullptr};
    const unsigned generation = techniquesGeneration();
    const Table* t = current.load(std::memory_order_acquire);
    if (t && t->generation == generation) return *t;
    std::lock_guard<std::mutex> lock(mutex);
    t = current.load(std::memory_order_acquire);
    if (t && t->generation == generation) return *t;
    auto n = std::make_unique<Table>();
    n->generation = generation;
    n->rows = buildTable();
    for (const auto& p : n->rows) {
        n->index.emplace(p.key, &p);
        n->keys.push_back(p.key);
    }
    kept.push_back(std::move(n));
    current.store(kept.back().get(), std::memory_order_release);
    return *kept.back();
}

const std::vector<std::string>& allKeys() {
    return currentTable().keys;
}

// Shortest decimal text that reads back as the same float (presets stay human-readable).
double shortFloat(double v) {
    char buf[32];
    for (int prec = 6; prec <= 9; ++prec) {
        std::snprintf(buf, sizeof buf, "%.*g", prec, v);
        if (float(std::strtod(buf, nullptr)) == float(v)) break;
    }
    return std::strtod(buf, nullptr);
}

} // namespace

std::string Param::format(double v) const {
    char buf[32];
    switch (type) {
    case T::Bool:
        return v != 0.0 ? "true" : "false";
    case T::Enum:
        return choices.at(size_t(v));
    case T::Int:
        std::snprintf(buf, sizeof buf, "%d", int(v));
        return buf;
    case T::Float:
        std::snprintf(buf, sizeof buf, "%g", shortFloat(v));
        return buf;
    }
    return {};
}

bool Param::isDefault(const Settings& s) const {
    return get(s) == def;
}

bool Param::applies(const Settings& s) const {
    for (const Condition& c : when) {
        const Param* other = findParam(c.key);
        if (!other) return false;
        const std::string v = other->format(other->get(s));
        bool any = false;
        for (const auto& allowed : c.values)
            any |= v == allowed;
        if (!any || !other->applies(s)) return false;
    }
    return true;
}

std::string Param::whenText() const {
    std::string out;
    for (const Condition& c : when) {
        std::string values;
        for (auto& v : c.values)
            values += (values.empty() ? "" : "|") + v;
        out += (out.empty() ? "" : " and ") + c.key + " = " + values;
    }
    return out;
}

Param& Param::onlyWhen(const std::string& k, std::vector<std::string> values) {
    when.push_back({k, std::move(values)});
    return *this;
}

const std::vector<Param>& paramTable() {
    return currentTable().rows;
}

const Param* findParam(const std::string& key) {
    const auto& index = currentTable().index;
    auto it = index.find(key);
    return it == index.end() ? nullptr : it->second;
}

Settings defaultSettings() {
    return Settings{};
}

void setParam(Settings& s, const std::string& key, const std::string& text) {
    const Param* p = findParam(key);
    if (!p) throw Error("unknown parameter '" + key + "'" + didYouMean(key, allKeys()));
    switch (p->type) {
    case T::Bool:
        if (text == "true" || text == "1" || text == "on") return p->set(s, 1);
        if (text == "false" || text == "0" || text == "off") return p->set(s, 0);
        throw Error(key + ": '" + text + "' is not a boolean (true|false)");
    case T::Enum:
        for (size_t i = 0; i < p->choices.size(); ++i)
            if (p->choices[i] == text) return p->set(s, double(i));
        if (key == "ao.technique")
            if (const std::string why = refusedTechniqueReason(text); !why.empty())
                throw Error("technique " + text + " was not loaded: " + why);
        throw Error(key + ": '" + text + "' is not one of " + choiceList(*p));
    default:
        checkAndSet(*p, s, parseNumber(*p, text), text);
    }
}

void validateSettings(const Settings& s) {
    for (const Param& p : paramTable()) {
        if (!p.applies(s)) continue;
        const double v = p.get(s);
        if (p.type == T::Float || p.type == T::Int) checkValue(p, v, p.format(v));
    }
}

void fitUserValues(Settings& s) {
    for (auto it = s.user.values.begin(); it != s.user.values.end();) {
        const Param* p = findParam(it->first);
        if (!p) {
            it = s.user.values.erase(it);
            continue;
        }
        double v = std::isfinite(it->second) ? it->second : p->def;
        if (p->type != T::Float) v = std::round(v);
        it->second = std::clamp(v, p->min, p->max);
        ++it;
    }
}

void applyAssignment(Settings& s, const std::string& assignment) {
    auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) throw Error("--set '" + assignment + "': expected key=value");
    setParam(s, assignment.substr(0, eq), assignment.substr(eq + 1));
}

namespace {
nlohmann::json serialise(const Settings& s, bool effectiveOnly) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& p : paramTable()) {
        if (effectiveOnly && !p.applies(s)) {
            j[p.group()]; // the group exists even when none of its rows applies
            continue;
        }
        double v = p.get(s);
        auto& slot = j[p.group()][p.name()];
        switch (p.type) {
        case T::Bool:
            slot = v != 0.0;
            break;
        case T::Enum:
            slot = p.choices.at(size_t(v));
            break;
        case T::Int:
            slot = int(v);
            break;
        case T::Float:
            slot = shortFloat(v);
            break;
        }
    }
    return j;
}
} // namespace

nlohmann::json toJson(const Settings& s) {
    return serialise(s, false);
}

nlohmann::json toEffectiveJson(const Settings& s) {
    return serialise(s, true);
}

namespace {
bool isTechnique(const std::string& id) {
    for (const auto& t : registeredTechniques())
        if (t.id == id) return true;
    return false;
}
} // namespace

void applyJson(Settings& s, const nlohmann::json& patch, const std::string& origin) {
    if (!patch.is_object()) throw Error(origin + ": a preset must be a JSON object");
    for (auto& [group, members] : patch.items()) {
        if (isPresetMetadataKey(group)) continue;
        if (!members.is_object()) throw Error(origin + ": '" + group + "' must be an object of parameters");
        for (auto& [name, value] : members.items()) {
            const std::string key = group + "." + name;
            const Param* p = findParam(key);
            if (!p && group.rfind("user.", 0) == 0 && !isTechnique(group))
                throw Error(origin + ": unknown key '" + key + "': the user technique " + group +
                            " is not loaded (its file is not in the technique folder)");
            if (!p) throw Error(origin + ": unknown key '" + key + "'" + didYouMean(key, allKeys()));
            try {
                switch (p->type) {
                case T::Bool:
                    if (!value.is_boolean()) throw Error(key + ": expected true or false");
                    p->set(s, value.get<bool>() ? 1 : 0);
                    break;
                case T::Enum:
                    if (!value.is_string()) throw Error(key + ": expected one of " + choiceList(*p));
                    setParam(s, key, value.get<std::string>());
                    break;
                default:
                    if (!value.is_number()) throw Error(key + ": expected a number");
                    checkAndSet(*p, s, value.get<double>(), value.dump());
                }
            } catch (const Error& e) {
                throw Error(origin + ": " + e.what());
            }
        }
    }
}

Settings loadPreset(const std::string& path) {
    return readPresetFile(path).settings;
}

bool operator==(const Settings& a, const Settings& b) {
    for (const auto& p : paramTable())
        if (p.get(a) != p.get(b)) return false;
    return true;
}

} // namespace ssao
