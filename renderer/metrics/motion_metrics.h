// Error in motion: an AO technique's frames along a camera path (scene/camera_path.h), each judged
// against its own ray-traced reference, and between frames at the pixels that show the same
// surface point (metrics/reprojection.h):
//   per-frame RMSE (geometry pixels; mean and max over the path);
//   instability: RMS over every such pixel pair of (T_k - T_k-1) - (R_k - R_k-1), the technique's
//     frame-to-frame change minus the reference's own (flicker and crawling grain; real change of
//     the AO between the two views cancels);
//   ghosting: mean |T - R| at pixels in their first ghostFrames frames after a disocclusion, against
//     the same at stable pixels (visible for longer): history that lingers where it no longer
//     belongs shows as an excess.
// Pure CPU code on plain float arrays: no GL.
#pragma once
#include <limits>
#include <string>
#include <vector>

namespace ssao {

// One frame of the path: single-channel images, row-major, top row first, width*height values.
struct MotionFrameInput {
    const float* test = nullptr;      // AO under test (NaN/inf count as 1.0, as in ErrorMetrics)
    const float* reference = nullptr; // reference AO, finite
    const float* geometry = nullptr;  // > 0 where the pixel shows geometry; null = all geometry
    const float* depth = nullptr;     // linear view depth (the per-frame edge split); may be null
    const float* referenceStdErr = nullptr; // the reference's per-pixel standard error; null = 0
    const float* exclude = nullptr;   // > 0: ambiguous reference pixel, left out of everything; null = none
    // reprojectToPrevious() of this frame against the one before: a pixel index of the previous
    // frame, kDisoccluded or kOffScreen. Unused for the first frame (may be null); null later = no pixel
    // is followed.
    const int* toPrevious = nullptr;
};

struct MotionOptions {
    int ghostFrames = 2; // a disoccluded pixel counts as fresh for its first ghostFrames frames
    // Ghosting is a mean over fresh pixels: fewer than this many back no figure (NaN, shown as
    // "n/a (K pixels)"); two pixels once printed as a ghosting of +0.6.
    long minGhostPixels = 64;
};

struct MotionMetrics {
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    int frames = 0;
    std::vector<double> frameRmse; // geometry RMSE of each frame (ErrorMetrics::rmse)
    double rmseMean = 0, rmseMax = 0, mseMean = 0; // over the frames
    // RMS of the change difference over followed pixel pairs (NaN: none); the floor bounds what the
    // references' own noise adds to it in quadrature, sqrt(mean(se_k^2 + se_k-1^2)): an upper bound,
    // as the reference's scrambled Sobol samples converge faster than its binomial standard error.
    double instability = kNaN, instabilityFloor = kNaN;
    long pairs = 0;
    // Mean |T - R|: at fresh disoccluded pixels, at stable ones, and at stable ones within 3 px of a
    // depth discontinuity (where disocclusions happen: the control for edge error); NaN when the set
    // is empty. ghosting = disoccludedMae - stableMae, NaN with fewer than minGhostPixels fresh pixels.
    double disoccludedMae = kNaN, stableMae = kNaN, stableEdgeMae = kNaN, ghosting = kNaN;
    long disoccludedPixels = 0, stablePixels = 0;
};

// The motion score, one number for ranking (bench's motion rank, the explorer's motion axis):
// sqrt(mean per-frame RMSE^2 + instability^2), the instability an RMS of its own (NaN counts as 0).
double motionScore(double rmseMean, double instability);
// Ghosting as every line prints it: "+0.0123", or "n/a (K pixels)" where too few fresh pixels back it.
std::string ghostingText(const MotionMetrics& m);
double motionScore(const MotionMetrics& m);
// What `tune --objective motion` minimises per view: the motion score squared.
double motionObjective(const MotionMetrics& m);

// Throws std::invalid_argument when a size is negative or a frame lacks test or reference.
MotionMetrics computeMotionMetrics(int width, int height, const std::vector<MotionFrameInput>& frames,
                                   const MotionOptions& opt = {});

} // namespace ssao
