#include "util/json_file.h"

#include "util/error.h"

#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ssao {

size_t jsonNestingDepth(const char* text, size_t size) {
    size_t depth = 0, deepest = 0;
    bool inString = false;
    for (size_t i = 0; i < size; ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i; // the escaped character is never a quote that ends the string
            else if (c == '"') inString = false;
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

void checkJsonNesting(const std::string& text, const std::string& what) {
    if (jsonNestingDepth(text.data(), text.size()) > kMaxJsonDepth)
        throw Error(what + " nests arrays or objects deeper than " + std::to_string(kMaxJsonDepth) + " levels");
}

std::string readRegularFile(const std::string& path, const std::string& what, size_t maxBytes) {
    // Opened without blocking, then checked: a FIFO opened for reading would wait for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw Error(what + " " + path + ": cannot open it");
    struct stat st{};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw Error(what + " " + path + " is not a regular file");
    }
    if (size_t(st.st_size) > maxBytes) {
        ::close(fd);
        throw Error(what + " " + path + " is larger than " + std::to_string(maxBytes >> 20) + " MiB");
    }
    std::string bytes(size_t(st.st_size), '\0');
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
        if (n <= 0) break;
        done += size_t(n);
    }
    ::close(fd);
    bytes.resize(done);
    return bytes;
}

nlohmann::json readJsonFile(const std::string& path, const std::string& what) {
    const std::string text = readRegularFile(path, what);
    checkJsonNesting(text, what + " " + path);
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) { // syntax, or a number that overflows a double
        std::string msg = e.what();
        const size_t bracket = msg.find("] ");
        if (bracket != std::string::npos) msg = msg.substr(bracket + 2); // drop "[json.exception...]"
        throw Error(what + " " + path + " is not valid JSON (" + msg + ")");
    }
}

std::string dumpJson(const nlohmann::json& j, int indent) {
    return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

} // namespace ssao
