// Per-pixel noise of the horizon techniques: two values in [0,1) for a pixel, of the kind in
// AoCommon.estimator.y (SSAO_NOISE_*; renderer/techniques/noise/noise.h). Each kind moves with the
// temporal frame index (frame.clip.w), so accumulated frames average different patterns.
// Needs frame.glsl and bindings.h.

layout(binding = SSAO_TEX_BLUE_NOISE) uniform sampler2D aoBlueNoise;

// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare"): a value whose 3x3 neighbourhoods are well spread.
float aoIgn(vec2 p) {
    return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715))));
}

// A hash of an integer pair to [0,1) (Jarzynski & Olano 2020, PCG-style), for the 4x4 tile.
float aoHash(uvec2 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * 1664525u;
    v.y += v.x * 1664525u;
    v ^= v >> 16u;
    v.x += v.y * 1664525u;
    v.y += v.x * 1664525u;
    v ^= v >> 16u;
    return float(v.x >> 8u) * (1.0 / 16777216.0);
}

// The kind, a constant where the variant fixes it (AO_NOISE: ao_pass.cpp aoFeatureDefines, from the
// same packed word): llvmpipe would otherwise run every case of the switch below.
int aoNoiseKind(AoCommon_ c) {
#ifdef AO_NOISE
    return AO_NOISE;
#else
    return int(c.estimator.y);
#endif
}

// Whether the technique asked for noise at all (none: one fixed pattern, banding).
bool aoNoiseOn(AoCommon_ c) { return aoNoiseKind(c) != SSAO_NOISE_NONE; }

#ifdef AO_DEINTERLEAVED
// Deinterleaved AO (ao.deinterleave, renderer/techniques/deinterleave.h): the layer's cell (i, j)
// of the 4x4 tile. Every pixel of a layer takes the noise of that cell: one jitter a layer, as
// HBAO+'s 4x4 jitter texture, so neighbouring lanes tap neighbouring texels.
layout(location = SSAO_LOC_AO_LAYER_CELL) uniform vec2 uAoLayerCell;
#endif

vec2 aoNoise(AoCommon_ c, vec2 fragCoord) {
#ifdef AO_DEINTERLEAVED
    fragCoord = uAoLayerCell + 0.5;
#endif
    float f = frame.clip.w; // temporal frame index (0 without accumulation)
    vec2 p = floor(fragCoord);
    // Golden-ratio steps per frame keep each pixel's sequence over time well spread (Wolfe 2022,
    // animated blue noise): every kind but IGN advances this way.
    vec2 temporalShift = fract(f * vec2(0.61803398875, 0.75487766625));
    switch (aoNoiseKind(c)) {
    case SSAO_NOISE_IGN: {
        vec2 q = fragCoord + 5.588238 * f;
        return vec2(aoIgn(q), aoIgn(q + vec2(47.0, 17.0)));
    }
    case SSAO_NOISE_R2:
        // Roberts' R2 sequence as a dither: alpha = (1/g, 1/g²), g the plastic number 1.3247...;
        // the second value walks the transposed lattice so the two are not a shifted copy.
        return fract(vec2(dot(p, vec2(0.75487766625, 0.56984029099)), dot(p.yx, vec2(0.75487766625, 0.56984029099))) +
                     temporalShift);
    case SSAO_NOISE_BLUE:
        return fract(texelFetch(aoBlueNoise, ivec2(p) & 63, 0).rg + temporalShift);
    case SSAO_NOISE_TILE4: {
        uvec2 cell = uvec2(ivec2(p) & 3);
        return fract(vec2(aoHash(cell), aoHash(cell + uvec2(4u, 9u))) + temporalShift);
    }
    }
    return vec2(0.5);
}
