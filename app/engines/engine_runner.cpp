#include "engines/engine_runner.h"

#include "scene/load/browser_assets.h"
#include "scene/scene.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "util/image_budget.h"
#include "util/json_file.h"
#include "util/paths.h"
#include "util/process.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <unistd.h>

namespace fs = std::filesystem;

namespace ssao {

namespace {

const char* const kInstallHint = "install Node.js with npm and Debian's chromium (make deps), then the pinned npm "
                                 "packages (make engine-modules)";

std::string lastLine(const std::string& text) {
    size_t end = text.find_last_not_of("\r\n \t");
    if (end == std::string::npos) return "no message";
    const size_t start = text.find_last_of('\n', end);
    return text.substr(start == std::string::npos ? 0 : start + 1, end - (start == std::string::npos ? 0 : start + 1) + 1);
}

// The installed version of a package, "" when it is not there.
std::string installedVersion(const std::string& modules, const std::string& package) {
    const std::string file = modules + "/" + package + "/package.json";
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) return "";
    const nlohmann::json j = readJsonFile(file, "package.json");
    return j.is_object() && j.contains("version") && j["version"].is_string() ? j["version"].get<std::string>() : "";
}

// The major version of `node --version` ("v20.20.2" -> 20); 0 when it did not run.
int nodeMajor(const std::string& node) {
    const ProgramRun r = runProgram({node, "--version"}, ChildStream::Capture, ChildStream::Discard);
    if (!r.started || r.exitCode != 0 || r.out.size() < 2 || r.out[0] != 'v') return 0;
    return std::atoi(r.out.c_str() + 1);
}

// playwright-core's own minimum Node.js major (its package.json engines.node, ">=20").
int playwrightNeeds(const std::string& modules) {
    const nlohmann::json j = readJsonFile(modules + "/playwright-core/package.json", "package.json");
    if (!j.contains("engines") || !j["engines"].contains("node") || !j["engines"]["node"].is_string()) return 0;
    const std::string s = j["engines"]["node"].get<std::string>();
    const size_t digit = s.find_first_of("0123456789");
    return digit == std::string::npos ? 0 : std::atoi(s.c_str() + digit);
}

} // namespace

std::string defaultEngineModules() {
    if (dataRootSource() == "installed") return enginePeersDir() + "/node_modules"; // cmake --install copies them there
    const std::string exe = executablePath();
    if (exe.empty()) return "";
    return (fs::path(exe).parent_path().parent_path() / "peers" / "node_modules").string(); // BUILD/app/ssaolab
}

EngineTools locateEngineTools(const std::string& modules, const EngineTable& table) {
    return locateEngineTools(modules, table, "tune --engine");
}

EngineTools locateEngineTools(const std::string& modules, const EngineTable& table, const std::string& command) {
    const std::string what = command + " " + table.engine + " runs " + table.title + " in Chromium: ";
    EngineTools t{"node", modules.empty() ? defaultEngineModules() : modules, enginePeersDir()};
    const int major = nodeMajor(t.node);
    if (major == 0) throw Error(what + "node (Node.js) is not on PATH; " + kInstallHint);
    const char* env = std::getenv("CHROMIUM");
    const std::string chromium = env && *env ? env : "/usr/bin/chromium";
    std::error_code ec;
    if (!fs::is_regular_file(chromium, ec) || ::access(chromium.c_str(), X_OK) != 0)
        throw Error(what + "no browser at " + chromium + (env && *env ? " (CHROMIUM)" : "") + "; " + kInstallHint);
    for (const std::string& p : {table.package, std::string("playwright-core")})
        if (installedVersion(t.modules, p).empty())
            throw Error(what + "the npm package " + p + " is not installed in " + t.modules +
                        " (make engine-modules installs the pinned packages, or name a folder with --engine-modules)");
    const std::string version = installedVersion(t.modules, table.package);
    if (version != table.version)
        throw Error(what + t.modules + " holds " + table.package + " " + version + ", its table is for " + table.version +
                    " (make engine-modules installs the version the lock pins)");
    if (const int needs = playwrightNeeds(t.modules); needs > major)
        throw Error(what + "Node.js " + std::to_string(major) + " is older than playwright-core needs (" +
                    std::to_string(needs) + "); " + kInstallHint);
    if (!fs::is_regular_file(t.scripts + "/run_engine.mjs", ec))
        throw Error(what + "run_engine.mjs is not in " + t.scripts);
    return t;
}

