// Untrusted GLSL is tried in a child process first: ssaolab itself, running one of its hidden
// commands (commands/probe/probe_command.h), its address space capped and its time limited, handed
// the bytes that were checked here as a file in a private folder. Its verdict is its exit code,
// its "ok HASH" line (the hash of the bytes it was handed) and its error line; a crash, a limit or
// a time-out in the driver's compiler ends the child, never this process.
#pragma once
#include <string>
#include <vector>

namespace ssao {

constexpr double kUntrustedChildSeconds = 30;  // compile and frames included
constexpr unsigned kUntrustedChildMib = 1024;  // address space (docs/guide/hostile-input.md)

struct ChildVerdict {
    bool ok = false;
    std::string message; // why not: the child's error line (FILE:LINE: ...) or the limit it reached
};

// Runs `program` with `args` plus `--source FILE --max-memory-mib N`, FILE holding `text`; `label`
// names the user's file in messages.
ChildVerdict runUntrustedChild(const std::string& program, const std::vector<std::string>& args, const std::string& text,
                               const std::string& label);

} // namespace ssao
