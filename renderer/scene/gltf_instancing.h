// EXT_mesh_gpu_instancing: a node drawing its mesh once per instance, each instance's transform
// (TRANSLATION, ROTATION, SCALE accessors) applied in the node's local frame before the node's own
// (world = node's world x T x R x S). ssaolab expands instances into triangles, within the scene's
// triangle budget, so the G-buffer and the reference hold the same surfaces.
#pragma once
#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace ssao {

// The instances a node's mesh is drawn with: 1 without the extension. From the accessors' counts
// alone (checked equal), so the budget is checked before anything is read or allocated.
size_t instanceCount(const tinygltf::Model& m, const tinygltf::Node& n, const std::string& what);

// Each instance's transform in the node's local frame (one identity without the extension).
// Throws ssao::Error naming the accessor that cannot be read.
std::vector<glm::dmat4> instanceTransforms(const tinygltf::Model& m, const tinygltf::Node& n, const std::string& what);

} // namespace ssao
