#include "view/technique_watch.h"

#include "techniques/technique.h"
#include "techniques/user/user_folder.h"
#include "techniques/user/user_technique.h"
#include "util/error.h"
#include "util/files.h"
#include "util/process.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace ssao {

namespace {

constexpr const char* kErrorPrefix = "ssaolab: error: ";

// The probe in its own process: its verdict is its exit code, its "ok HASH" line and its error line.
void probe(const std::string& program, const std::string& path, const std::string& hash, const std::string& size,
           bool& ok, std::string& message) {
    const ProgramRun r = runProgram({program, "--frame-time-limit", std::to_string(TechniqueWatch::kFrameLimitS),
                                     "probe-technique", path, "--size", size},
                                    ChildStream::Capture, ChildStream::Capture, TechniqueWatch::kProbeLimitS);
    std::istringstream lines(r.out);
    std::string line, error, tested;
    while (std::getline(lines, line)) {
        if (line.rfind(kErrorPrefix, 0) == 0 && error.empty()) error = line.substr(std::strlen(kErrorPrefix));
        const std::string stops = " - the run stops"; // the frame limit's words for a headless run
        if (error.size() > stops.size() && error.compare(error.size() - stops.size(), stops.size(), stops) == 0)
            error.resize(error.size() - stops.size());
        if (line.rfind("ok ", 0) == 0) tested = line.substr(3);
    }
    ok = r.started && r.exitCode == 0 && tested == hash;
    if (ok) return;
    if (!r.started)
        message = path + ": the probe could not be started (" + program + ")";
    else if (r.timedOut)
        message = path + ": the probe did not finish within " + std::to_string(int(TechniqueWatch::kProbeLimitS)) +
                  " s (a shader that never ends?)";
    else if (!error.empty())
        message = error;
    else if (r.exitCode == 0)
        message = path + ": the file changed while it was probed";
    else
        message = path + ": the probe ended without a verdict (exit " + std::to_string(r.exitCode) +
                  (r.exitCode < 0 ? ": a signal - the driver crashed?" : "") + ")";
}

} // namespace

TechniqueWatch::TechniqueWatch(std::string dir, std::string program, std::function<void()> wake)
    : dir_(std::move(dir)), program_(std::move(program)) {
    for (const TechniqueInfo& t : techniques())
        if (!t.file.empty()) seen_[t.file] = t.version;
    // A file refused at start is not in seen_: the first scan reads it again and says why.
    worker_ = std::make_unique<LatestJob<Job, State>>(
        [this](const Job& job) {
            State s;
            probe(program_, job.path, job.hash, std::to_string(job.width) + "x" + std::to_string(job.height), s.ok,
                  s.message);
            s.done = true;
            worker_->publish(job, [&](State& st) { st.done = true, st.ok = s.ok, st.message = s.message; });
        },
        std::move(wake));
}

TechniqueWatch::~TechniqueWatch() = default;

TechniqueWatch::News TechniqueWatch::poll(int width, int height) {
    News news;
    if (dir_.empty()) return news;
    if (probing_) {
        const State s = worker_->state();
        if (s.done) finish(s, news);
    }
    scan(news);
    if (!probing_ && !queue_.empty()) {
        probing_ = queue_.front();
        queue_.pop_front();
        worker_->start({probing_->path + "#" + probing_->hash, probing_->path, probing_->hash, std::max(width, 16),
                        std::max(height, 16)});
    }
    news.probing = probing_.has_value();
    return news;
}

void TechniqueWatch::scan(News& news) {
    std::vector<std::string> files;
    try {
        files = listFilesInside(dir_, "", "technique folder", kMaxUserFolderFiles);
    } catch (const Error&) {
        return; // the folder went away or is too full: what runs keeps running
    }
    std::sort(files.begin(), files.end());
    for (const std::string& f : files) {
        if (f.find('/') != std::string::npos || f.size() <= 8 || f.compare(f.size() - 8, 8, ".ao.glsl") != 0) continue;
        const std::string path = (fs::path(dir_) / f).string();
        std::string text;
        try {
            text = readFileInside(dir_, f, "user technique", kMaxUserFileBytes);
        } catch (const Error& e) {
            if (seen_[path] != "unreadable") news.errors.push_back(std::string(e.what()) + " - not adopted");
            seen_[path] = "unreadable";
            continue;
        }
        const std::string hash = userTechniqueHash(text);
        if (seen_[path] == hash) continue;
        seen_[path] = hash;
        try {
            loadUserTechnique(text, path, builtinTechniqueIds()); // the header and body rules, first
        } catch (const Error& e) {
            news.errors.push_back(std::string(e.what()) + " - the last good version keeps running");
            continue;
        }
        queue_.erase(std::remove_if(queue_.begin(), queue_.end(), [&](const Candidate& c) { return c.path == path; }),
                     queue_.end());
        queue_.push_back({path, hash, std::move(text)});
    }
}

void TechniqueWatch::finish(const State& s, News& news) {
    const Candidate c = *probing_;
    probing_.reset();
    if (s.ok)
        adopt(c, news);
    else
        news.errors.push_back(s.message + " - the last good version keeps running");
}

void TechniqueWatch::adopt(const Candidate& c, News& news) {
    auto t = std::make_shared<const UserTechnique>(loadUserTechnique(c.text, c.path, builtinTechniqueIds()));
    std::vector<std::shared_ptr<const UserTechnique>> list;
    for (const TechniqueInfo& info : techniques())
        if (!info.file.empty() && info.id != userTechniqueId(t->name)) list.push_back(info.user);
    list.push_back(t);
    std::vector<std::pair<std::string, std::string>> refused;
    for (const auto& r : refusedUserTechniques())
        if (r.first != userTechniqueId(t->name)) refused.push_back(r);
    setUserTechniques(list, refused);
    news.adopted.push_back(userTechniqueId(t->name) + " (" + c.path + ")");
}

} // namespace ssao
