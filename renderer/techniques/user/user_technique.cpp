#include "techniques/user/user_technique.h"

#include "techniques/technique_settings.h"
#include "techniques/user/user_pass.h"

namespace ssao {

namespace {

double valueOr(const Settings& s, const std::string& key, double def) {
    const auto it = s.user.values.find(key);
    return it == s.user.values.end() ? def : it->second;
}

Param userRow(const std::string& id, const UserParam& u) {
    Param p;
    p.key = id + "." + u.name;
    p.label = u.label;
    p.unit = u.unit;
    p.help = u.tooltip;
    p.min = u.min, p.max = u.max;
    switch (u.type) {
    case UserParam::Type::Float: p.type = Param::Type::Float; break;
    case UserParam::Type::Int: p.type = Param::Type::Int; break;
    case UserParam::Type::Bool: p.type = Param::Type::Bool; break;
    case UserParam::Type::Enum: p.type = Param::Type::Enum, p.choices = u.items; break;
    }
    const std::string key = p.key;
    const double def = u.def;
    const bool isFloat = p.type == Param::Type::Float;
    p.get = [key, def](const Settings& s) { return valueOr(s, key, def); };
    // Held as the shader reads it: a float row as a float, like the built-ins' members.
    p.set = [key, isFloat](Settings& s, double v) { s.user.values[key] = isFloat ? double(float(v)) : v; };
    return p;
}

Param noiseRow(const std::string& id) {
    Param p;
    p.key = id + "." + kUserNoiseRow;
    p.label = "Noise";
    p.type = Param::Type::Enum;
    p.help = kAoNoiseHelp;
    for (const auto& [name, kind] : aoNoiseChoices())
        p.choices.push_back(name);
    p.min = 0, p.max = double(p.choices.size() - 1);
    const std::string key = p.key;
    p.get = [key](const Settings& s) { return valueOr(s, key, 0.0); }; // ign, the horizon techniques' default
    p.set = [key](Settings& s, double v) { s.user.values[key] = v; };
    return p;
}

} // namespace

std::string userTechniqueId(const std::string& name) {
    return "user." + name;
}

TechniqueInfo userTechniqueInfo(std::shared_ptr<const UserTechnique> t) {
    TechniqueInfo info;
    info.id = userTechniqueId(t->name);
    info.label = t->header.label;
    info.summary = t->header.summary.empty() ? t->path : t->header.summary;
    info.file = t->path;
    info.version = t->hash;
    info.user = t;
    info.secondLayer = true; // ssaoSecondLayerAt (shaders/include/user_interface.glsl)
    info.staticNoise = [t](const Settings& s) { return userNoise(*t, s) == AoNoise::None; };
    const std::string id = info.id;
    info.params = [t, id] {
        std::vector<Param> rows;
        for (const UserParam& u : t->header.params)
            rows.push_back(userRow(id, u));
        rows.push_back(noiseRow(id));
        return rows;
    };
    info.makePasses = [t](const Chain& c) {
        std::vector<std::unique_ptr<Pass>> passes;
        passes.push_back(std::make_unique<UserAoPass>(c, t));
        return passes;
    };
    // `tune` fits its float rows; it states no quality levels, presets or bounds of its own.
    for (const UserParam& u : t->header.params)
        if (u.type == UserParam::Type::Float) info.tuned.push_back(id + "." + u.name);
    return info;
}

std::vector<double> userParamValues(const UserTechnique& t, const Settings& s) {
    std::vector<double> v;
    const std::string id = userTechniqueId(t.name);
    for (const UserParam& u : t.header.params)
        v.push_back(valueOr(s, id + "." + u.name, u.def));
    return v;
}

AoNoise userNoise(const UserTechnique& t, const Settings& s) {
    const auto choices = aoNoiseChoices();
    const size_t i = size_t(valueOr(s, userTechniqueId(t.name) + "." + kUserNoiseRow, 0.0));
    return i < choices.size() ? choices[i].second : AoNoise::Ign;
}

} // namespace ssao
