// What one frame of the graph did, as plain data (no GL): which passes ran, were clean or were
// culled, their GPU times and counters.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace ssao {

struct PassReport {
    std::string name;
    bool ran = false;
    bool culled = false; // not run: nothing wanted reads its outputs (FrameGraph::setWanted)
    double gpuMs = -1.0; // GL_TIME_ELAPSED of this frame's run; -1 when skipped
    std::vector<std::pair<std::string, double>> counters; // Pass::counters() of this frame's run
};

struct FrameReport {
    std::vector<PassReport> passes; // in execution order
    std::vector<std::string> ran() const {
        std::vector<std::string> out;
        for (const auto& p : passes)
            if (p.ran) out.push_back(p.name);
        return out;
    }
};

} // namespace ssao
