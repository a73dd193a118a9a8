// The explorer's watch over the user's technique folder (renderer/techniques/user/user_folder.h):
// each NAME.ao.glsl whose text changes (or that appears) is checked in-process (its header and
// body rules), then probed in a child process - `ssaolab probe-technique FILE` renders two frames
// at the explorer's render size under a per-frame time limit (a shader too slow for the explorer's
// frames fails it), the whole probe under a wall-clock and a memory limit, handed the bytes that
// were checked here - and only a
// version that passed is adopted (techniques/technique.h setUserTechniques). A version that fails
// is named with its reason (FILE:LINE, or the time limit) and the last good one keeps running, so
// a shader that never ends or crashes the driver cannot freeze or end the explorer.
#pragma once
#include "measure/latest_job.h"

#include <chrono>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ssao {

struct UserTechnique;

class TechniqueWatch {
  public:
    static constexpr double kFrameLimitS = 5; // the probe's --frame-time-limit (its time and memory: cli/untrusted_child.h)

    // `dir`: the folder the run's techniques came from ("" = none to watch); `program`: the ssaolab
    // binary that probes; `wake` is called from the probe's thread when it has finished.
    TechniqueWatch(std::string dir, std::string program, std::function<void()> wake);
    ~TechniqueWatch();

    struct News {
        std::vector<std::string> adopted; // "user.NAME (FILE)" of each version now running
        std::vector<std::string> errors;  // one line each: FILE:LINE: why, and that the last good one runs
        bool probing = false;             // a probe is still running
    };
    // Reads the folder (call it a few times a second) and takes a finished probe's verdict; a new
    // version is probed at `width` x `height`, the size the explorer renders at.
    News poll(int width, int height);

  private:
    struct Job {
        std::string key, path, hash, text;
        int width = 0, height = 0;
    };
    struct State {
        std::string key;
        unsigned version = 0;
        bool done = false, ok = false;
        std::string message; // the child's error line, or why it gave none
    };
    struct Candidate {
        std::string path, hash, text;
    };
    void scan(News& news);
    void forget(const std::string& path); // its file gone or no longer a regular file: its pending version is dropped
    void finish(const State& s, News& news);
    void adopt(const Candidate& c, News& news);

    std::string dir_, program_;
    std::map<std::string, std::string> seen_; // path -> hash of the text last read
    std::deque<Candidate> queue_;             // checked in-process, waiting for their probe
    std::optional<Candidate> probing_;
    bool probingDropped_ = false; // its file changed kind or went away while it was probed: never adopted
    std::unique_ptr<LatestJob<Job, State>> worker_;
};

} // namespace ssao
