// Tangent frame around the unit normal n, rotated by the random vector r. Gram–Schmidt as in
// the seeds (t = r - n(r·n)), except when r is (nearly) parallel to n or zero: there the seeds'
// normalize(0) is NaN, so fall back to Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited" (JCGT 6(1)), listing 3. Mirrored on the CPU by ssao::tangentFrame (tested there).
mat3 tangentFrame(vec3 n, vec3 r) {
    vec3 t = r - n * dot(r, n);
    float len2 = dot(t, t);
    if (len2 > 1e-6) {
        t *= inversesqrt(len2);
    } else {
        float s = n.z >= 0.0 ? 1.0 : -1.0;
        float a = -1.0 / (s + n.z);
        float b = n.x * n.y * a;
        t = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    }
    return mat3(t, cross(n, t), n);
}
