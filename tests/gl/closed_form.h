// What tests judge AO against: closed forms of cosine-weighted visibility within R (the reference's
// definition), the builtin:corner profile, and the ray-traced reference of a rendered view.
#pragma once
#include "gl_fixture.h"
#include "metrics/evaluate.h"
#include "reference/embree_scene.h"

#include <string>

namespace ssaotest {

// AO of a floor point at distance d from an infinite wall: 1 - (acos a - a sqrt(1 - a^2)) / pi,
// a = min(d / R, 1).
double wallClosedForm(double d, double R);

// The denoised AO along the floor of builtin:corner (17 centre columns, 320x240), averaged in 5 cm
// bins of wall distance out to 2 R.
struct CornerProfile {
    double rmse = 0;    // against the closed form, over the bins
    double atWall = 0;  // mean AO of the bins within 0.1 R of the wall
    double far = 0;     // mean AO of the bins between 1.5 R and 2 R (the closed form is 1 there)
    size_t bins = 0;
};
// `scene`: builtin:corner, or builtin:hidden (the same floor and wall, the wall hidden by a plate).
CornerProfile cornerProfile(const ssao::Settings& s, const std::string& scene = "builtin:corner");
inline double cornerRmse(const ssao::Settings& s) { return cornerProfile(s).rmse; }

// The renderer's last frame (ao.denoised) against the visibility reference of its camera, size
// and radius, traced with `rays` per pixel.
ssao::Evaluation judgeAgainstReference(ssao::Renderer& r, const ssao::EmbreeScene& rt, int rays);

} // namespace ssaotest
