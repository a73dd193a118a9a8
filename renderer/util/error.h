// One error type that travels to the edge (the CLI or the app) and is reported there, once.
#pragma once
#include <cstdio>
#include <stdexcept>
#include <string>

namespace ssao {

struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline std::string hex(unsigned v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%x", v);
    return buf;
}

} // namespace ssao
