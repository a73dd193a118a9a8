#include "util/atomic_file.h"

#include "util/error.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ssao {

namespace {
// A staging name no other process or call uses: pid and a per-process counter.
std::string stagingName(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    return path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
}
} // namespace

void checkOutputPath(const std::string& path) {
    struct stat st{};
    if (::lstat(path.c_str(), &st) != 0) {
        if (errno == ENOENT) { // absent: it will be created, in a folder that must be there now
            const size_t slash = path.find_last_of('/');
            const std::string parent = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
            struct stat dir{};
            if (::stat(parent.c_str(), &dir) != 0 || !S_ISDIR(dir.st_mode))
                throw Error("cannot write " + path + ": the folder " + parent + " does not exist");
            return;
        }
        throw Error("cannot write " + path + ": " + std::strerror(errno));
    }
    if (!S_ISREG(st.st_mode))
        throw Error("cannot write " + path + ": it exists and is not a regular file (" +
                    (S_ISLNK(st.st_mode)   ? "a symbolic link"
                     : S_ISDIR(st.st_mode) ? "a folder"
                     : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                     : S_ISFIFO(st.st_mode) ? "a FIFO"
                                            : "not a file") +
                    "); choose another path");
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
    checkOutputPath(path);
    // Created exclusively, never through a link: a name planted in the folder beforehand (a symlink
    // to a file elsewhere) makes the open fail instead of writing through it.
    std::string tmp;
    int fd = -1;
    for (int attempt = 0; attempt < 16 && fd < 0; ++attempt) {
        tmp = stagingName(path);
        fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
        if (fd < 0 && errno != EEXIST) break;
    }
    // The staging name is ours, not the user's: the error names the destination only.
    if (fd < 0) throw Error("cannot write " + path + ": cannot create a file in its folder (" + std::strerror(errno) + ")");
    auto fail = [&](const char* what, int err) {
        if (fd >= 0) ::close(fd);
        ::unlink(tmp.c_str());
        throw Error("cannot write " + path + ": " + what + " (" + std::strerror(err) + ")");
    };
    for (size_t done = 0; done < bytes.size();) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail("write failed", n < 0 ? errno : ENOSPC);
        done += size_t(n);
    }
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) fail("sync failed", errno);
    const int closed = ::close(fd);
    fd = -1;
    if (closed != 0) fail("close failed", errno);
    checkOutputPath(path); // nothing became a link or a device meanwhile
    if (std::rename(tmp.c_str(), path.c_str()) != 0) fail("rename failed", errno);
}

} // namespace ssao