EngineRunner::EngineRunner(EngineTools tools, EngineTable table, std::string sceneFile, int width, int height,
                           std::vector<EngineView> views)
    : tools_(std::move(tools)), table_(std::move(table)), width_(width), height_(height), views_(std::move(views)) {
    std::error_code ec;
    scene_ = fs::absolute(sceneFile, ec).string();
    checkBrowserAssets(scene_); // what the browser would fetch and decode, before it starts
    static std::atomic<int> counter{0};
    const fs::path base = fs::temp_directory_path(ec);
    for (int attempt = 0; attempt < 100 && work_.empty(); ++attempt) {
        const fs::path p = base / ("ssaolab-engine-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        if (fs::create_directory(p, ec)) work_ = p.string(); // a fresh folder, never one that was there
    }
    if (work_.empty()) throw Error("cannot make a work folder for the engine runner in " + base.string());
}

EngineRunner::~EngineRunner() {
    live_.clear(); // every session ends (its browser closes) before its folder goes
    std::error_code ec;
    fs::remove_all(work_, ec);
}

std::vector<EngineResult> EngineRunner::run(const std::vector<EngineJob>& jobs) {
    // One session runs one harness page: jobs of engines on different pages run in one session each.
    std::vector<std::string> pages;
    for (const EngineJob& j : jobs)
        if (const std::string& p = (j.table ? *j.table : table_).page; std::find(pages.begin(), pages.end(), p) == pages.end())
            pages.push_back(p);
    if (pages.size() <= 1) return runPage(jobs, pages.empty() ? table_.page : pages[0]);
    std::vector<EngineResult> out(jobs.size());
    for (const std::string& page : pages) {
        std::vector<EngineJob> part;
        std::vector<size_t> at;
        for (size_t i = 0; i < jobs.size(); ++i)
            if ((jobs[i].table ? *jobs[i].table : table_).page == page) part.push_back(jobs[i]), at.push_back(i);
        std::vector<EngineResult> got = runPage(part, page);
        for (size_t k = 0; k < at.size(); ++k)
            out[at[k]] = std::move(got[k]);
    }
    return out;
}

std::vector<EngineResult> EngineRunner::runPage(const std::vector<EngineJob>& jobs, const std::string& page, int hung) {
    const std::string tag = "b" + std::to_string(batches_++), dir = work_ + "/" + tag;
    // The session's own engine: the runner's when it is on this page, else the first job's.
    const EngineTable& own = table_.page == page || jobs.empty() || !jobs[0].table ? table_ : *jobs[0].table;
    auto rows = [](const EngineTable& t) {
        nlohmann::json params = nlohmann::json::array();
        for (const EngineParam& p : t.params)
            if (p.role != EngineParam::Role::Fixed) params.push_back(p.row);
        return params;
    };
    nlohmann::json views = nlohmann::json::array(), list = nlohmann::json::array(), tables = nlohmann::json::object();
    for (const EngineView& v : views_)
        views.push_back({{"camera", v.camera}, {"radius", v.radius}});
    for (size_t i = 0; i < jobs.size(); ++i) {
        const EngineTable& t = jobs[i].table ? *jobs[i].table : table_;
        nlohmann::json values = nlohmann::json::object(), scale = nlohmann::json::object();
        for (const auto& [name, v] : jobs[i].values)
            if (const EngineParam* p = t.find(name)) values[name] = engineValueJson(*p, v);
        for (const auto& [name, f] : jobs[i].scale)
            if (t.find(name)) scale[name] = f;
        list.push_back({{"view", jobs[i].view}, {"values", values}, {"image", "j" + std::to_string(i) + ".pgm"},
                        {"frames", jobs[i].frames}});
        if (!scale.empty()) list.back()["scale"] = scale;
        if (jobs[i].droppable) list.back()["droppable"] = true;
        if (t.peer != own.peer) list.back()["peer"] = t.peer, tables[t.peer] = rows(t);
    }
    nlohmann::json seconds = nlohmann::json::object();
    for (const auto& [frames, s] : jobSeconds_)
        seconds[std::to_string(frames)] = s;
    const nlohmann::json spec = {{"scene", scene_}, {"width", width_}, {"height", height_}, {"page", page},
                                 {"peer", own.peer}, {"params", rows(own)}, {"tables", tables}, {"views", views},
                                 {"frames", 0}, {"jobs", list}, {"job_seconds", seconds}};
    writeFileAtomically(dir + ".json", dumpJson(spec) + "\n");
    const std::string who = tables.empty() ? own.title : "the web engines"; // several in one session
    if (const std::string failure = serve(page, dir, who); !failure.empty()) return afterHang(jobs, page, hung, dir, failure);
    const nlohmann::json res = readJsonFile(dir + "/results.json", "engine results");
    if (!res.contains("jobs") || !res["jobs"].is_array() || res["jobs"].size() != jobs.size())
        throw Error(who + " in Chromium returned " + dir + "/results.json without one entry per job");
    std::vector<EngineResult> out;
    for (size_t i = 0; i < jobs.size(); ++i)
        out.push_back(readResult(dir, i, res["jobs"][i], jobs[i].frames));
    std::error_code ec;
    fs::remove_all(dir, ec);
    return out;
}

// One batch (DIR.json) in the page's session, started on the first batch: "" when it ran, else what
// failed (the session is gone then, and the next batch starts a new one).
std::string EngineRunner::serve(const std::string& page, const std::string& dir, const std::string& who) {
    auto& child = live_[page];
    if (!child) {
        child = std::make_unique<ChildProcess>(std::vector<std::string>{tools_.node, tools_.scripts + "/run_engine.mjs",
                                                                        "--modules", tools_.modules});
        if (!child->started()) {
            live_.erase(page);
            throw Error("cannot start " + tools_.node + " for " + who);
        }
        ++sessions_;
    }
    if (child->writeLine(dumpJson(nlohmann::json{{"jobs", dir + ".json"}, {"out", dir}}, -1)))
        while (const auto line = child->readLine())
            if (*line == "ssaolab-batch-done") return "";
    child->finish();
    const std::string failure = who + " in Chromium failed: " + lastLine(child->output());
    live_.erase(page);
    return failure;
}

EngineResult EngineRunner::readResult(const std::string& dir, size_t i, const nlohmann::json& j, int frames) {
    EngineResult e;
    if (j.contains("seconds") && j["seconds"].is_number()) { // what a job takes, for the next session's time limit
        std::vector<double>& s = jobSeconds_[frames];
        s.push_back(j["seconds"].get<double>());
        if (s.size() > 64) s.erase(s.begin());
    }
    e.ao = readEngineAo(dir + "/j" + std::to_string(i) + ".pgm", width_, height_);
    if (j.contains("values") && j["values"].is_object())
        for (const auto& [name, v] : j["values"].items())
            if (v.is_number() || v.is_boolean()) e.values[name] = v.is_boolean() ? double(v.get<bool>()) : v.get<double>();
    if (j.contains("ao_ms") && j["ao_ms"].is_number()) e.aoMs = j["ao_ms"].get<double>();
    if (j.contains("ao_ms_min") && j["ao_ms_min"].is_number()) e.aoMsMin = j["ao_ms_min"].get<double>();
    if (j.contains("ao_ms_max") && j["ao_ms_max"].is_number()) e.aoMsMax = j["ao_ms_max"].get<double>();
    if (j.contains("timed_frames") && j["timed_frames"].is_number_integer())
        e.timedFrames = int(std::clamp<long long>(j["timed_frames"].get<long long>(), 0, 1 << 20));
    return e;
}

// A session that failed: when the page hung on one job past its time limit (run_engine.mjs wrote
// DIR/hung.json), the jobs it finished are kept, that job comes back `hung` and the rest run in a
// new session; any other failure, or one hang too many, throws `failure`.
std::vector<EngineResult> EngineRunner::afterHang(const std::vector<EngineJob>& jobs, const std::string& page, int hung,
                                                  const std::string& dir, const std::string& failure) {
    std::error_code ec;
    if (!fs::is_regular_file(dir + "/hung.json", ec)) throw Error(failure);
    const nlohmann::json h = readJsonFile(dir + "/hung.json", "engine session");
    if (!h.contains("job") || !h["job"].is_number_integer() || h["job"].get<long>() < 0 || size_t(h["job"].get<long>()) >= jobs.size())
        throw Error(failure);
    const size_t stuck = size_t(h["job"].get<long>());
    if (!jobs[stuck].droppable && hung >= kMaxHungJobs) throw Error(failure); // a search's candidates never count
    std::vector<EngineResult> out(jobs.size());
    std::vector<EngineJob> rest;
    std::vector<size_t> at;
    const auto dropped = [&](size_t i) { // the stuck job, or an unrun one of its group
        return i == stuck || (jobs[stuck].droppable && jobs[i].droppable && jobs[i].group >= 0 && jobs[i].group == jobs[stuck].group);
    };
    for (size_t i = 0; i < jobs.size(); ++i) {
        const std::string done = dir + "/j" + std::to_string(i) + ".json";
        if (fs::is_regular_file(done, ec) && i != stuck) out[i] = readResult(dir, i, readJsonFile(done, "engine result"), jobs[i].frames);
        else if (dropped(i)) out[i].hung = true;
        else rest.push_back(jobs[i]), at.push_back(i);
    }
    fs::remove_all(dir, ec);
    if (!rest.empty()) {
        std::vector<EngineResult> more = runPage(rest, page, hung + (jobs[stuck].droppable ? 0 : 1));
        for (size_t k = 0; k < at.size(); ++k)
            out[at[k]] = std::move(more[k]);
    }
    return out;
}

Image readEngineAo(const std::string& file, int width, int height) {
    const ImageBudget budget{sceneBudget().maskPixels, 0, "decoded images", "--max-mask-mpix"};
    auto sizeCheck = [&](uint64_t w, uint64_t h) {
        if (w != uint64_t(width) || h != uint64_t(height))
            throw Error("engine AO " + file + ": " + std::to_string(w) + "x" + std::to_string(h) + ", the view is " +
                        std::to_string(width) + "x" + std::to_string(height));
    };
    const Image img = decodeImage(readRegularFile(file, "engine AO", imageFileBytes(budget)), budget, "engine AO " + file,
                                  [&](const ImageHeader& h) { sizeCheck(h.width, h.height); });
    sizeCheck(uint64_t(img.width), uint64_t(img.height));
    Image ao{img.width, img.height, 1, std::vector<float>(size_t(img.width) * img.height)};
    for (size_t i = 0; i < ao.data.size(); ++i) {
        const float v = img.data[i * size_t(img.channels)];
        if (!std::isfinite(v) || v < 0.0f || v > 1.0f) throw Error("engine AO " + file + ": a value outside [0, 1]");
        ao.data[i] = v;
    }
    return ao;
}

} // namespace ssao
