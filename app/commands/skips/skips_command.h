// `ssaolab skips`: every skip of work a scene does not need, measured against the same frame
// without it in the same run (docs/bench/skips.md): passes re-run per dependency,
// sky pixels, adaptive sample counts, frustum culling, unused G-buffer targets, idle frames. Each
// row gives both times, their ratio and the error change (0 for exact skips).
#pragma once
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ssao {

struct SkipsOptions {
    std::vector<std::string> scenes; // default: builtin:showcase
    std::string size = "1280x720";
    int frames = 10;         // timed frames per variant (median)
    int referenceRays = 256; // for the adaptive rows' error against the reference
    std::string out = "skips-out";
    bool quiet = false;
};

void addSkipsOptions(CLI::App& cmd, SkipsOptions& o);
int runSkips(const SkipsOptions& o);

} // namespace ssao
