// Joint-bilateral 2x2 upsample (Kopf, Cohen, Lischinski, Uyttendaele 2007, "Joint Bilateral
// Upsampling") of reduced-resolution AO to the G-buffer's size: each full-resolution pixel blends
// the 2x2 AO texels around it with bilinear weights times a depth-similarity weight, so AO does not
// bleed across silhouettes the way a plain bilinear upsample smears it. The depth of AO texel t is
// that of the G-buffer texel its AO pass computed it at (aoPixelUv: texel t·k, k = 2 or 4), so the
// weight compares like with like. Where no corner is similar (a thin feature the reduced AO never
// sampled) the corner nearest in depth is taken, as nearest-depth upsampling does.
// One function for its own pass (passes/upsample_joint.frag) and for the composite that does it
// inline when nothing else shows the full-resolution AO (passes/composite.frag): the same texels
// give the same value in both.

float jointDepthAt(sampler2D depth, ivec2 p, ivec2 size) { return texelFetch(depth, clamp(p, ivec2(0), size - 1), 0).r; }

// Depth change per pixel along one axis on the continuous side (the smaller of the two
// one-sided differences), so a silhouette next to the pixel does not widen its tolerance.
float jointSlope(sampler2D depth, ivec2 p, ivec2 axis, float z0, ivec2 size) {
    float a = jointDepthAt(depth, p + axis, size), b = jointDepthAt(depth, p - axis, size);
    float da = a > 0.0 ? abs(a - z0) : 1e30, db = b > 0.0 ? abs(b - z0) : 1e30;
    float d = min(da, db);
    return d < 1e29 ? d : 0.0;
}

// The AO at full-resolution pixel p from the reduced `ao`; `depth` is gbuffer.depth (linear, sky
// = 0), `curvature` the relative tolerance in 1/1000 of the depth (DenoiseConstants taps.w).
float jointUpsample(sampler2D ao, sampler2D depth, ivec2 p, int curvature) {
    ivec2 full = textureSize(depth, 0), inSize = textureSize(ao, 0);
    float z0 = texelFetch(depth, p, 0).r;
    if (!(z0 > 0.0)) return 1.0; // sky: no surface to shade
    int k = max(full.x / max(inSize.x, 1), 1); // 2 (half) or 4 (quarter resolution)
    vec2 q = vec2(p) / float(k);               // AO texel t sits at t (its G-buffer texel t·k)
    ivec2 i0 = ivec2(floor(q));
    vec2 f = q - vec2(i0);
    if (f == vec2(0.0)) { // the G-buffer texel this AO texel was computed at: its own value
        float own = texelFetch(ao, clamp(i0, ivec2(0), inSize - 1), 0).r;
        return own > 1.0 ? 1.0 : own;
    }
    // Tolerance: what a continuous surface changes over k pixels on each axis (its slope), plus
    // a relative term for curvature.
    float tol = float(k) * (jointSlope(depth, p, ivec2(1, 0), z0, full) + jointSlope(depth, p, ivec2(0, 1), z0, full)) +
                z0 * float(curvature) * 1e-3;
    float sum = 0.0, wsum = 0.0, nearestAo = 1.0, nearestGap = 1e30;
    for (int j = 0; j < 4; ++j) {
        ivec2 o = ivec2(j & 1, j >> 1);
        float bw = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        if (bw == 0.0) continue; // a corner the pixel does not lie between
        ivec2 t = clamp(i0 + o, ivec2(0), inSize - 1);
        float z = jointDepthAt(depth, t * k, full);
        if (!(z > 0.0)) continue; // a sky texel holds no AO of a surface
        float a = texelFetch(ao, t, 0).r;
        float gap = abs(z - z0);
        if (gap < nearestGap) {
            nearestGap = gap;
            nearestAo = a;
        }
        float r = gap / max(tol, 1e-30);
        float w = bw * exp(-r * r);
        sum += a * w;
        wsum += w;
    }
    float v = wsum > 1e-4 ? sum / wsum : nearestAo;
    return v > 1.0 ? 1.0 : v; // a weighted mean of ones may round past 1; a NaN stays visible
}
