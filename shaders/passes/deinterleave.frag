#version 450 core
// Deinterleaved AO (renderer/techniques/deinterleave.h): 8 of the 16 quarter-size layers of a
// G-buffer target at once; layer l = i + 4j holds the pixel (4x + i, 4y + j) at texel (x, y).
// Texels past the frame are sky (w = 0) and face the camera.
#include "include/bindings.h"

layout(binding = SSAO_TEX_VIEW_SOURCE) uniform sampler2D uSource;
layout(location = 0) uniform int uFirstLayer; // 0 or 8

layout(location = 0) out vec4 o0;
layout(location = 1) out vec4 o1;
layout(location = 2) out vec4 o2;
layout(location = 3) out vec4 o3;
layout(location = 4) out vec4 o4;
layout(location = 5) out vec4 o5;
layout(location = 6) out vec4 o6;
layout(location = 7) out vec4 o7;

vec4 layerTexel(int l) {
    ivec2 p = ivec2(gl_FragCoord.xy) * 4 + ivec2(l & 3, l >> 2);
    return all(lessThan(p, textureSize(uSource, 0))) ? texelFetch(uSource, p, 0) : vec4(0.0, 0.0, 1.0, 0.0);
}

void main() {
    o0 = layerTexel(uFirstLayer);
    o1 = layerTexel(uFirstLayer + 1);
    o2 = layerTexel(uFirstLayer + 2);
    o3 = layerTexel(uFirstLayer + 3);
    o4 = layerTexel(uFirstLayer + 4);
    o5 = layerTexel(uFirstLayer + 5);
    o6 = layerTexel(uFirstLayer + 6);
    o7 = layerTexel(uFirstLayer + 7);
}
