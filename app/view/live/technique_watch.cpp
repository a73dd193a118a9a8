#include "view/live/technique_watch.h"

#include "techniques/technique.h"
#include "techniques/user/user_folder.h"
#include "techniques/user/user_technique.h"
#include "util/error.h"
#include "util/files.h"
#include "cli/untrusted_child.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <set>
#include <utility>

namespace fs = std::filesystem;

namespace ssao {

namespace {

// The probe in its own process, handed the bytes checked here (never the file again: a link swapped
// in meanwhile is not followed); its verdict is its exit code, its "ok HASH" line and its error line.
ChildVerdict probe(const std::string& program, const std::string& path, const std::string& text, const std::string& size) {
    return runUntrustedChild(program, {"--frame-time-limit", std::to_string(TechniqueWatch::kFrameLimitS), "probe-technique",
                                       path, "--size", size},
                             text, path);
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
            const ChildVerdict v = probe(program_, job.path, job.text, std::to_string(job.width) + "x" + std::to_string(job.height));
            s.ok = v.ok, s.message = v.message;
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
        worker_->start({probing_->path + "#" + probing_->hash, probing_->path, probing_->hash, probing_->text,
                        std::max(width, 16), std::max(height, 16)});
    }
    news.probing = probing_.has_value();
    return news;
}

void TechniqueWatch::scan(News& news) {
    std::vector<std::string> files;
    try {
        files = listTechniqueFiles(dir_).files;
    } catch (const Error&) {
        return; // the folder went away: what runs keeps running
    }
    std::set<std::string> present;
    for (const std::string& f : files) {
        const std::string path = (fs::path(dir_) / f).string();
        present.insert(path);
        std::string text;
        try {
            text = readFileInside(dir_, f, "user technique", kMaxUserFileBytes);
        } catch (const Error& e) {
            if (seen_[path] != "unreadable") news.errors.push_back(std::string(e.what()) + " - not adopted");
            seen_[path] = "unreadable";
            forget(path);
            continue;
        }
        const std::string hash = userTechniqueHash(text);
        if (seen_[path] == hash) continue;
        seen_[path] = hash;
        queue_.erase(std::remove_if(queue_.begin(), queue_.end(), [&](const Candidate& c) { return c.path == path; }),
                     queue_.end()); // an older version waiting is replaced
        try {
            loadUserTechnique(text, path, builtinTechniqueIds()); // the header and body rules, first
        } catch (const Error& e) {
            news.errors.push_back(std::string(e.what()) + " - the last good version keeps running");
            continue;
        }
        queue_.push_back({path, hash, std::move(text)});
    }
    // A file no longer listed (removed, or now a link, a FIFO or a folder) is no version to adopt.
    for (auto it = seen_.begin(); it != seen_.end();) {
        if (present.count(it->first)) {
            ++it;
            continue;
        }
        forget(it->first);
        it = seen_.erase(it); // read afresh when a regular file is there again
    }
}

void TechniqueWatch::forget(const std::string& path) {
    queue_.erase(std::remove_if(queue_.begin(), queue_.end(), [&](const Candidate& c) { return c.path == path; }),
                 queue_.end());
    if (probing_ && probing_->path == path) probingDropped_ = true;
}

void TechniqueWatch::finish(const State& s, News& news) {
    const Candidate c = *probing_;
    probing_.reset();
    const bool dropped = std::exchange(probingDropped_, false);
    if (dropped)
        news.errors.push_back(c.path + ": changed while it was probed (now gone, or no longer a regular file) - not adopted");
    else if (s.ok)
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
