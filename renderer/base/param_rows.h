// Builders for parameter-table rows, shared by the core table and each technique's rows.
// Enum rows map each choice name to its enum value explicitly, so reordering either list can
// never silently change what a preset means.
#pragma once
#include "base/param.h"

#include <utility>

namespace ssao::rows {

template <class Ref>
Param number(Param::Type t, const char* key, const char* label, double lo, double hi, const char* unit,
             const char* help, Ref ref) {
    Param p;
    p.key = key, p.label = label, p.type = t, p.min = lo, p.max = hi, p.unit = unit, p.help = help;
    p.get = [ref](const Settings& s) { return double(ref(const_cast<Settings&>(s))); };
    if (t == Param::Type::Float)
        p.set = [ref](Settings& s, double v) { ref(s) = float(v); };
    else
        p.set = [ref](Settings& s, double v) { ref(s) = int(v); };
    return p;
}

template <class Ref> Param flag(const char* key, const char* label, const char* help, Ref ref) {
    Param p;
    p.key = key, p.label = label, p.type = Param::Type::Bool, p.min = 0, p.max = 1, p.help = help;
    p.get = [ref](const Settings& s) { return ref(const_cast<Settings&>(s)) ? 1.0 : 0.0; };
    p.set = [ref](Settings& s, double v) { ref(s) = v != 0.0; };
    return p;
}

template <class E, class Ref>
Param choice(const char* key, const char* label, const char* help, std::vector<std::pair<std::string, E>> map,
             Ref ref) {
    Param p;
    p.key = key, p.label = label, p.type = Param::Type::Enum, p.help = help;
    for (auto& [name, value] : map)
        p.choices.push_back(name);
    p.min = 0, p.max = double(map.size() - 1);
    p.get = [map, ref](const Settings& s) {
        const E v = ref(const_cast<Settings&>(s));
        for (size_t i = 0; i < map.size(); ++i)
            if (map[i].second == v) return double(i);
        return 0.0; // unreachable: every enum value the code uses is in the map (tested)
    };
    p.set = [map, ref](Settings& s, double v) { ref(s) = map.at(size_t(v)).second; };
    return p;
}

} // namespace ssao::rows

// `field` is a member path inside Settings, e.g. ao.radius or kernel.samples.
#define SSAO_REF(field)                                                                                      \
    [](Settings & s) -> auto& {                                                                              \
        return s.field;                                                                                      \
    }
#define FLOAT_ROW(key, label, field, lo, hi, unit, help)                                                     \
    ::ssao::rows::number(::ssao::Param::Type::Float, key, label, lo, hi, unit, help, SSAO_REF(field))
#define INT_ROW(key, label, field, lo, hi, unit, help)                                                       \
    ::ssao::rows::number(::ssao::Param::Type::Int, key, label, lo, hi, unit, help, SSAO_REF(field))
#define BOOL_ROW(key, label, field, help) ::ssao::rows::flag(key, label, help, SSAO_REF(field))
#define ENUM_ROW(key, label, field, E, help, ...)                                                            \
    ::ssao::rows::choice<E>(key, label, help, std::vector<std::pair<std::string, E>> __VA_ARGS__,            \
                            SSAO_REF(field))
