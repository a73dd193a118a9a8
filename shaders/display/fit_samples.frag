#version 450 core
// Picks the texels a display-range fit reads (renderer/display/display_range.h fitSamples), so the
// app reads back ~65k texels instead of a whole buffer (a read-back stalls the frame for every
// byte it copies). Output texel i (row-major, uWidth =
// FitSamplePicker::kWidth wide) holds pixel p = i * stride of the source in row-major order from
// the top row, and in w the mask at that pixel (mapPixel of renderer/base/image.h, in integers as
// there); past the last sample, 0.
#include "include/bindings.h"

layout(binding = SSAO_TEX_VIEW_SOURCE) uniform sampler2D src;
layout(binding = SSAO_TEX_VIEW_MASK) uniform sampler2D mask; // gbuffer.depth: > 0 on geometry
layout(location = 0) uniform uint uStride;
layout(location = 1) uniform uint uCount;
layout(location = 2) uniform uint uWidth; // of this output

layout(location = 0) out vec4 oSample;

// renderer/base/image.h mapPixel: the pixel of a `to`-pixel axis whose span holds the centre of pixel p
// of a `from`-pixel axis.
uint mapPixel(uint p, uint from, uint to) { return min(((2u * p + 1u) * to) / (2u * from), to - 1u); }

void main() {
    uint i = uint(gl_FragCoord.y) * uWidth + uint(gl_FragCoord.x);
    if (i >= uCount) {
        oSample = vec4(0.0);
        return;
    }
    uvec2 size = uvec2(textureSize(src, 0)), msize = uvec2(textureSize(mask, 0));
    uint p = i * uStride, x = p % size.x, yTop = p / size.x;
    vec3 v = texelFetch(src, ivec2(x, size.y - 1u - yTop), 0).xyz; // GL rows run bottom-up
    uint mx = mapPixel(x, size.x, msize.x), my = mapPixel(yTop, size.y, msize.y);
    float m = texelFetch(mask, ivec2(mx, msize.y - 1u - my), 0).r;
    oSample = vec4(v, m);
}
