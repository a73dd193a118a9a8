// What every AO technique shares: the radius in world units at a pixel and the final contrast.
// Expects `AoCommon_ common` in the technique's constant block (bindings.h).

// World-space radius for a pixel at view distance `depth` (scene units, positive).
// Screen mode keeps the kernel at radiusPx pixels wherever the pixel is (N8AO screenSpaceRadius).
float aoRadius(AoCommon_ c, float depth) {
    return int(c.radius.z) == SSAO_RADIUS_SCREEN ? c.radius.y * c.radius.w * frameDepthScale(depth) : c.radius.x;
}

// aoLoops: the techniques' sample loops are do-whiles that test at their end, not fors that test
// at their top. llvmpipe runs a shader's lanes together under a mask: a for loop's break clears the
// mask, yet the body runs once more with every lane off before the loop ends (its taps, reads and
// angles all computed, then discarded), so slices x steps would take slices x (steps + 1) + 1
// passes; a do-while gives the same AO to the last bit. A loop whose count may be 0 is guarded by an if.

// Seed 001's contrast: AO = visibility^power (its 1 - (1 - occ/N)^power is the occlusion).
// AO_POWER_ONE (ao_pass.cpp aoFeatureDefines, where the packed power is 1): no pow, which on
// llvmpipe is an exp2 and a log2 per pixel and returns x only to rounding.
float aoFinish(AoCommon_ c, float visibility) {
#ifdef AO_POWER_ONE
    return clamp(visibility, 0.0, 1.0);
#else
    return pow(clamp(visibility, 0.0, 1.0), c.estimator.x);
#endif
}

// The G-buffer texel an AO pixel stands for, as a uv at that texel's centre. At half or quarter
// resolution an AO pixel's centre falls exactly on a boundary between G-buffer texels, where
// nearest sampling picks either side by rounding: the pixel's own position and its taps (offset
// by whole G-buffer pixels) would then disagree from pixel to pixel, drawing stripes. The -0.25
// picks the texel below-left of a boundary at every resolution and the texel itself at full size.
vec2 aoPixelUv(vec2 uv) {
    return (floor(uv * frame.viewport.xy - 0.25) + 0.5) * frame.viewport.zw;
}

// Distance in depth from P to a neighbour that can stand in for it: a sky texel or one off the
// image is never chosen.
float aoNeighbourGap(vec4 S, vec2 uv, vec3 P) {
    bool inside = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
    return inside && S.w != 0.0 ? abs(S.z - P.z) : 1e30;
}

// The pixel's unit view-space normal: decoded from the G-buffer, or (estimator.z = SSAO_NORMALS_DEPTH)
// reconstructed from the positions alone. The reconstruction takes, on each axis, the neighbour
// whose depth is closer to the pixel's (the one on the same surface): a naive cross product of
// screen derivatives mixes the two sides of a silhouette and bends the normal of every edge pixel.
vec3 aoNormal(AoCommon_ c, sampler2D positions, sampler2D normals, vec2 uv, vec3 P) {
    vec3 N;
#ifdef AO_NORMALS_DEPTH // compiled in only with that estimator (ao_pass.cpp aoFeatureDefines)
    if (int(c.estimator.z) == SSAO_NORMALS_DEPTH) {
        // Whole texels around the pixel's own texel (see aoPixelUv), never a boundary.
        vec2 t = 1.0 / vec2(textureSize(positions, 0));
        uv = (floor(uv / t - 0.25) + 0.5) * t;
        P = textureLod(positions, uv, 0.0).xyz;
        vec2 uvL = uv - vec2(t.x, 0.0), uvR = uv + vec2(t.x, 0.0);
        vec2 uvD = uv - vec2(0.0, t.y), uvU = uv + vec2(0.0, t.y);
        vec4 L = textureLod(positions, uvL, 0.0), R = textureLod(positions, uvR, 0.0);
        vec4 D = textureLod(positions, uvD, 0.0), U = textureLod(positions, uvU, 0.0);
        float gL = aoNeighbourGap(L, uvL, P), gR = aoNeighbourGap(R, uvR, P);
        float gD = aoNeighbourGap(D, uvD, P), gU = aoNeighbourGap(U, uvU, P);
        vec3 dx = gL < gR ? P - L.xyz : R.xyz - P;
        vec3 dy = gD < gU ? P - D.xyz : U.xyz - P;
        N = cross(dx, dy);
        vec3 V = frameViewVector(P);
        if (min(gL, gR) >= 1e30 || min(gD, gU) >= 1e30 || !(dot(N, N) > 1e-36)) N = V; // isolated pixel
        N = normalize(N);
        return dot(N, V) < 0.0 ? -N : N; // face the camera, as the G-buffer's normals do
    }
#endif
    N = texture(normals, uv).xyz;
    if (c.flags.z != 0.0) N = N * 2.0 - 1.0; // an RGBA8 target stores (n+1)/2
    float l2 = dot(N, N);
    return l2 > 1e-12 ? N * inversesqrt(l2) : vec3(0.0, 0.0, 1.0);
}

// Sky pixels (no geometry: position w = 0) are unoccluded. With skip.sky (common.flags.x = 1, the
// default) they return 1 at once; without, they run the whole estimate on a stand-in surface facing
// the camera two scene radii away and AO_RESULT discards it: the same image, and the time shows
// what the skip saves (`ssaolab skips`). A uniform, not a shader variant: geometry pixels run the
// same compiled code either way (two variants may round a multiply-add differently and flip a
// sample's depth test). The optional inputs (pyramid, guard band, back-face layer, normals from
// depth) are variants instead (AO_* defines, ao_pass.cpp aoFeatureDefines): they are other
// settings, not a skip measured against the same frame, and on llvmpipe a uniform branch costs.
#define AO_SKY_EARLY_OUT(P4, uv)                                                                   \
    bool aoSky = P4.w == 0.0;                                                                      \
    if (aoSky && ssao.aoCommon.flags.x != 0.0) {                                                   \
        oAO = 1.0;                                                                                 \
        INSPECT_RESULT(false, vec3(0.0), vec3(0.0), 0.0, 1.0, 0.0, 1.0);                           \
        return;                                                                                    \
    }                                                                                              \
    if (aoSky) P4 = vec4(frameViewPosition(uv, 2.0 * frame.clip.z), 1.0);
#define AO_RESULT(v) (aoSky ? max((v), 1.0) : (v))

// Pixels of the frame per pixel of what the pass is drawn over: 4 over the quarter-size layers of
// deinterleaved sampling (AO_DEINTERLEAVED, renderer/techniques/deinterleave.h), where frame.viewport
// is the layer's size and a radius in pixels comes out in layer pixels; 1 otherwise.
#ifdef AO_DEINTERLEAVED
const float aoFramePixels = 4.0;
#else
const float aoFramePixels = 1.0;
#endif

// Adaptive sample counts (ao.adaptive; common.flags.y = pixels per sample, 0 = off): the rule of
// include/adaptive.h, which C++ shares. `radiusPx` in pixels of what the pass is drawn over; the
// rule counts frame pixels.
#include "include/adaptive.h"
int aoAdaptiveSteps(AoCommon_ c, int steps, float radiusPx) {
    return adaptiveSteps(c.flags.y, steps, radiusPx * aoFramePixels);
}
int aoAdaptiveSamples(AoCommon_ c, int samples, float radiusPx) {
    return adaptiveSamples(c.flags.y, samples, radiusPx * aoFramePixels);
}
