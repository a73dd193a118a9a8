// The MASK alpha test of the scene passes, texel for texel the C++ of renderer/scene/alpha_mask.h
// (the reference's Embree filter): nearest texel, no MIP maps, the sampler's wrap modes. Built in
// only with ALPHA_MASK (renderer/scene/gpu/gpu_scene.h ScenePrograms): a shader that may discard loses
// the early depth test, so opaque draws use the variant without it.
#ifndef SSAO_ALPHA_MASK_GLSL
#define SSAO_ALPHA_MASK_GLSL
#ifdef ALPHA_MASK
#include "include/bindings.h"

layout(binding = SSAO_TEX_SCENE_ALPHA) uniform sampler2D uAlphaTexture; // R8: the texture's alpha
layout(location = 1) uniform vec4 uAlphaTest; // x cutoff, y factor alpha, z 1 = read the texture
layout(location = 2) uniform ivec2 uAlphaWrap; // S, T: 0 repeat, 1 clamp to edge, 2 mirrored repeat

int alphaWrapTexel(float t, int n, int mode) {
    float f = floor(t * float(n));
    int i = abs(f) < 1e9 ? int(f) : 0;
    if (mode == 1) return clamp(i, 0, n - 1);
    if (mode == 2) {
        int m = ((i % (2 * n)) + 2 * n) % (2 * n);
        return m < n ? m : 2 * n - 1 - m;
    }
    return ((i % n) + n) % n;
}

// Discards the fragment where the surface is cut out: factor x texture alpha below the cutoff.
void alphaMaskTest(vec2 uv) {
    float a = uAlphaTest.y;
    if (uAlphaTest.z > 0.5) {
        ivec2 size = textureSize(uAlphaTexture, 0);
        ivec2 p = ivec2(alphaWrapTexel(uv.x, size.x, uAlphaWrap.x), alphaWrapTexel(uv.y, size.y, uAlphaWrap.y));
        a *= texelFetch(uAlphaTexture, p, 0).r;
    }
    if (a < uAlphaTest.x) discard;
}
#else
void alphaMaskTest(vec2 uv) {}
#endif
#endif
