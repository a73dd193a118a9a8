// Which pixel of the previous frame shows the same surface point as a pixel of this one: the
// pixel's centre unprojected with its linear view depth through this frame's camera, projected
// through the previous one, and kept only when the previous frame's depth there agrees (else the
// point was hidden or off screen then: a disocclusion). The cameras are as rendered (clip planes
// fitted) and map pixels as the rasteriser and the reference do (reference_ao.cpp, PrimaryRays).
// Pure CPU code on float arrays: no GL.
#pragma once
#include "scene/camera.h"

#include <vector>

namespace ssao {

// A pixel with no counterpart in the previous frame: hidden there (a disocclusion: it projects
// inside the previous frame, where another surface or the sky was), or off it (it enters at the
// frame's edge, or lay behind the previous eye).
constexpr int kDisoccluded = -1;
constexpr int kOffScreen = -2;

// One frame's depth: linear view depth (scene units, along the view axis) and a mask (> 0:
// geometry, else sky), width*height values, row-major, top row first.
struct DepthFrame {
    const Camera* camera = nullptr;
    const float* depth = nullptr;
    const float* geometry = nullptr;
};

// Where the surface point of pixel (x, y) at view depth `depth` of `from` lies in `to`: continuous
// pixel coordinates (pixel centres at +0.5) and its view depth there. False when it is behind
// `to`'s eye.
bool reprojectPoint(const Camera& from, const Camera& to, int width, int height, int x, int y, float depth,
                    float& toX, float& toY, float& toDepth);

// For every pixel of `current`, the index (y * width + x) of the pixel of `previous` that shows its
// surface point (the nearest of the 2x2 pixel centres around the projected point whose depth is
// within relTolerance x the expected depth); kDisoccluded when none of them agrees; kOffScreen when
// the point lies off the previous frame; kDisoccluded also for sky pixels (nothing to follow).
std::vector<int> reprojectToPrevious(const DepthFrame& current, const DepthFrame& previous, int width, int height,
                                     float relTolerance = 0.02f);

} // namespace ssao
