#include "util/process.h"

#include <algorithm>
#include <cerrno>

#include <fcntl.h>
#include <spawn.h>
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

} // namespace

ProgramRun runProgram(const std::vector<std::string>& argv, ChildStream out, ChildStream err) {
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
    std::vector<char*> args;
    for (const auto& a : argv)
        args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = -1;
    // glibc's posix_spawnp returns the exec's failure (a missing program) as its own result.
    const int rc = posix_spawnp(&pid, args[0], &fa, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    if (capture) ::close(fds[1]);
    if (rc == 0) {
        run.started = true;
        char buf[4096];
        for (ssize_t n; capture && (n = ::read(fds[0], buf, sizeof buf)) != 0;) {
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) break;
            run.out.append(buf, std::min(size_t(n), kMaxCaptured - std::min(kMaxCaptured, run.out.size())));
        }
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    if (capture) ::close(fds[0]);
    return run;
}

} // namespace ssao
