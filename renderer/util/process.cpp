#include "util/process.h"

#include "util/error.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <optional>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace ssao {

namespace {

constexpr size_t kMaxCaptured = size_t(1) << 20;

// The child's end of one stream: /dev/null, or the write end of `pipeFds`.
void redirect(posix_spawn_file_actions_t& fa, ChildStream how, int target, const int pipeFds[2]) {
    if (how == ChildStream::Discard) posix_spawn_file_actions_addopen(&fa, target, "/dev/null", O_WRONLY, 0);
    if (how == ChildStream::Capture) {
        posix_spawn_file_actions_adddup2(&fa, pipeFds[1], target);
        posix_spawn_file_actions_addclose(&fa, pipeFds[0]);
    }
}

using Clock = std::chrono::steady_clock;

// Milliseconds left until `deadline` (-1: none, as poll takes it).
int msLeft(const std::optional<Clock::time_point>& deadline) {
    if (!deadline) return -1;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(*deadline - Clock::now()).count();
    return int(std::max<long long>(0, std::min<long long>(left, 1 << 30)));
}

// Waits for `pid`, killing it at the deadline; returns its wait status.
int reap(pid_t pid, const std::optional<Clock::time_point>& deadline, bool& timedOut) {
    int status = 0;
    for (;;) {
        const pid_t r = ::waitpid(pid, &status, deadline && !timedOut ? WNOHANG : 0);
        if (r == pid) return status;
        if (r < 0 && errno != EINTR) return status;
        if (r == 0 && msLeft(deadline) == 0) {
            ::kill(pid, SIGKILL);
            timedOut = true;
        } else if (r == 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
}

// Starts argv[0] (on PATH when it holds no '/') with `fa`'s streams, which it then frees: its pid,
// or -1. glibc's posix_spawnp returns the exec's failure (a missing program) as its own result.
pid_t spawn(const std::vector<std::string>& argv, posix_spawn_file_actions_t& fa) {
    std::vector<char*> args;
    for (const auto& a : argv)
        args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = -1;
    const int rc = posix_spawnp(&pid, args[0], &fa, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    return rc == 0 ? pid : -1;
}

} // namespace

ProgramRun runProgram(const std::vector<std::string>& argv, ChildStream out, ChildStream err, double timeoutSeconds) {
    ProgramRun run;
    if (argv.empty()) return run;
    int fds[2] = {-1, -1};
    const bool capture = out == ChildStream::Capture || err == ChildStream::Capture;
    if (capture && ::pipe2(fds, O_CLOEXEC) != 0) return run;
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    redirect(fa, out, 1, fds);
    redirect(fa, err, 2, fds);
    const pid_t pid = spawn(argv, fa);
    if (capture) ::close(fds[1]);
    if (pid > 0) {
        run.started = true;
        std::optional<Clock::time_point> deadline;
        if (timeoutSeconds > 0)
            deadline = Clock::now() + std::chrono::microseconds(static_cast<long long>(timeoutSeconds * 1e6));
        char buf[4096];
        while (capture) {
            if (deadline && msLeft(deadline) == 0) { // a child that never stops writing still meets its limit
                ::kill(pid, SIGKILL);
                run.timedOut = true;
                break;
            }
            pollfd p{fds[0], POLLIN, 0};
            const int ready = ::poll(&p, 1, msLeft(deadline));
            if (ready < 0 && errno == EINTR) continue;
            if (ready == 0) { // the time limit, with the stream still open
                ::kill(pid, SIGKILL);
                run.timedOut = true;
                break;
            }
            const ssize_t n = ready < 0 ? -1 : ::read(fds[0], buf, sizeof buf);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) break;
            run.out.append(buf, std::min(size_t(n), kMaxCaptured - std::min(kMaxCaptured, run.out.size())));
        }
        const int status = reap(pid, deadline, run.timedOut);
        run.exitCode = !run.timedOut && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    if (capture) ::close(fds[0]);
    return run;
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, double exitSeconds) : exitSeconds_(exitSeconds) {
    if (argv.empty()) return;
    int in[2] = {-1, -1}, out[2] = {-1, -1};
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, in) != 0) return;
    if (::pipe2(out, O_CLOEXEC) != 0) {
        ::close(in[0]), ::close(in[1]);
        return;
    }
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, in[1], 0);
    posix_spawn_file_actions_adddup2(&fa, out[1], 1);
    posix_spawn_file_actions_adddup2(&fa, out[1], 2);
    const pid_t pid = spawn(argv, fa);
    ::close(in[1]), ::close(out[1]);
    if (pid <= 0) {
        ::close(in[0]), ::close(out[0]);
        return;
    }
    pid_ = pid, in_ = in[0], outFd_ = out[0];
}

