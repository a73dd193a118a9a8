// A scene by its name on the command line: "builtin:NAME" (scene/load/builtin_scenes.h) or a glTF
// file (scene/load/gltf_loader.h).
#pragma once
#include "scene/scene.h"

#include <string>

namespace ssao {

// "builtin:NAME" → procedural scene, anything else → glTF file. Throws ssao::Error.
Scene loadScene(const std::string& spec);

} // namespace ssao
