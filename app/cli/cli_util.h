// Command-line helpers shared by every subcommand: a range check that refuses NaN (CLI11's
// Range lets "nan" through: every comparison with it is false), and the one-line report of a
// mistyped option or command naming the closest valid one (util/closest_name.h), and warnings.
#pragma once
#include "util/closest_name.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace ssao {

// A finite number in [lo, hi].
CLI::Validator cliRange(double lo, double hi);

// After parsing with extras allowed: throws ssao::Error naming the first unknown command or
// option (with the closest valid one and the help to read), if there is one.
void refuseExtras(const CLI::App& app);
// "ssaolab bench merge --help": the help of the innermost subcommand chosen.
std::string helpCommand(const CLI::App& app);

// What a path option names, as its type name in --help: the generic hostile-path test
// (tests/cli/test_cli_paths.cpp) finds every path option of every command by these.
constexpr const char* kInFile = "FILE";       // read: a regular file (or builtin:NAME / a preset name)
constexpr const char* kInFiles = "FILE...";   // read: regular files
constexpr const char* kInDir = "DIR";         // read: a folder
constexpr const char* kInDirs = "DIR...";     // read: folders (bench merge's shards)
constexpr const char* kOutFile = "OUT-FILE";  // written: one file
constexpr const char* kOutDir = "OUT-DIR";    // written: a folder of outputs
// Prints one JSON line per option of every command: {"command", "option", "type", "flag"}.
void printOptionKinds(const CLI::App& app);

// One `ssaolab: warning: ...` line on stderr each (e.g. a --set that has no effect,
// settings/applicability.h); warnings never change the exit code.
void printWarnings(const std::vector<std::string>& warnings);

} // namespace ssao
