// Physics at every setting, not only at the defaults: for every technique, at each of its quality
// levels (its defaults and every shipped TECHNIQUE-* preset, each also deinterleaved and with two
// depth layers where the technique takes them) and with each of its rows (and the
// shared AO and denoise rows) at the ends of its range or at each of its choices, an open plane
// stays unoccluded (AO >= 0.99, finite, in [0,1]) and the floor beside a wall follows the closed
// form: within the technique's stated bound at its quality levels; at any limit never darker away
// from the wall than at it, open at 2 R and within a looser bound. The rows come from the parameter table and the presets from assets/, so a
// new technique, row or preset is swept without editing this file.
#include "closed_form.h"
#include "gl_fixture.h"

#include "scene/scene.h"
#include "techniques/technique.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

using namespace ssao;
using namespace ssaotest;

namespace {
class PhysicsLimits : public GlTest {};

struct Config {
    std::string label;
    Settings settings;
};

// The corner's geometry is in metres: the closed form is for a world radius.
Settings atWorldRadius(Settings s) {
    s.ao.radiusMode = RadiusMode::World;
    s.ao.radius = 1.0f;
    return s;
}

Settings forTechnique(const std::string& id) {
    Settings s = defaultSettings();
    s.ao.technique = id;
    return atWorldRadius(s);
}

std::vector<Config> qualityLevels(const std::string& id) {
    std::vector<Config> out{{id + " defaults", forTechnique(id)}};
    std::set<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(std::string(SSAOLAB_ASSET_DIR) + "/presets")) {
        const std::string name = e.path().stem().string();
        if (name.rfind(id + "-", 0) == 0) names.insert(name);
    }
    for (const auto& name : names)
        out.push_back({name, atWorldRadius(preset(name))});
    // Deinterleaved sampling (ao.deinterleave) at each level, where the technique takes it and the
    // level leaves it in effect (full resolution, no pyramid).
    for (size_t i = 0, n = out.size(); i < n; ++i) {
        Config d = out[i];
        d.settings.ao.deinterleave = true;
        if (!deinterleaves(d.settings)) continue;
        d.label += " deinterleaved";
        out.push_back(d);
    }
    // Two depth layers (gbuffer.second_layer) at each level, both builds, where the technique reads them.
    for (size_t i = 0, n = out.size(); i < n; ++i)
        for (const SecondLayerBuild build : {SecondLayerBuild::Peel, SecondLayerBuild::Previous}) {
            Config d = out[i];
            d.settings.gbuffer.secondLayer = true;
            d.settings.gbuffer.secondLayerBuild = build;
            if (!findParam("gbuffer.second_layer")->applies(d.settings)) break;
            d.label += build == SecondLayerBuild::Peel ? " 2 layers" : " 2 layers, one pass";
            out.push_back(d);
        }
    return out;
}

// Makes `p` apply, keeping every condition that already holds (the technique stays the one tested).
void makeApply(Settings& s, const Param& p) {
    for (const auto& c : p.when) {
        const Param& q = *findParam(c.key);
        if (c.key == "ao.technique") continue; // never switch the technique under test: see applies()
        makeApply(s, q);
        const std::string now = q.format(q.get(s));
        if (std::find(c.values.begin(), c.values.end(), now) == c.values.end()) setParam(s, c.key, c.values.front());
    }
}

// The technique's own rows and the shared rows a user sets beside them, each at its limits.
std::vector<Config> limits(const std::string& id) {
    static const std::set<std::string> shared = {"ao.power",    "ao.resolution", "ao.normals", "ao.adaptive",
                                                 "ao.adaptive_px", "ao.deinterleave", "denoise.kind", "denoise.upsample",
                                                 "gbuffer.back_faces", "gbuffer.second_layer",
                                                 "gbuffer.second_layer_separation", "gbuffer.second_layer_build"};
    std::vector<Config> out;
    for (const Param& p : paramTable()) {
        if (p.group() != id && !shared.count(p.key)) continue;
        std::vector<double> values;
        if (p.type == Param::Type::Float || p.type == Param::Type::Int)
            values = {p.min, p.max};
        else
            for (double v = p.min; v <= p.max; v += 1.0)
                values.push_back(v);
        for (double v : values) {
            Settings s = forTechnique(id);
            makeApply(s, p);
            p.set(s, v);
            if (!p.applies(s)) continue; // a row of another technique's choice
            out.push_back({p.key + "=" + p.format(v), s});
        }
    }
    return out;
}

