#version 450 core
// Deinterleaved AO (renderer/techniques/deinterleave.h): each pixel (x, y) of ao.raw from its
// layer's texel in the atlas, where layer (x & 3, y & 3) fills the tile of that cell.
#include "include/bindings.h"

layout(binding = SSAO_TEX_AO) uniform sampler2D uAtlas;
layout(location = 0) uniform ivec2 uLayerSize; // ceil(frame / 4)

layout(location = 0) out float oAO;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    oAO = texelFetch(uAtlas, (p & 3) * uLayerSize + (p >> 2), 0).r;
}
