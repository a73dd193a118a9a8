// The per-frame time limit of headless runs: a user's shader is untrusted code on the GPU, and
// one that never ends must not hang ssaolab forever. A frame's GL work is fenced and waited for
// in slices; a monitor thread also watches the frame, since a driver call (llvmpipe waiting for a
// texture the stuck pass writes) may block before the fence is reached. Past the limit the
// context cannot be trusted or torn down (the driver's threads may spin forever), so the process
// prints one `ssaolab: error:` line and ends at once (std::_Exit: no destructors, no GL teardown).
// Only headless runs set a limit (Renderer::setFrameTimeLimit); the explorer never does.
#pragma once
#include "gl/handle.h"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace ssao::gl {

// A GL fence after the work submitted so far; deleted with it.
class Fence {
  public:
    Fence();
    ~Fence();
    Fence(const Fence&) = delete;
    Fence& operator=(const Fence&) = delete;
    // Waits (flushing first) until the work finishes or `deadline` passes; false when it passed.
    bool waitUntil(std::chrono::steady_clock::time_point deadline);

  private:
    GLsync sync_ = nullptr;
};

// The one line the run ends with: the limit, and `what` (the technique or the user's file) when
// known, e.g. "ssaolab: error: a frame took longer than N s (technique gtao: the GPU work did not
// finish; a shader that never ends?) - the run stops".
std::string frameTimeLimitLine(double seconds, const std::string& what);

class FrameWatchdog {
  public:
    explicit FrameWatchdog(double seconds); // seconds > 0
    ~FrameWatchdog();
    FrameWatchdog(const FrameWatchdog&) = delete;
    FrameWatchdog& operator=(const FrameWatchdog&) = delete;
    double seconds() const { return seconds_; }

    // One frame, watched from construction (`what`: the technique or the user's file); a null
    // watchdog watches nothing.
    class Frame {
      public:
        Frame(FrameWatchdog* w, std::string what);
        ~Frame(); // the frame is over: nothing watched until the next
        Frame(const Frame&) = delete;
        Frame& operator=(const Frame&) = delete;
        // After the frame's GL work is submitted: waits for it within the limit, else ends the run.
        void waitForGpu();

      private:
        FrameWatchdog* w_;
        std::chrono::steady_clock::time_point deadline_;
    };

  private:
    [[noreturn]] void expire();
    void monitor();

    double seconds_;
    std::mutex m_;
    std::condition_variable cv_;
    bool armed_ = false, stop_ = false;
    std::chrono::steady_clock::time_point deadline_;
    std::string what_;
    std::thread thread_; // last: started once the members above exist
};

} // namespace ssao::gl
