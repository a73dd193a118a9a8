#version 450 core
// Maps one buffer to a displayable RGBA8 image (renderer/display/display_range.h decides the
// range). NaN and inf show as magenta so a numerical bug is impossible to miss; sky is dark grey.
// VIEW_MODE (SSAO_VIEW_*) and FALSE_COLOR are defines, one variant per mapping
// (display/view_painter.cpp): llvmpipe runs every side of a branch on a uniform, so one shader with
// all five mappings would cost each grid cell every one of them.
#ifndef VIEW_MODE
#error "VIEW_MODE must be defined (SSAO_VIEW_*)"
#endif
#include "include/bindings.h"
#include "include/view_colors.h"

layout(binding = SSAO_TEX_VIEW_SOURCE) uniform sampler2D src;
layout(binding = SSAO_TEX_VIEW_SOURCE_B) uniform sampler2D srcB;
layout(binding = SSAO_TEX_VIEW_MASK) uniform sampler2D mask; // gbuffer.depth: > 0 on geometry
layout(location = 1) uniform vec3 uLo;       // per channel: lo → 0 ...
layout(location = 5) uniform vec3 uHi;       // ... hi → 1 (scalars use x)
layout(location = 3) uniform vec2 uDecode;   // stored * x + y = value ((n+1)/2 normals: 2, -1)
layout(location = 4) uniform float uDiffScale;
layout(location = 6) uniform int uChannels;  // of the buffer: a colour difference uses all three

in vec2 vUv;
layout(location = 0) out vec4 oColor;

// Viridis (van der Walt & Smith, matplotlib 2015) through its quarter-point colours: perceptually
// uniform and readable by colour-blind users.
vec3 viridis(float t) {
    const vec3 c[5] = vec3[5](vec3(0.267, 0.005, 0.329), vec3(0.231, 0.322, 0.545), vec3(0.129, 0.569, 0.549),
                              vec3(0.369, 0.788, 0.384), vec3(0.992, 0.906, 0.145));
    float x = clamp(t, 0.0, 1.0) * 4.0;
    int i = min(int(x), 3);
    return mix(c[i], c[i + 1], x - float(i));
}

void main() {
    // The texel under this output pixel's centre: 1:1 at the buffer's size, one texel per pixel of a
    // smaller thumbnail (BufferViews paints grid cells at their own size).
    ivec2 p = ivec2(vUv * vec2(textureSize(src, 0)));
    vec4 v = texelFetch(src, p, 0);
    bool geometry = texture(mask, vUv).r > 0.0; // the mask may have another resolution
#if VIEW_MODE == SSAO_VIEW_DIFF
    v = (v - texture(srcB, vUv)) * uDecode.x; // B may have another size
#endif
    if (any(isnan(v)) || any(isinf(v))) {
        oColor = vec4(1.0, 0.0, 1.0, 1.0);
        return;
    }
    vec3 c;
    vec3 span = max(uHi - uLo, vec3(1e-30));
#if VIEW_MODE == SSAO_VIEW_COLOR
    c = v.rgb;
#elif VIEW_MODE == SSAO_VIEW_VECTOR
    c = ((v.rgb * uDecode.x + uDecode.y) - uLo) / span;
#elif VIEW_MODE == SSAO_VIEW_DIFF
    {
        float d = v.r; // the signed largest difference over the channels the buffer has
        if (uChannels >= 3) {
            d = abs(v.g) > abs(d) ? v.g : d;
            d = abs(v.b) > abs(d) ? v.b : d;
        }
        d = clamp(d * uDiffScale, -1.0, 1.0);
        c = d >= 0.0 ? mix(vec3(0.5), vec3(1.0, 0.15, 0.1), d) : mix(vec3(0.5), vec3(0.1, 0.35, 1.0), -d);
    }
#elif VIEW_MODE == SSAO_VIEW_SIGNED
    {
        // The CLI's error.png (metrics/evaluate.cpp errorHeatmap): white at 0, red above, blue below.
        float t = clamp((v.r * uDecode.x + uDecode.y) / span.x * 2.0, -1.0, 1.0);
        c = vec3(t < 0.0 ? 1.0 + t : 1.0, 1.0 - abs(t), t > 0.0 ? 1.0 - t : 1.0);
    }
#else // SSAO_VIEW_SCALAR
    float t = ((v.r * uDecode.x + uDecode.y) - uLo.x) / span.x;
#ifdef FALSE_COLOR
    c = viridis(t);
#else
    c = vec3(t);
#endif
#endif
#if VIEW_MODE != SSAO_VIEW_COLOR
    if (!geometry) c = vec3(SSAO_SKY_GREY);
#endif
    oColor = vec4(clamp(c, 0.0, 1.0), 1.0);
}
