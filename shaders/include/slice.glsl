// One slice of the slice-based horizon techniques (GTAO, visibility bitmask): Jimenez et al. 2016,
// laid out like XeGTAO's MainPass. A slice is the plane through the view vector V and the screen
// direction omega; angles in it are measured from V, positive toward omega.

const float PI = 3.14159265358979;
const float HALF_PI = 1.57079632679490;

// acos of a cosine that rounding may have pushed past ±1 (acos(1 + ε) is NaN on llvmpipe).
float safeAcos(float x) { return acos(clamp(x, -1.0, 1.0)); }

struct AoSlice {
    vec2 omega;      // screen direction (pixel space, y up like view space)
    float projNLen;  // length of the normal projected into the slice: the slice's weight
    float cosN;      // cos of the projected normal's angle from V
    float n;         // that angle, signed (the paper's gamma)
    vec3 axis;       // unit normal of the slice plane
    vec3 slide;      // (axis - N (axis.N)) / projNLen^2: see aoSliceDelta
};

AoSlice aoSlice(float phi, vec3 V, vec3 N) {
    AoSlice s;
    s.omega = vec2(cos(phi), sin(phi));
    vec3 dirV = vec3(s.omega, 0.0);
    // The slice plane holds V and dirV; project the normal into it.
    vec3 orthoDir = dirV - dot(dirV, V) * V;
    vec3 axis = normalize(cross(orthoDir, V));
    vec3 projN = N - axis * dot(N, axis);
    s.projNLen = length(projN);
    s.cosN = clamp(dot(projN, V) / max(s.projNLen, 1e-6), 0.0, 1.0);
    s.n = sign(dot(orthoDir, projN)) * safeAcos(s.cosN);
    s.axis = axis;
    // axis's part within the tangent plane; its dot with axis is 1 - (axis.N)^2 = projNLen^2.
    float along = s.projNLen * s.projNLen;
    s.slide = along > 1e-4 ? (axis - N * dot(axis, N)) / along : vec3(0.0);
    return s;
}

// A sample snapped to a texel centre lies up to half a pixel off the slice plane. Measured from V
// as it is, a sample on the pixel's own tangent plane then reads as a horizon above the slice's
// tangent line (with one slice an open plane came out hatched, mean 0.90). Sliding it along the
// tangent plane into the slice puts such a sample exactly on the tangent line, keeps a sample at
// height h above the plane at h, and leaves a sample already in the slice where it is. (A slice
// almost perpendicular to the normal, projNLen ~ 0, weighs nothing and is left unslid.)
vec3 aoSliceDelta(AoSlice s, vec3 delta) { return delta - s.slide * dot(delta, s.axis); }

// The slices' visible measure over their open measure (both weighted by projNLen). A single slice's
// open measure projNLen (cos n + n sin n) is 1 only on average over the slice angle (Jimenez 2016,
// eq. 10 integrated over phi): dividing by the slice count, as XeGTAO does, leaves an open plane
// at 0.3..1.4 per pixel with one slice (a mean of 0.90 after the clamp to 1). Over the open
// measure of the same slices it is exactly 1 on any open surface at any slice count, never above
// 1, and converges to the same integral as the slices grow (a ratio estimator).
float aoSliceRatio(float visible, float open) { return open > 1e-6 ? clamp(visible / open, 0.0, 1.0) : 1.0; }