ChildProcess::~ChildProcess() {
    finish();
    if (outFd_ >= 0) ::close(outFd_);
}

bool ChildProcess::writeLine(const std::string& line) {
    if (in_ < 0) return false;
    const std::string text = line + "\n";
    for (size_t done = 0; done < text.size();) {
        const ssize_t n = ::send(in_, text.data() + done, text.size() - done, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += size_t(n);
    }
    return true;
}

std::optional<std::string> ChildProcess::readLine() {
    for (;;) {
        if (const size_t nl = pending_.find('\n'); nl != std::string::npos) {
            std::string line = pending_.substr(0, nl);
            pending_.erase(0, nl + 1);
            return line;
        }
        if (outFd_ < 0) return std::nullopt;
        char buf[4096];
        const ssize_t n = ::read(outFd_, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) { // closed: a last line without its newline still comes back
            ::close(outFd_);
            outFd_ = -1;
            if (pending_.empty()) return std::nullopt;
            std::string line;
            line.swap(pending_);
            return line;
        }
        keep(buf, size_t(n));
    }
}

int ChildProcess::finish() {
    if (in_ >= 0) ::close(in_), in_ = -1; // a serving child ends with its input
    if (pid_ > 0 && !reaped_) {
        const auto deadline = Clock::now() + std::chrono::milliseconds(static_cast<long long>(exitSeconds_ * 1e3));
        int status = 0;
        bool killed = false;
        for (;;) { // read what it still writes while it ends, so a full pipe never holds it
            const pid_t r = ::waitpid(pid_, &status, WNOHANG);
            if (r == pid_ || (r < 0 && errno != EINTR)) break;
            if (!killed && Clock::now() >= deadline) ::kill(pid_, SIGKILL), killed = true;
            drain(20);
        }
        exitCode_ = !killed && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        reaped_ = true;
    }
    drain(0);
    return exitCode_;
}

// Whatever the child wrote that is ready within `ms` (a descendant may keep the pipe open: never
// read until it closes).
void ChildProcess::drain(int ms) {
    if (outFd_ < 0) {
        if (ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(ms));
        return;
    }
    pollfd p{outFd_, POLLIN, 0};
    if (::poll(&p, 1, ms) <= 0) return;
    char buf[4096];
    const ssize_t n = ::read(outFd_, buf, sizeof buf);
    if (n <= 0) {
        ::close(outFd_);
        outFd_ = -1;
        return;
    }
    keep(buf, size_t(n));
}

void ChildProcess::keep(const char* data, size_t n) {
    constexpr size_t kKept = size_t(64) << 10;
    pending_.append(data, n);
    out_.append(data, n);
    if (out_.size() > kKept) out_.erase(0, out_.size() - kKept);
}

// A sanitizer's shadow memory takes terabytes of address space: no rlimit can hold it.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SSAO_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define SSAO_SANITIZED 1
#endif
#endif

void limitAddressSpace(unsigned mib) {
#ifdef SSAO_SANITIZED
    // A thread watches the peak resident memory instead: past `mib` MiB more than at the start (the
    // sanitizer's own share), the process ends as a killed one would.
    auto peakKiB = [] {
        rusage u{};
        ::getrusage(RUSAGE_SELF, &u);
        return static_cast<long long>(u.ru_maxrss);
    };
    const long long limit = peakKiB() + (static_cast<long long>(mib) << 10);
    std::thread([peakKiB, limit] {
        for (;;) {
            if (peakKiB() > limit) ::_exit(137);
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }).detach();
#else
    rlimit r{};
    if (::getrlimit(RLIMIT_DATA, &r) != 0) throw Error("cannot read this process's memory limit");
    const rlim_t want = rlim_t(mib) << 20; // only ever lowered: an inherited lower limit stays
    r.rlim_max = r.rlim_max == RLIM_INFINITY ? want : std::min(r.rlim_max, want);
    r.rlim_cur = r.rlim_cur == RLIM_INFINITY ? r.rlim_max : std::min(r.rlim_cur, r.rlim_max);
    if (::setrlimit(RLIMIT_DATA, &r) != 0) throw Error("cannot limit this process's memory to " + std::to_string(mib) + " MiB");
#endif
}

} // namespace ssao
