// A one-line progress bar with ETA on stderr for long CLI work (reference tracing, benchmarks).
// On a terminal it redraws in place; in a log (not a TTY) it prints a line every 25 %.
#pragma once
#include <chrono>
#include <string>

namespace ssao {

class ProgressBar {
  public:
    explicit ProgressBar(std::string label, bool enabled = true);
    ~ProgressBar() { finish(); }
    void update(double fraction); // 0..1
    void finish();                // completes the line (idempotent)

  private:
    std::string label_;
    bool enabled_, tty_, open_ = false;
    int lastQuarter_ = -1;
    std::chrono::steady_clock::time_point start_;
};

} // namespace ssao
