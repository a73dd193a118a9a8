#include "gl/frame_watchdog.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace ssao::gl {

using Clock = std::chrono::steady_clock;

Fence::Fence() : sync_(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0)) {}

Fence::~Fence() {
    if (sync_) glDeleteSync(sync_);
}

bool Fence::waitUntil(Clock::time_point deadline) {
    if (!sync_) return true; // no fence made: a GL error, reported by the run's own checks
    GLbitfield flags = GL_SYNC_FLUSH_COMMANDS_BIT;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(deadline - Clock::now());
        if (left.count() <= 0) return false;
        // Slices of at most 100 ms: a driver that ignores the timeout still wakes the monitor thread.
        const GLuint64 slice = GLuint64(std::min<long long>(left.count(), 100'000'000LL));
        const GLenum r = glClientWaitSync(sync_, flags, slice);
        flags = 0;
        if (r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED || r == GL_WAIT_FAILED) return true;
    }
}

std::string frameTimeLimitLine(double seconds, const std::string& what) {
    char n[32];
    std::snprintf(n, sizeof n, "%g", seconds);
    return std::string("ssaolab: error: a frame took longer than ") + n + " s (" + (what.empty() ? "" : what + ": ") +
           "the GPU work did not finish; a shader that never ends?) - the run stops";
}

FrameWatchdog::FrameWatchdog(double seconds) : seconds_(seconds), thread_([this] { monitor(); }) {}

FrameWatchdog::~FrameWatchdog() {
    {
        std::lock_guard<std::mutex> lock(m_);
        stop_ = true;
    }
    cv_.notify_all();
    thread_.join();
}

void FrameWatchdog::expire() {
    std::fflush(stdout);
    std::fprintf(stderr, "%s\n", frameTimeLimitLine(seconds_, what_).c_str());
    std::fflush(stderr);
    std::_Exit(1); // the stuck context cannot be destroyed: no destructors, no GL teardown
}

void FrameWatchdog::monitor() {
    std::unique_lock<std::mutex> lock(m_);
    while (!stop_) {
        if (!armed_) {
            cv_.wait(lock);
            continue;
        }
        const auto deadline = deadline_;
        cv_.wait_until(lock, deadline);
        if (armed_ && !stop_ && deadline_ == deadline && Clock::now() >= deadline) expire();
    }
}

FrameWatchdog::Frame::Frame(FrameWatchdog* w, std::string what) : w_(w) {
    if (!w_) return;
    deadline_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(w_->seconds_));
    {
        std::lock_guard<std::mutex> lock(w_->m_);
        w_->armed_ = true;
        w_->deadline_ = deadline_;
        w_->what_ = std::move(what);
    }
    w_->cv_.notify_all();
}

FrameWatchdog::Frame::~Frame() {
    if (!w_) return;
    {
        std::lock_guard<std::mutex> lock(w_->m_);
        w_->armed_ = false;
    }
    w_->cv_.notify_all();
}

void FrameWatchdog::Frame::waitForGpu() {
    if (!w_) return;
    Fence fence;
    if (!fence.waitUntil(deadline_)) {
        std::lock_guard<std::mutex> lock(w_->m_);
        w_->expire();
    }
}

} // namespace ssao::gl
