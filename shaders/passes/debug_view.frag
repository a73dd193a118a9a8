#version 450 core
// Maps one G-buffer / AO buffer to a displayable RGBA8 image. NaN and inf show as magenta so a
// numerical bug is impossible to miss; sky pixels are dark grey.
#include "include/bindings.h"

layout(binding = SSAO_TEX_VIEW_SOURCE) uniform sampler2D src;
layout(binding = SSAO_TEX_VIEW_MASK) uniform sampler2D mask;
layout(location = 0) uniform int uMode;
layout(location = 1) uniform float uScale;

layout(location = 0) out vec4 oColor;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 v = texelFetch(src, p, 0);
    bool geometry = texelFetch(mask, p, 0).w > 0.0;
    if (any(isnan(v)) || any(isinf(v))) {
        oColor = vec4(1.0, 0.0, 1.0, 1.0);
        return;
    }
    vec3 c;
    if (uMode == SSAO_VIEW_COLOR) c = v.rgb;
    else if (uMode == SSAO_VIEW_SIGNED) c = v.rgb * 0.5 + 0.5;
    else if (uMode == SSAO_VIEW_UNORM_NORMAL) c = v.rgb;
    else if (uMode == SSAO_VIEW_POSITION) c = v.rgb * uScale + 0.5;
    else c = vec3(v.r * uScale);
    if (!geometry && uMode != SSAO_VIEW_COLOR) c = vec3(0.12);
    oColor = vec4(clamp(c, 0.0, 1.0), 1.0);
}
