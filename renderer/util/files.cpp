#include "util/files.h"

#include "util/atomic_file.h"
#include "util/error.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace ssao {

namespace {

// Closes a descriptor on every path out of a function.
struct Fd {
    int fd = -1;
    explicit Fd(int f) : fd(f) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

const char* kindOf(mode_t m) {
    return S_ISDIR(m)                  ? "a folder"
           : S_ISFIFO(m)               ? "a FIFO"
           : S_ISCHR(m) || S_ISBLK(m)  ? "a device"
           : S_ISSOCK(m)               ? "a socket"
           : S_ISLNK(m)                ? "a symbolic link"
                                       : "not a file";
}

std::string openFailure(const std::string& label, int err) {
    if (err == ELOOP) return label + " is a symbolic link (refused inside a folder read as foreign input)";
    if (err == ENOENT) return label + ": no such file";
    return label + ": cannot open it (" + std::strerror(err) + ")";
}

// The bytes of an opened descriptor: a regular file of at most maxBytes, read to its end.
std::string readOpened(const Fd& f, const std::string& label, size_t maxBytes) {
    struct stat st{};
    if (::fstat(f.fd, &st) != 0) throw Error(label + ": cannot read it (" + std::strerror(errno) + ")");
    if (!S_ISREG(st.st_mode)) throw Error(label + " is " + kindOf(st.st_mode) + ", not a regular file");
    auto tooLarge = [&] {
        const size_t mib = maxBytes >> 20;
        return FileTooLarge(label + " is larger than " + (mib ? std::to_string(mib) + " MiB" : std::to_string(maxBytes) + " bytes"));
    };
    if (uint64_t(st.st_size) > maxBytes) throw tooLarge();
    std::string bytes;
    bytes.reserve(size_t(st.st_size));
    char buf[65536];
    for (;;) {
        const ssize_t n = ::read(f.fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw Error(label + ": cannot read it (" + std::strerror(errno) + ")");
        if (n == 0) break;
        if (bytes.size() + size_t(n) > maxBytes) throw tooLarge(); // grew, or a /proc file
        bytes.append(buf, size_t(n));
    }
    return bytes;
}

// The names of `relative`, each a plain name: no '..', no absolute path.
std::vector<std::string> plainNames(const std::string& relative, const std::string& label) {
    if (relative.empty() || relative[0] == '/') throw Error(label + ": not a name inside its folder");
    std::vector<std::string> names;
    size_t start = 0;
    while (start <= relative.size()) {
        const size_t end = std::min(relative.find('/', start), relative.size());
        const std::string n = relative.substr(start, end - start);
        if (n == "..") throw Error(label + ": '..' leaves its folder");
        if (!n.empty() && n != ".") names.push_back(n);
        start = end + 1;
    }
    if (names.empty()) throw Error(label + ": not a name inside its folder");
    return names;
}

} // namespace

std::string readRegularFile(const std::string& path, const std::string& what, size_t maxBytes) {
    const std::string label = what + " " + path;
    // Opened without blocking, then checked: a FIFO opened for reading would wait for a writer.
    const Fd f(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
    if (f.fd < 0) throw Error(openFailure(label, errno));
    return readOpened(f, label, maxBytes);
}

std::string readFileInside(const std::string& root, const std::string& relative, const std::string& what,
                           size_t maxBytes) {
    const std::string label = what + " " + (fs::path(root) / relative).string();
    const std::vector<std::string> names = plainNames(relative, label);
    int dir = ::open(root.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0) throw Error(openFailure(what + " folder " + root, errno));
    for (size_t i = 0; i + 1 < names.size(); ++i) {
        const int next = ::openat(dir, names[i].c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        const int err = errno;
        ::close(dir);
        if (next < 0) throw Error(openFailure(label + " (at '" + names[i] + "')", err == ENOTDIR ? ELOOP : err));
        dir = next;
    }
    const Fd f(::openat(dir, names.back().c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
    const int err = errno;
    ::close(dir);
    if (f.fd < 0) throw Error(openFailure(label, err));
    return readOpened(f, label, maxBytes);
}

std::vector<std::string> listFilesInside(const std::string& root, const std::string& sub, const std::string& what,
                                         size_t maxFiles) {
    std::vector<std::string> out;
    const fs::path base = sub.empty() ? fs::path(root) : fs::path(root) / sub;
    std::error_code ec;
    const auto st = fs::symlink_status(base, ec);
    if (ec || !fs::is_directory(st)) return out; // absent, or a link: nothing of its to take
    for (auto it = fs::recursive_directory_iterator(base, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
        const auto s = it->symlink_status(ec);
        if (ec || !fs::is_regular_file(s)) continue; // links (to files or folders), FIFOs, devices
        if (out.size() == maxFiles)
            throw Error(what + " " + base.string() + " holds more than " + std::to_string(maxFiles) + " files");
        out.push_back(fs::relative(it->path(), root, ec).generic_string());
    }
    if (ec) throw Error(what + " " + base.string() + ": cannot list it (" + ec.message() + ")");
    return out;
}

void makeOutputFolder(const std::string& path) {
    std::error_code ec;
    fs::create_directories(path, ec);
    if (fs::is_directory(path)) return;
    throw Error("cannot write to " + path + ": " +
                (fs::exists(fs::symlink_status(path, ec)) ? std::string("it exists and is not a folder")
                                                          : "cannot create it (" + ec.message() + ")"));
}

AppendFile::AppendFile(const std::string& path, const std::string& what) : path_(path), what_(what) {
    checkOutputPath(path); // absent or a regular file: never a device, a FIFO or a link
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY, 0644);
    if (fd_ < 0) throw Error("cannot write " + what + " " + path + ": " + std::strerror(errno));
    struct stat st{};
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) { // replaced between the check and the open
        ::close(fd_);
        fd_ = -1;
        throw Error("cannot write " + what + " " + path + ": it is not a regular file");
    }
}

AppendFile::AppendFile(AppendFile&& o) noexcept : fd_(o.fd_), path_(std::move(o.path_)), what_(std::move(o.what_)) {
    o.fd_ = -1;
}

AppendFile& AppendFile::operator=(AppendFile&& o) noexcept {
    if (this != &o) {
        if (fd_ >= 0) ::close(fd_);
        fd_ = o.fd_, path_ = std::move(o.path_), what_ = std::move(o.what_);
        o.fd_ = -1;
    }
    return *this;
}

AppendFile::~AppendFile() {
    if (fd_ >= 0) ::close(fd_);
}

void AppendFile::write(const std::string& bytes) {
    if (fd_ < 0) return;
    for (size_t done = 0; done < bytes.size();) {
        const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw Error("cannot write " + what_ + " " + path_ + ": " + std::strerror(n < 0 ? errno : ENOSPC));
        done += size_t(n);
    }
}

void AppendFile::close() {
    if (fd_ < 0) return;
    const int fd = fd_;
    fd_ = -1;
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {
        const int err = errno;
        ::close(fd);
        throw Error("cannot write " + what_ + " " + path_ + ": " + std::strerror(err));
    }
    if (::close(fd) != 0) throw Error("cannot write " + what_ + " " + path_ + ": " + std::strerror(errno));
}

} // namespace ssao
