#pragma once
#include "scene/scene.h"

namespace ssao {
// Loads a .gltf or .glb file. Throws ssao::Error with one line naming the file and the problem.
Scene loadGltf(const std::string& path);
} // namespace ssao