struct Outcome {
    double plane = 0, planeRaw = 0;
    CornerProfile corner;
};

Outcome measure(const Settings& s) {
    Outcome o;
    const Rendered plane = render("builtin:plane", s, 160, 90);
    EXPECT_TRUE(finiteInRange(plane.aoRaw, 0.0f, 1.0f));
    EXPECT_TRUE(finiteInRange(plane.ao, 0.0f, 1.0f));
    o.plane = geometryMean(plane, plane.ao);
    o.planeRaw = geometryMean(plane, plane.aoRaw);
    o.corner = cornerProfile(s);
    return o;
}

// At a row's limits: AO = 1 everywhere is 0.175 from the closed form, AO 0 at the wall (power 16,
// SAO intensity 10) up to 0.38.
constexpr double kLimitBound = 0.4;
} // namespace

TEST_F(PhysicsLimits, EveryQualityLevelKeepsAnOpenPlaneAndTheClosedFormCorner) {
    for (const auto& t : techniques()) {
        // The bound the technique states at its quality levels (TechniqueInfo, technique.h).
        ASSERT_GT(t.levelsCornerBound, 0.0) << "state a closed-form bound for " << t.id
                                            << " (TechniqueInfo::levelsCornerBound)";
        for (const Config& c : qualityLevels(t.id)) {
            const Outcome o = measure(c.settings);
            std::printf("%-22s plane %.4f (raw %.4f)  corner RMSE %.4f  wall %.3f far %.3f\n", c.label.c_str(),
                        o.plane, o.planeRaw, o.corner.rmse, o.corner.atWall, o.corner.far);
            EXPECT_GE(o.planeRaw, 0.99) << c.label;
            EXPECT_GE(o.plane, 0.99) << c.label;
            EXPECT_LT(o.corner.rmse, t.levelsCornerBound) << c.label;
        }
    }
}

TEST_F(PhysicsLimits, EveryRowAtItsLimitsKeepsAnOpenPlaneAndACornerThatDarkensTowardTheWall) {
    int tried = 0, exempt = 0;
    for (const auto& t : techniques())
        for (const Config& c : limits(t.id)) {
            const Outcome o = measure(c.settings);
            const std::string why = unphysicalReason(c.settings); // declared by the technique
            const bool unphysical = !why.empty();
            std::printf("%-5s %-34s plane %.4f (raw %.4f)  corner RMSE %.4f  wall %.3f far %.3f%s%s\n",
                        t.id.c_str(), c.label.c_str(), o.plane, o.planeRaw, o.corner.rmse, o.corner.atWall,
                        o.corner.far, unphysical ? "  exempt: " : "", why.c_str());
            ++tried;
            if (unphysical) {
                ++exempt;
                continue;
            }
            EXPECT_GE(o.planeRaw, 0.99) << t.id << " " << c.label;
            EXPECT_GE(o.plane, 0.99) << t.id << " " << c.label;
            // A limit may remove occlusion (intensity 0, a bias of the whole radius) or darken it
            // (power 16), but never inverts it, never occludes beyond twice the reach, and stays
            // within the limits' bound of the closed form.
            EXPECT_LE(o.corner.atWall, o.corner.far + 0.01) << t.id << " " << c.label;
            EXPECT_GE(o.corner.far, 0.9) << t.id << " " << c.label;
            EXPECT_LT(o.corner.rmse, kLimitBound) << t.id << " " << c.label;
        }
    std::printf("%d settings, %d exempt as unphysical by design\n", tried, exempt);
    EXPECT_GT(tried, 60);
}
