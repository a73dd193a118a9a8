#include "cli/untrusted_child.h"

#include "techniques/user/user_header.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/process.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace ssao {

namespace {

constexpr const char* kErrorPrefix = "ssaolab: error: ";

// A folder only this process can read, removed with its file when the child is done.
class PrivateFolder {
  public:
    PrivateFolder() {
        std::error_code ec;
        std::string t = (fs::temp_directory_path(ec) / "ssaolab-child-XXXXXX").string();
        if (ec || !::mkdtemp(t.data())) throw Error("cannot make a private folder to hand GLSL to a child process");
        path_ = t;
    }
    ~PrivateFolder() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    PrivateFolder(const PrivateFolder&) = delete;
    PrivateFolder& operator=(const PrivateFolder&) = delete;
    const std::string& path() const { return path_; }

  private:
    std::string path_;
};

std::string firstError(const std::string& out, std::string& tested) {
    std::istringstream lines(out);
    std::string line, error;
    while (std::getline(lines, line)) {
        if (line.rfind(kErrorPrefix, 0) == 0 && error.empty()) error = line.substr(std::strlen(kErrorPrefix));
        if (line.rfind("ok ", 0) == 0) tested = line.substr(3);
    }
    const std::string stops = " - the run stops"; // the frame limit's words for a headless run
    if (error.size() > stops.size() && error.compare(error.size() - stops.size(), stops.size(), stops) == 0)
        error.resize(error.size() - stops.size());
    return error;
}

} // namespace

ChildVerdict runUntrustedChild(const std::string& program, const std::vector<std::string>& args, const std::string& text,
                               const std::string& label) {
    PrivateFolder folder;
    const std::string source = folder.path() + "/source.glsl";
    writeFileAtomically(source, text);
    std::vector<std::string> argv{program};
    argv.insert(argv.end(), args.begin(), args.end());
    argv.insert(argv.end(), {"--source", source, "--max-memory-mib", std::to_string(kUntrustedChildMib)});
    const ProgramRun r = runProgram(argv, ChildStream::Capture, ChildStream::Capture, kUntrustedChildSeconds);
    std::string tested;
    const std::string error = firstError(r.out, tested);
    ChildVerdict v;
    v.ok = r.started && r.exitCode == 0 && tested == userTechniqueHash(text);
    if (v.ok) return v;
    const std::string limits = " in a child process limited to " + std::to_string(kUntrustedChildMib) + " MiB and " +
                               std::to_string(int(kUntrustedChildSeconds)) + " s";
    if (!r.started)
        v.message = label + ": the child process that tries it could not be started (" + program + ")";
    else if (r.timedOut)
        v.message = label + ": did not finish" + limits + " (a shader or a compile that never ends?)";
    else if (!error.empty())
        v.message = error;
    else
        v.message = label + ": the GLSL compiler or driver failed" + limits + " (" +
                    (r.exitCode < 0 ? std::string("killed by a signal") : "exit " + std::to_string(r.exitCode)) +
                    "): too large or too deep for it";
    return v;
}

} // namespace ssao
