#include "scene/load/load_scene.h"

#include "scene/load/builtin_scenes.h"
#include "scene/load/gltf_loader.h"

namespace ssao {

Scene loadScene(const std::string& spec) {
    const std::string prefix = "builtin:";
    if (spec.rfind(prefix, 0) == 0) return makeBuiltinScene(spec.substr(prefix.size()));
    return loadGltf(spec);
}

} // namespace ssao
