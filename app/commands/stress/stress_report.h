// The results of `ssaolab stress` (one row per scene, technique and case) and their files:
// stress.json (every row) and stability.md (per scene and axis, cases down, techniques across).
#pragma once
#include <string>
#include <vector>

namespace ssao {

struct StressRow {
    std::string scene, technique, axis, variant;
    std::string status;  // "ok", or "refused" (a guard's clear error: message)
    std::string message;
    bool invariant = false; // must match the benign render within the tolerance
    bool compared = false;  // the RMSE against the benign render is reported, not required
    long nonFinite = 0, outside = 0; // over ao.raw and ao.denoised, every pixel
    long geometry = 0;               // geometry pixels
    double mean = 1.0;               // mean denoised AO over geometry
    double rmse = 0.0, coverage = 0.0; // invariant and compared cases: against the benign render
    // Cases that change settings are also judged on an open plane (builtin:plane), whose AO is 1:
    // its mean denoised AO (-1 = not judged), and why the settings are unphysical by design when
    // the technique declares so (then a dark plane is expected, not a failure).
    double planeMean = -1.0;
    std::string unphysical;
    bool planeFails() const { return planeMean >= 0.0 && planeMean < 0.99 && unphysical.empty(); }
};

struct StressRun {
    std::string size;
    double tolerance = 0.02;
    std::vector<StressRow> rows;
};

struct StressVerdict {
    long nonFinite = 0, outside = 0;
    int invarianceFailures = 0, refused = 0;
    int planeFailures = 0; // cases that darken an open plane below 0.99
    bool ok() const { return nonFinite == 0 && outside == 0 && invarianceFailures == 0 && planeFailures == 0; }
};
StressVerdict verdict(const StressRun& run);

std::string stabilityMarkdown(const StressRun& run);
void writeStressFiles(const StressRun& run, const std::string& dir);

} // namespace ssao
