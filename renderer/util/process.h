// Starting another program (git, python3, chromium) from an argv vector with posix_spawnp: never
// through a shell, so a name holding quotes, `$(...)`, backticks, ';' or newlines is one argument and
// nothing else (tests/cpu/test_file_gate.cpp fails on any call of the C library's shell runners in
// app/ and renderer/).
#pragma once
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace ssao {

// Where a child's stdout or stderr goes. Its stdin is always /dev/null.
enum class ChildStream { Inherit, Discard, Capture };

struct ProgramRun {
    bool started = false; // false: the program was not found or could not be started
    int exitCode = -1;    // -1 when it did not exit normally (a signal)
    std::string out;      // what it wrote to a captured stream, at most 1 MiB
    bool timedOut = false; // it was still running at the time limit and was killed
};

// Runs argv[0] (looked up on PATH when it holds no '/') with argv and this process's environment
// and waits for it. A captured stream is read until the child closes it. With `timeoutSeconds` > 0
// a child still running that long after its start is killed (SIGKILL) and reported as timed out.
ProgramRun runProgram(const std::vector<std::string>& argv, ChildStream out = ChildStream::Inherit,
                      ChildStream err = ChildStream::Inherit, double timeoutSeconds = 0);

// A program that stays running between requests (a browser session serving many batches): argv
// as runProgram takes it; its stdin a socket this process writes lines to (a write to a child that
// is gone fails instead of raising SIGPIPE), its stdout and stderr one pipe read line by line. The
// destructor closes its stdin and waits up to `exitSeconds` for it to end, then kills it.
class ChildProcess {
  public:
    explicit ChildProcess(const std::vector<std::string>& argv, double exitSeconds = 30);
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    bool started() const { return pid_ > 0; }
    // `line` and a newline to the child's stdin; false when the child no longer reads it.
    bool writeLine(const std::string& line);
    // The next line the child writes, without its newline; nullopt once it closed its output.
    std::optional<std::string> readLine();
    // Closes its stdin and waits for it: its exit code, -1 when a signal ended it.
    int finish();
    // The end of what it wrote (at most the last 64 KiB), protocol lines included.
    const std::string& output() const { return out_; }

  private:
    void drain(int ms);
    void keep(const char* data, size_t n);

    pid_t pid_ = -1;
    int in_ = -1, outFd_ = -1;
    double exitSeconds_;
    std::string out_, pending_;
    int exitCode_ = -1;
    bool reaped_ = false;
};

// This process's private writable memory capped at `mib` MiB (RLIMIT_DATA: heap and anonymous
// mappings, not the address space a GPU driver reserves or maps from its device), for a child that
// runs untrusted work (a user's GLSL through the driver's compiler): past it an allocation fails
// there instead of the machine's memory running out. In a sanitizer build, whose shadow memory
// takes terabytes of address space, a thread ends the process (exit 137) once its peak resident
// memory has grown by `mib` instead. Throws ssao::Error when the limit cannot be set.
void limitAddressSpace(unsigned mib);

} // namespace ssao
