#include "scene/scene.h"

#include "util/error.h"


#include <algorithm>
#include <cmath>

namespace ssao {

namespace {
SceneBudget gBudget;
Transparent gTransparent = Transparent::Skip;
} // namespace

void setTransparentMode(Transparent t) {
    gTransparent = t;
}
Transparent transparentMode() {
    return gTransparent;
}
Transparent parseTransparent(const std::string& s) {
    if (s == "skip") return Transparent::Skip;
    if (s == "opaque") return Transparent::Opaque;
    throw Error("transparent surfaces: '" + s + "' is not skip or opaque");
}

void setSceneBudget(SceneBudget b) {
    gBudget = b;
}
SceneBudget sceneBudget() {
    return gBudget;
}

void Scene::computeBounds() {
    bounds = Bounds{};
    for (const auto& v : vertices)
        bounds.add(v.position);
}

void Scene::setWorldPositions(const std::vector<glm::dvec3>& world, bool rebase) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const auto& p : world)
        lo = glm::min(lo, p), hi = glm::max(hi, p);
    origin = glm::dvec3(0.0);
    if (rebase && !world.empty()) {
        const glm::dvec3 centre = (lo + hi) * 0.5;
        // Farther than its own size from 0: float positions would waste their bits on the offset.
        if (glm::length(centre) > std::max(glm::length(hi - lo), 1e-30)) origin = centre;
    }
    for (size_t i = 0; i < world.size() && i < vertices.size(); ++i)
        vertices[i].position = toScene(world[i]);
    computeBounds();
}

Camera cameraToScene(const Camera& c, const Scene& s) {
    Camera out = c;
    out.eye = s.toScene(glm::dvec3(c.eye));
    out.target = s.toScene(glm::dvec3(c.target));
    return out;
}

Camera cameraToFile(const Camera& c, const Scene& s) {
    Camera out = c;
    out.eye = glm::vec3(s.toWorld(c.eye));
    out.target = glm::vec3(s.toWorld(c.target));
    return out;
}

} // namespace ssao
