#include "cli/progress_bar.h"

#include <algorithm>
#include <cstdio>

#include <unistd.h>

namespace ssao {

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled), tty_(isatty(2) != 0),
      start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(double fraction) {
    if (!enabled_) return;
    fraction = std::clamp(fraction, 0.0, 1.0);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    if (tty_) {
        constexpr int kWidth = 30;
        const int filled = int(fraction * kWidth + 0.5);
        std::fprintf(stderr, "\r%s [%s%s] %3d%%  %.0f s, ETA %.0f s ", label_.c_str(),
                     std::string(size_t(filled), '#').c_str(), std::string(size_t(kWidth - filled), ' ').c_str(),
                     int(fraction * 100.0 + 0.5), elapsed, eta);
        open_ = true;
    } else {
        const int quarter = int(fraction * 4.0);
        if (quarter == lastQuarter_) return;
        lastQuarter_ = quarter;
        std::fprintf(stderr, "%s %3d%%  %.0f s, ETA %.0f s\n", label_.c_str(), quarter * 25, elapsed, eta);
    }
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (open_) std::fprintf(stderr, "\n");
    open_ = false;
}

} // namespace ssao
