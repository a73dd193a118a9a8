#pragma once
#include "scene/scene.h"

#include <string>
#include <vector>

namespace ssao {
std::vector<std::string> builtinSceneNames();
// Throws ssao::Error listing the available names when `name` is unknown.
Scene makeBuiltinScene(const std::string& name);
} // namespace ssao
