#include "commands/stress/stress_cases.h"

#include "scene/view_fit.h"
#include "settings/params.h"

#include <cmath>
#include <cstdio>

namespace ssao {

namespace {
// Makes `p` apply: each condition's key set to its first allowed value (recursively).
void makeApplyFor(Settings& s, const Param& p) {
    for (const auto& c : p.when) {
        const Param* q = findParam(c.key);
        if (!q) continue;
        makeApplyFor(s, *q);
        setParam(s, c.key, c.values.front());
    }
}

std::string sci(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}
} // namespace

Scene transformScene(const Scene& s, double scale, const glm::dvec3& offset, bool sceneOrigin) {
    Scene out = s;
    std::vector<glm::dvec3> world(s.vertices.size());
    for (size_t i = 0; i < world.size(); ++i)
        world[i] = s.toWorld(s.vertices[i].position) * scale + offset;
    out.setWorldPositions(world, sceneOrigin); // a new origin near the moved scene, as the glTF loader picks it
    if (out.camera) *out.camera = transformCamera(*out.camera, s, out, scale, offset);
    for (auto& [name, c] : out.cameras)
        c = transformCamera(c, s, out, scale, offset);
    return out;
}

Camera transformCamera(const Camera& c, const Scene& from, const Scene& to, double scale, const glm::dvec3& offset) {
    Camera out = c;
    out.eye = to.toScene(from.toWorld(c.eye) * scale + offset);
    out.target = to.toScene(from.toWorld(c.target) * scale + offset);
    out.nearZ = float(double(c.nearZ) * scale);
    out.farZ = float(double(c.farZ) * scale);
    return out;
}

namespace {

void projectionCases(std::vector<StressCase>& cases) {
    // Projection: fixed planes, in units of the scene's bounding-box diagonal so every scene sees
    // the same ratios (up to 1e11), with each depth mapping. Standard depth loses surfaces as the
    // ratio grows (reported against the benign render; past 1e8 the camera check refuses, which
    // the report shows); reversed-Z float depth must draw what the fitted planes draw.
    for (DepthMode d : {DepthMode::Standard, DepthMode::Reversed}) {
        const std::string mode = std::string(", ") + depthModeName(d);
        // Invariant when the planes enclose the scene (far >= 10 diagonals: a far plane of one
        // diagonal clips CornellBox, whose camera stands farther than that, and changes its AO).
        auto planes = [&](const std::string& axis, const std::string& variant, float n, float f) {
            StressCase c{axis, variant + mode};
            c.nearZ = n, c.farZ = f, c.depth = d;
            c.compared = true, c.invariant = d == DepthMode::Reversed && f >= 10.0f;
            cases.push_back(c);
        };
        for (double n : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1})
            planes("near", sci(n) + " x diag", float(n), 10.0f);
        for (double f : {1.0, 10.0, 1e2, 1e3, 1e4, 1e5})
            planes("far", sci(f) + " x diag", 1e-3f, float(f));
        planes("near/far", "1e-5 / 1e4 x diag", 1e-5f, 1e4f); // a 1e9 ratio
    }
    {
        StressCase inf{"projection", "infinite far, near 1e-6 x diag, reversed"};
        inf.nearZ = 1e-6f, inf.farZ = INFINITY, inf.depth = DepthMode::Reversed;
        inf.compared = inf.invariant = true;
        cases.push_back(inf);
        for (DepthMode d : {DepthMode::Standard, DepthMode::Reversed}) {
            StressCase o{"projection", std::string("orthographic, ") + depthModeName(d)};
            o.projection = Projection::Orthographic, o.depth = d;
            cases.push_back(o);
            StressCase on{"projection", std::string("orthographic, near 1e-6 x diag, ") + depthModeName(d)};
            on.projection = Projection::Orthographic, on.depth = d, on.nearZ = 1e-6f, on.farZ = 10.0f;
            cases.push_back(on);
        }
    }
}

void placementCases(std::vector<StressCase>& cases) {
    // Scale and placement: the radius follows the scene (scene mode), so AO must not change.
    for (double s : {1e-3, 1e-2, 1e-1, 10.0, 1e2, 1e3}) {
        StressCase c{"scale", "x" + sci(s)};
        c.scale = s, c.invariant = true;
        cases.push_back(c);
    }
    for (double t : {1e3, 1e4, 1e5, 1e6, 1e7}) {
        StressCase c{"translate", "+" + sci(t)};
        c.offset = glm::dvec3(t, 0.5 * t, -0.25 * t), c.invariant = true;
        cases.push_back(c);
    }
    // The same without the scene's double-precision origin: what float positions alone lose.
    for (double t : {1e5, 1e6}) {
        StressCase c{"translate", "+" + sci(t) + ", float positions (no scene origin)"};
        c.offset = glm::dvec3(t, 0.5 * t, -0.25 * t), c.compared = true, c.sceneOrigin = false;
        cases.push_back(c);
    }
}

void precisionCases(std::vector<StressCase>& cases, const std::string& technique) {
    // G-buffer precision, and every technique row that chooses where positions come from.
    std::vector<std::string> precision = {"gbuffer.position_format=rgba16f", "gbuffer.normal_format=rgba8",
                                          "gbuffer.normal_format=rgba32f", "ao.normals=depth"};
    for (const Param& p : paramTable())
        if (p.group() == technique && p.name() == "position_source") precision.push_back(p.key + "=depth");
    for (const std::string& a : precision) {
        StressCase c{"gbuffer", a};
        const std::string assignment = a;
        c.settings = [assignment](Settings& s) { applyAssignment(s, assignment); };
        cases.push_back(c);
    }
}

void limitCases(std::vector<StressCase>& cases, const std::string& technique) {
    // Every parameter that applies to this technique, at both ends of its range.
    for (const Param& p : paramTable()) {
        const std::string g = p.group();
        if (g != "ao" && g != "denoise" && g != technique) continue;
        if (p.key == "ao.technique") continue;
        if (p.type != Param::Type::Float && p.type != Param::Type::Int) continue;
        for (double v : {p.min, p.max}) {
            StressCase c{"limits", p.key + "=" + p.format(v)};
            const std::string key = p.key;
            c.settings = [key, v](Settings& s) {
                const Param* q = findParam(key);
                makeApplyFor(s, *q);
                q->set(s, v);
            };
            cases.push_back(c);
        }
    }
}

void cameraCases(std::vector<StressCase>& cases) {
    // Awkward cameras: inside the geometry, on a surface, grazing, looking away from everything.
    {
        StressCase c{"camera", "inside the scene's centre"};
        c.camera = [](Camera& cam, const Scene& s) {
            const glm::vec3 d = cam.target - cam.eye;
            cam.eye = s.bounds.center();
            cam.target = cam.eye + d;
        };
        cases.push_back(c);
        StressCase g{"camera", "grazing the floor"};
        g.camera = [](Camera& cam, const Scene& s) {
            const glm::vec3 lo = s.bounds.min, hi = s.bounds.max;
            cam.eye = glm::vec3(lo.x, lo.y + 1e-3f * (hi.y - lo.y), lo.z);
            cam.target = glm::vec3(hi.x, lo.y, hi.z);
            cam.up = glm::vec3(0, 1, 0);
        };
        cases.push_back(g);
        StressCase on{"camera", "on a surface"}; // the eye on the first surface along the view ray
        on.camera = [](Camera& cam, const Scene& s) {
            const glm::vec3 d = glm::normalize(cam.target - cam.eye);
            if (const auto hit = firstHit(s, cam.eye, d)) {
                cam.eye += d * *hit;
                cam.target = cam.eye + d * glm::length(cam.target - cam.eye);
            }
        };
        cases.push_back(on);
        StressCase a{"camera", "looking away"};
        a.camera = [](Camera& cam, const Scene& s) {
            const glm::vec3 d = glm::normalize(s.bounds.center() - cam.eye);
            cam.eye = s.bounds.center() - d * (2.0f * s.bounds.radius());
            cam.target = cam.eye - d;
        };
        cases.push_back(a);
    }
}

void geometryCases(std::vector<StressCase>& cases) {
    // Geometry: zero-area triangles (must change nothing), normals of zero or non-unit length
    // (renormalised, or replaced by the face's own: finite either way).
    {
        StressCase deg{"geometry", "10 % more triangles, all degenerate"};
        deg.invariant = true;
        deg.geometry = [](Scene& s) {
            const size_t n = s.indices.size() / 3, first = s.indices.size();
            for (size_t t = 0; t < n; t += 10) { // (a, a, b) and (a, b, midpoint-free line): zero area
                const uint32_t a = s.indices[3 * t], b = s.indices[3 * t + 1];
                s.indices.insert(s.indices.end(), {a, a, b, b, b, b});
            }
            s.draws.push_back({uint32_t(first), uint32_t(s.indices.size() - first), glm::vec4(1.0f)});
        };
        cases.push_back(deg);
        for (float k : {0.0f, 1e-6f, 1e6f}) {
            StressCase c{"geometry", k == 0.0f ? "every 3rd normal zero" : "normals x " + sci(k)};
            c.invariant = k != 0.0f, c.compared = k == 0.0f;
            c.geometry = [k](Scene& s) {
                for (size_t i = 0; i < s.vertices.size(); ++i)
                    if (k != 0.0f || i % 3 == 0) s.vertices[i].normal *= k;
            };
            cases.push_back(c);
        }
    }
}

} // namespace

std::vector<StressCase> stressCases(const std::string& technique) {
    std::vector<StressCase> cases;
    projectionCases(cases);
    placementCases(cases);
    precisionCases(cases, technique);
    limitCases(cases, technique);
    cameraCases(cases);
    geometryCases(cases);
    return cases;
}

} // namespace ssao
