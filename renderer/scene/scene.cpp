#include "scene/scene.h"

#include "scene/builtin_scenes.h"
#include "scene/gltf_loader.h"

namespace ssao {

namespace {
SceneBudget gBudget;
} // namespace

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

Scene loadScene(const std::string& spec) {
    const std::string prefix = "builtin:";
    if (spec.rfind(prefix, 0) == 0) return makeBuiltinScene(spec.substr(prefix.size()));
    return loadGltf(spec);
}

} // namespace ssao
