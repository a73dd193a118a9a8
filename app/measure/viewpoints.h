// Named viewpoints of a scene for benchmarks and tuning: the scene's own camera, then orbits of it
// about its target (the same distance, field of view and clip mode; alternating sides, growing
// angles, with a little elevation change so views are not only rotations about one axis).
#pragma once
#include "scene/camera.h"

#include <string>
#include <utility>
#include <vector>

namespace ssao {

// `count` viewpoints (≥ 1): "camera", "orbit+25", "orbit-25", "orbit+50", ...
std::vector<std::pair<std::string, Camera>> viewpoints(const Camera& base, int count);

} // namespace ssao
