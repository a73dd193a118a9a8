// `ssaolab stress`: numerical stability as a measured feature. For every technique and scene it
// runs the cases of stress_cases.h and reports, per case, non-finite pixels, pixels outside [0,1],
// and for the invariance cases (scale, translation) the RMSE against the benign render; plus the
// cases a guard refuses with its message. Writes stress.json and stability.md; exits 1 when any
// image is non-finite or out of range, or an invariance case exceeds the stated RMSE.
#pragma once
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ssao {

struct StressOptions {
    std::vector<std::string> scenes;     // default: builtin:showcase
    std::vector<std::string> techniques; // default: every registered technique
    std::string size = "320x180";
    double tolerance = 0.02; // RMSE of ao.denoised against the benign render, invariance cases
    std::string out = "stress-out";
    bool quiet = false;
};

void addStressOptions(CLI::App& cmd, StressOptions& o);
int runStress(const StressOptions& o);

} // namespace ssao
