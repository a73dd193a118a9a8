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
    return s;
}
