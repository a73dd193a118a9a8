// Colours the view painter (display/view.frag) and the CPU image writers (output/) share, so a
// preview and a file of the same buffer look alike. Plain #defines: read by GLSL and C++.
#ifndef SSAO_VIEW_COLORS_H
#define SSAO_VIEW_COLORS_H

// Sky (no geometry) in every scalar or vector view: dark grey, so a silhouette against the sky
// stays visible in an AO image, where open surfaces are white.
#define SSAO_SKY_GREY 0.12

#endif
