#version 450 core
// One level of the position pyramid (renderer/passes/position_pyramid_pass.h): each texel keeps
// one of the 2x2 texels below it on SAO's rotated grid (McGuire, Mara, Luebke 2012, §3.2), a real
// surface point rather than an average across a silhouette. The sampler sees only the level below
// (base = max level), so texelFetch's level 0 is that level.
#include "include/bindings.h"

layout(binding = SSAO_TEX_POSITION_MIPS) uniform sampler2D finer;
layout(location = 0) out vec4 oPosition;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 src = 2 * p + ivec2((p.y & 1) ^ 1, (p.x & 1) ^ 1);
    oPosition = texelFetch(finer, min(src, textureSize(finer, 0) - 1), 0);
}
