// The one way ssaolab opens a file (tests/cpu/test_file_gate.cpp fails on any other open in app/
// and renderer/). Reads take regular files only, opened without blocking (a FIFO opened for
// reading waits for a writer for ever), bounded in size; writes go through writeFileAtomically
// (atomic_file.h) or, for a log written as it goes, AppendFile below. Errors are one ssao::Error
// naming the file and never quoting its bytes.
#pragma once
#include "util/error.h"

#include <cstddef>
#include <string>
#include <vector>

namespace ssao {

// Thrown by the reads below when a file holds more than the bytes allowed (callers name their budget).
struct FileTooLarge : Error {
    using Error::Error;
};

constexpr size_t kMaxFileBytes = size_t(64) << 20; // text inputs: presets, sweeps, shaders, results

// The file's bytes: a regular file (no FIFO, device or folder) of at most `maxBytes`, read until its
// end (a /proc file says size 0). `what` names it in errors ("preset", "sweep", "shader").
std::string readRegularFile(const std::string& path, const std::string& what, size_t maxBytes = kMaxFileBytes);

// A file of a foreign folder (a bench shard, an output folder others could have written into):
// `relative` is opened under `root` one name at a time without following any symbolic link, and
// '..', absolute names and empty names are refused, so nothing it holds can point outside it.
std::string readFileInside(const std::string& root, const std::string& relative, const std::string& what,
                           size_t maxBytes = kMaxFileBytes);

// The regular files under root/sub (sub "" for root itself), as paths relative to root, found
// without entering a linked folder; links and other non-regular entries are skipped. More than
// `maxFiles` is an error naming the folder.
std::vector<std::string> listFilesInside(const std::string& root, const std::string& sub, const std::string& what,
                                         size_t maxFiles);

// A folder for outputs: made when absent (with its parents); an existing path that is not a folder
// is an error naming it.
void makeOutputFolder(const std::string& path);

// A log written line by line while the program runs (--frame-log): the destination must be absent
// or a regular file, is never opened through a link or a FIFO, and every write is checked (a full
// disk is an error naming the file, not a silent stop).
class AppendFile {
  public:
    AppendFile() = default;
    AppendFile(const std::string& path, const std::string& what);
    AppendFile(AppendFile&& o) noexcept;
    AppendFile& operator=(AppendFile&& o) noexcept;
    AppendFile(const AppendFile&) = delete;
    AppendFile& operator=(const AppendFile&) = delete;
    ~AppendFile();
    bool isOpen() const { return fd_ >= 0; }
    void write(const std::string& bytes);
    void close(); // checked: a failed close is an error

  private:
    int fd_ = -1;
    std::string path_, what_;
};

} // namespace ssao
