#include "util/atomic_file.h"

#include "util/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <unistd.h>

namespace ssao {

void writeFileAtomically(const std::string& path, const std::string& bytes) {
    const std::string tmp = path + ".tmp" + std::to_string(::getpid());
    auto fail = [&](const char* what, int err) {
        std::remove(tmp.c_str());
        throw Error("cannot write " + path + ": " + what + " (" + std::strerror(err) + ")");
    };
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) fail("cannot create it", errno);
    if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) {
        const int err = errno;
        std::fclose(f);
        fail("write failed", err);
    }
    if (std::fflush(f) != 0) {
        const int err = errno;
        std::fclose(f);
        fail("flush failed", err);
    }
    if (::fsync(::fileno(f)) != 0 && errno != EINVAL && errno != EROFS) { // EINVAL: a pipe or special file
        const int err = errno;
        std::fclose(f);
        fail("sync failed", err);
    }
    if (std::fclose(f) != 0) fail("close failed", errno);
    if (std::rename(tmp.c_str(), path.c_str()) != 0) fail("rename failed", errno);
}

} // namespace ssao
