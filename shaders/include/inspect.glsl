// The sample inspector's record. A technique's shader calls INSPECT_TAP for every tap and
// INSPECT_RESULT once; both compile to nothing unless the program is built with INSPECT, which
// only the inspector's variant is (drawn for a single pixel, so no atomics are needed).
#ifdef INSPECT
layout(std430, binding = SSAO_SSBO_INSPECT) buffer InspectBlock {
    InspectHeader_ inspectHead;
    InspectTap_ inspectTaps[SSAO_INSPECT_MAX_TAPS];
};

bool inspectThisPixel() { return ivec2(gl_FragCoord.xy) == inspectHead.pixelCount.xy; }

void inspectTap(vec3 S, vec2 uv, int state, float contribution, int set) {
    if (!inspectThisPixel()) return;
    int i = inspectHead.pixelCount.z;
    inspectHead.pixelCount.z = i + 1;
    if (i < SSAO_INSPECT_MAX_TAPS) inspectTaps[i] = InspectTap_(vec4(S, contribution), vec4(uv, float(state), float(set)));
}

void inspectResult(bool geometry, vec3 P, vec3 N, float occlusion, float normaliser, float radius, float ao) {
    if (!inspectThisPixel()) return;
    inspectHead.pixelCount.w = geometry ? 1 : 0;
    inspectHead.result = vec4(ao, occlusion, normaliser, radius);
    inspectHead.position = vec4(P, 0.0);
    inspectHead.normal = vec4(N, 0.0);
}
#define INSPECT_TAP(S, uv, state, contribution, set) inspectTap(S, uv, state, contribution, set)
#define INSPECT_RESULT(geometry, P, N, occ, norm, radius, ao) inspectResult(geometry, P, N, occ, norm, radius, ao)
#else
#define INSPECT_TAP(S, uv, state, contribution, set)
#define INSPECT_RESULT(geometry, P, N, occ, norm, radius, ao)
#endif
