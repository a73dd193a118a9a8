#include "settings/params.h"

#include "settings/preset.h"

#include "util/error.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace ssao {

namespace {

using T = Param::Type;

// Row builders: keep the table below one readable line-group per parameter.
template <class Get, class Set>
Param row(const char* key, const char* label, T type, double def, double lo, double hi, const char* unit,
          const char* help, std::vector<std::string> choices, Get get, Set set) {
    return Param{key, label, type, def, lo, hi, unit, help, std::move(choices), get, set};
}

#define FLOAT_P(key, label, field, def, lo, hi, unit, help)                                                  \
    row(                                                                                                     \
        key, label, T::Float, def, lo, hi, unit, help, {},                                                   \
        [](const Settings& s) { return double(s.field); },                                                   \
        [](Settings& s, double v) { s.field = float(v); })
#define INT_P(key, label, field, def, lo, hi, unit, help)                                                    \
    row(                                                                                                     \
        key, label, T::Int, def, lo, hi, unit, help, {}, [](const Settings& s) { return double(s.field); },  \
        [](Settings& s, double v) { s.field = int(v); })
#define BOOL_P(key, label, field, def, help)                                                                 \
    row(                                                                                                     \
        key, label, T::Bool, def, 0, 1, "", help, {}, [](const Settings& s) { return s.field ? 1.0 : 0.0; }, \
        [](Settings& s, double v) { s.field = v != 0.0; })
#define ENUM_P(key, label, field, E, def, help, ...)                                                         \
    row(                                                                                                     \
        key, label, T::Enum, def, 0, std::vector<std::string>{__VA_ARGS__}.size() - 1, "", help,             \
        {__VA_ARGS__}, [](const Settings& s) { return double(int(s.field)); },                               \
        [](Settings& s, double v) { s.field = E(int(v)); })

std::vector<Param> buildTable() {
    return {
        // ---- G-buffer -------------------------------------------------------------------------
        ENUM_P("gbuffer.position_format", "Position format", gbuffer.positionFormat, TargetFormat, 1,
               "Precision of the view-space position target; rgba16f shows fp16 staircase acne at distance.",
               "rgba16f", "rgba32f"),
        ENUM_P("gbuffer.normal_format", "Normal format", gbuffer.normalFormat, TargetFormat, 0,
               "Normal target: float, or 8-bit (n+1)/2 as in seed 003 (renormalised after decoding).",
               "rgba16f", "rgba32f", "rgba8"),
        // ---- SSAO -----------------------------------------------------------------------------
        ENUM_P("ssao.kernel", "Kernel", ssao.kernel, Kernel, 0,
               "hemisphere: samples above the surface; sphere (Crytek): half the samples start inside, "
               "so flat surfaces read ~50% occluded.",
               "hemisphere", "sphere"),
        BOOL_P("ssao.separable", "Separable", ssao.separable, 0,
               "Seed 003: two sample sets in the x-z and y-z tangent planes (N each, normalised by 2N)."),
        INT_P("ssao.samples", "Samples", ssao.samples, 64, 1, 256, "samples",
              "Kernel samples per pixel (per plane when separable); more = less noise, linear cost."),
        FLOAT_P("ssao.radius", "Radius", ssao.radius, 0.5, 1e-4, 1e4, "scene units",
                "World-size of the sampling kernel: how far away geometry can still occlude."),
        FLOAT_P("ssao.bias", "Bias", ssao.bias, 0.025, 0.0, 1e3, "scene units",
                "Depth margin before a sample counts as occluded; removes self-occlusion acne, too much "
                "loses contact shadows."),
        ENUM_P("ssao.range_check", "Range check", ssao.rangeCheck, RangeCheck, 0,
               "Fades occluders far in depth from the pixel: smoothstep(radius/|dz|) (seed 004), hard "
               "|dz|<radius "
               "(seed 003) or off (dark halos behind silhouettes).",
               "smoothstep", "hard", "off"),
        ENUM_P("ssao.depth_test", "Depth test", ssao.depthTest, DepthTest, 0,
               "sample: occluded if the surface is in front of the sample (seeds 000/004); fragment: if it "
               "is behind "
               "the pixel itself (seed 003).",
               "sample", "fragment"),
        FLOAT_P("ssao.power", "Power", ssao.power, 1.0, 0.1, 16.0, "",
                "Contrast: AO = visibility^power; >1 darkens occluded areas, <1 lightens (seed 001)."),
        ENUM_P("ssao.noise", "Rotation noise", ssao.noise, Noise, 0,
               "Per-pixel kernel rotation: a tiled 4x4 texture (noise the blur removes) or none (banding).",
               "tex4x4", "none"),
        INT_P("ssao.seed", "Seed", ssao.seed, 0, 0, 1000000, "",
              "Random seed of the kernel and noise; change it to see which artefacts are sampling luck."),
        ENUM_P(
            "ssao.position_source", "Position source", ssao.positionSource, PositionSource, 0,
            "Read positions from the G-buffer target, or reconstruct them from the depth buffer (seed 001).",
            "gbuffer", "depth"),
        ENUM_P(
            "ssao.offscreen", "Off-screen samples", ssao.offscreen, Offscreen, 0,
            "Samples projecting outside the screen: skip (count as open) or clamp to the edge texel (seeds).",
            "skip", "clamp"),
        // ---- Blur -----------------------------------------------------------------------------
        ENUM_P("blur.kind", "Blur", blur.kind, BlurKind, 1,
               "Removes the 4x4 noise pattern: none, 4x4 box (seed 004) or gaussian (seed 003). Both run "
               "separably.",
               "none", "box4", "gaussian"),
        FLOAT_P("blur.sigma", "Sigma", blur.sigma, 1.5, 0.1, 32.0, "taps",
                "Gaussian standard deviation; weight = exp(-d^2 / (2 sigma^2))."),
        INT_P("blur.radius", "Half-width", blur.radius, 2, 0, 32, "taps",
              "Gaussian taps each side of the centre (2 gives the seed's 5x5)."),
        FLOAT_P(
            "blur.spacing", "Tap spacing", blur.spacing, 1.0, 0.25, 16.0, "pixels",
            "Distance between gaussian taps (seed 003 blurRadius); >1 widens the blur without more taps."),
        // ---- Composite ------------------------------------------------------------------------
        FLOAT_P("composite.ambient", "Ambient", composite.ambient, 0.7, 0.0, 4.0, "",
                "Ambient term strength: ambient * albedo * AO (seed 004 uses 0.1 with a bright light)."),
        FLOAT_P("composite.light", "Light", composite.light, 0.6, 0.0, 10.0, "",
                "Intensity of the one point light at the camera (0 shows ambient * AO only)."),
        BOOL_P("composite.ao", "Apply AO", composite.useAo, 1,
               "Multiply the ambient term by AO; off shows the same frame without SSAO."),
    };
}

double parseNumber(const Param& p, const std::string& text) {
    size_t used = 0;
    double v = 0;
    try {
        v = std::stod(text, &used);
    } catch (...) {
        used = 0;
    }
    if (used == 0 || used != text.size()) throw Error(p.key + ": '" + text + "' is not a number");
    return v;
}

void checkAndSet(const Param& p, Settings& s, double v, const std::string& shown) {
    if (!std::isfinite(v)) throw Error(p.key + ": value " + shown + " is not finite");
    if (p.type == T::Int && v != std::floor(v))
        throw Error(p.key + ": value " + shown + " is not an integer");
    if (v < p.min || v > p.max)
        throw Error(p.key + ": value " + shown + " is out of range [" + p.format(p.min) + ", " +
                    p.format(p.max) + "]" + (p.unit.empty() ? "" : " " + p.unit));
    p.set(s, v);
}

std::string choiceList(const Param& p) {
    std::string out;
    for (auto& c : p.choices)
        out += (out.empty() ? "" : "|") + c;
    return out;
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
    static const Settings defaults = defaultSettings();
    return get(s) == get(defaults);
}

const std::vector<Param>& paramTable() {
    static const std::vector<Param> table = buildTable();
    return table;
}

const Param* findParam(const std::string& key) {
    for (const auto& p : paramTable())
        if (p.key == key) return &p;
    return nullptr;
}

Settings defaultSettings() {
    Settings s;
    for (const auto& p : paramTable())
        p.set(s, p.def);
    return s;
}

void setParam(Settings& s, const std::string& key, const std::string& text) {
    const Param* p = findParam(key);
    if (!p) throw Error("unknown parameter '" + key + "'");
    switch (p->type) {
    case T::Bool:
        if (text == "true" || text == "1" || text == "on") return p->set(s, 1);
        if (text == "false" || text == "0" || text == "off") return p->set(s, 0);
        throw Error(key + ": '" + text + "' is not a boolean (true|false)");
    case T::Enum:
        for (size_t i = 0; i < p->choices.size(); ++i)
            if (p->choices[i] == text) return p->set(s, double(i));
        throw Error(key + ": '" + text + "' is not one of " + choiceList(*p));
    default:
        checkAndSet(*p, s, parseNumber(*p, text), text);
    }
}

void applyAssignment(Settings& s, const std::string& assignment) {
    auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) throw Error("--set '" + assignment + "': expected key=value");
    setParam(s, assignment.substr(0, eq), assignment.substr(eq + 1));
}

nlohmann::json toJson(const Settings& s) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& p : paramTable()) {
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

void applyJson(Settings& s, const nlohmann::json& patch, const std::string& origin) {
    if (!patch.is_object()) throw Error(origin + ": a preset must be a JSON object");
    for (auto& [group, members] : patch.items()) {
        if (group == "name" || group == "description" || group == "camera") continue; // preset metadata
        if (!members.is_object()) throw Error(origin + ": '" + group + "' must be an object of parameters");
        for (auto& [name, value] : members.items()) {
            const std::string key = group + "." + name;
            const Param* p = findParam(key);
            if (!p) throw Error(origin + ": unknown key '" + key + "'");
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
