// What every AO technique shares: the radius in world units at a pixel and the final contrast.
// Expects `AoCommon_ common` in the technique's constant block (bindings.h).

// World-space radius for a pixel at view distance `depth` (scene units, positive).
// Screen mode keeps the kernel at radiusPx pixels wherever the pixel is (N8AO screenSpaceRadius).
float aoRadius(AoCommon_ c, float depth) {
    return int(c.radius.z) == SSAO_RADIUS_SCREEN ? c.radius.y * c.radius.w * depth : c.radius.x;
}

// Seed 001's contrast: AO = visibility^power (its 1 - (1 - occ/N)^power is the occlusion).
float aoFinish(AoCommon_ c, float visibility) {
    return pow(clamp(visibility, 0.0, 1.0), c.shape.x);
}
