// One error type that travels to the edge (the CLI or the app) and is reported there, once.
#pragma once
#include <cstdio>
#include <stdexcept>
#include <string>

namespace ssao {

struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Parses a decimal number ("0.5", "-2e-3", "inf", "nan") that fills the whole text; no hex, no
// spaces. Returns false when the text is not one. Non-finite values parse (callers report them).
bool parseDecimal(const std::string& text, double& out);

// A message as the one line a terminal shows: trailing blanks dropped, line breaks as ';', other
// control bytes (an escape sequence in a file name) as '?', and at most about 600 bytes (a long
// middle, e.g. a huge value echoed from a file, left out and counted).
std::string oneLine(const std::string& message);

inline std::string hex(unsigned v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%x", v);
    return buf;
}

} // namespace ssao
