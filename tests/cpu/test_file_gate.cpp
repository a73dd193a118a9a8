// The gate, by construction: every file ssaolab opens goes through renderer/util/files.h (reads:
// regular files, non-blocking, bounded; foreign folders without links) or the atomic writer, and
// every program it starts goes through renderer/util/process.h (an argv vector, never a shell).
#include "util/atomic_file.h"
#include "util/files.h"
#include "util/process.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using namespace ssao;

namespace {
using ssaotest::errorOf;
std::string slurp(const fs::path& p) {
    return ssaotest::slurp(p.string());
}

fs::path fresh(const std::string& name) {
    const fs::path p = fs::path(SSAOLAB_TEST_TMP) / ("gate_" + name);
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}
} // namespace

TEST(FileGate, NoFileIsOpenedAndNoProgramStartedOutsideTheGate) {
    // The gate's own files are the only ones allowed these calls.
    const std::set<std::string> gate = {"renderer/util/files.cpp", "renderer/util/atomic_file.cpp",
                                        "renderer/util/process.cpp"};
    const std::regex forbidden(
        R"(\bsystem\s*\(|\bpopen\s*\(|\bexecl?[vp]*e?\s*\(|std::[io]?fstream|\bfopen\s*\(|\bfreopen\s*\(|(^|[^\w])::open(at)?\s*\(|)"
        R"((^|[^\w.>:])open(at)?\s*\([^;]*O_(RDONLY|WRONLY|RDWR)|)"
        R"(\bopenat\s*\(|\bcreat\s*\(|\bstbi_load\s*\(|\bstbi_write_(png|bmp|tga|jpg|hdr)\s*\(|\bLoadEXR\s*\(|)"
        R"(\bSaveEXR\s*\(|FromFile\s*\(|\bcopy_file\s*\(|\bfs::copy\s*\(|std::filesystem::copy\s*\()");
    for (const char* bad : {"const int rc = std::system(cmd.c_str());", "popen(cmd.c_str(), \"r\")",
                            "std::ifstream in(path);", "std::ofstream log_;", "fd = ::open(p, O_RDONLY);",
                            "int fd = open(p, O_WRONLY | O_CREAT);", "stbi_load(path.c_str(), &w, &h, &c, 0)",
                            "LoadEXR(&rgba, &w, &h, path.c_str(), &err)", "fs::copy_file(a, b, ec);",
                            "FILE* f = fopen(p, \"rb\");", "loader.LoadASCIIFromFile(&m, &e, &w, p);"})
        EXPECT_TRUE(std::regex_search(std::string(bad), forbidden)) << bad;
    for (const char* fine : {"Preset p = store_.open(name);", "Preset open(const std::string& nameOrPath) const;",
                             "Preset PresetStore::open(const std::string& n) const {", "stbi_load_from_memory(d, n, &w, &h, &c, 0)",
                             "LoadEXRFromMemory(&rgba, &w, &h, data, size, &err)", "readRegularFile(path, \"scene\")"})
        EXPECT_FALSE(std::regex_search(std::string(fine), forbidden)) << fine;
    int scanned = 0;
    std::string found;
    for (const char* top : {"app", "renderer"})
        for (const auto& e : fs::recursive_directory_iterator(fs::path(SSAOLAB_SOURCE_DIR) / top)) {
            const std::string ext = e.path().extension().string();
            if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
            const std::string rel = fs::relative(e.path(), SSAOLAB_SOURCE_DIR).generic_string();
            ++scanned;
            if (gate.count(rel)) continue;
            std::istringstream in(slurp(e.path()));
            int n = 0;
            for (std::string line; std::getline(in, line);) {
                ++n;
                const std::string code = line.substr(0, line.find("//")); // comments may name them
                if (std::regex_search(code, forbidden)) found += rel + ":" + std::to_string(n) + ": " + line + "\n";
            }
        }
    EXPECT_GT(scanned, 150);
    EXPECT_EQ(found, "") << "open files through renderer/util/files.h or atomic_file.h and start programs through "
                            "renderer/util/process.h:\n"
                         << found;
}

TEST(FileGate, ReadsTakeRegularFilesOnlyAndNeverWait) {
    const fs::path d = fresh("reads");
    ASSERT_EQ(::mkfifo((d / "fifo").c_str(), 0600), 0);
    EXPECT_NE(errorOf([&] { readRegularFile((d / "fifo").string(), "preset"); }).find("is a FIFO, not a regular file"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { readRegularFile(d.string(), "preset"); }).find("is a folder"), std::string::npos);
    EXPECT_NE(errorOf([&] { readRegularFile("/dev/zero", "preset"); }).find("is a device"), std::string::npos);
    EXPECT_NE(errorOf([&] { readRegularFile((d / "absent").string(), "preset"); }).find("no such file"),
              std::string::npos);
    std::ofstream(d / "big") << std::string(2000, 'x');
    EXPECT_THROW(readRegularFile((d / "big").string(), "preset", 1000), FileTooLarge);
    // A /proc file says it is empty and is read to its end all the same.
    EXPECT_NE(readRegularFile("/proc/self/status", "status", 1 << 20).find("Name:"), std::string::npos);
}

TEST(FileGate, AForeignFolderIsReadWithoutFollowingALinkOut) {
    const fs::path d = fresh("inside");
    const fs::path secret = fs::path(SSAOLAB_TEST_TMP) / "gate_private.txt";
    std::ofstream(secret) << "PRIVATE";
    fs::create_directories(d / "shard/thumbs/a");
    std::ofstream(d / "shard/thumbs/a/ok.png") << "png";
    fs::create_symlink(secret, d / "shard/thumbs/a/leak.png");
    fs::create_symlink(d / "..", d / "shard/thumbs/up");
    fs::create_symlink(secret, d / "shard/results.json");
    const std::string shard = (d / "shard").string();
    EXPECT_EQ(readFileInside(shard, "thumbs/a/ok.png", "thumb"), "png");
    const std::string link = errorOf([&] { readFileInside(shard, "thumbs/a/leak.png", "thumb"); });
    EXPECT_NE(link.find("symbolic link"), std::string::npos) << link;
    EXPECT_EQ(link.find("PRIVATE"), std::string::npos);
    EXPECT_NE(errorOf([&] { readFileInside(shard, "results.json", "results"); }).find("symbolic link"), std::string::npos);
    EXPECT_NE(errorOf([&] { readFileInside(shard, "thumbs/up/gate_private.txt", "thumb"); }), "");
    EXPECT_NE(errorOf([&] { readFileInside(shard, "../gate_private.txt", "thumb"); }).find("'..'"), std::string::npos);
    EXPECT_NE(errorOf([&] { readFileInside(shard, "/etc/passwd", "thumb"); }), "");
    // Listing skips the links, to files and to folders alike.
    EXPECT_EQ(listFilesInside(shard, "thumbs", "shard", 10), std::vector<std::string>{"thumbs/a/ok.png"});
    EXPECT_NE(errorOf([&] { listFilesInside(shard, "thumbs", "shard", 0); }).find("more than 0 files"), std::string::npos);
}

TEST(FileGate, ALogIsNeverWrittenThroughALinkAFifoOrAFullDevice) {
    const fs::path d = fresh("log");
    const fs::path victim = d / "victim";
    std::ofstream(victim) << "precious";
    fs::create_symlink(victim, d / "link.log");
    EXPECT_NE(errorOf([&] { AppendFile((d / "link.log").string(), "frame log"); }).find("symbolic link"),
              std::string::npos);
    EXPECT_EQ(slurp(victim), "precious");
    ASSERT_EQ(::mkfifo((d / "fifo.log").c_str(), 0600), 0);
    EXPECT_NE(errorOf([&] { AppendFile((d / "fifo.log").string(), "frame log"); }).find("FIFO"), std::string::npos);
    EXPECT_NE(errorOf([&] { AppendFile("/dev/full", "frame log"); }).find("device"), std::string::npos);
    AppendFile ok((d / "frames.log").string(), "frame log");
    ok.write("1 2 3\n");
    ok.close();
    EXPECT_EQ(slurp(d / "frames.log"), "1 2 3\n");
}

TEST(FileGate, AProgramGetsItsArgumentsVerbatimAndNoShellRunsThem) {
    const fs::path d = fresh("spawn");
    const std::string marker = (d / "PWNED").string();
    for (const std::string& hostile : {"'; touch " + marker + "; '", "$(touch " + marker + ")", "`touch " + marker + "`",
                                      "a\ntouch " + marker, "\" && touch " + marker + " #"}) {
        const ProgramRun r = runProgram({"printf", "%s", hostile}, ChildStream::Capture, ChildStream::Discard);
        ASSERT_TRUE(r.started);
        EXPECT_EQ(r.exitCode, 0);
        EXPECT_EQ(r.out, hostile);
    }
    EXPECT_FALSE(fs::exists(marker));
    EXPECT_FALSE(runProgram({"ssaolab-no-such-program"}).started);
    EXPECT_EQ(runProgram({"false"}, ChildStream::Discard, ChildStream::Discard).exitCode, 1);
}

// A child that serves many requests (the engines' browser session): lines in, lines out, in turn;
// one that is gone fails a write instead of killing this process with SIGPIPE; one that never ends
// is killed at the end of its grace period.
TEST(Process, AServingChildAnswersLineByLineAndEndsWithItsInput) {
    ChildProcess cat({"cat"});
    ASSERT_TRUE(cat.started());
    for (const std::string line : {"first", "'; touch x; '", "third"}) {
        ASSERT_TRUE(cat.writeLine(line));
        EXPECT_EQ(cat.readLine().value_or("(closed)"), line);
    }
    EXPECT_EQ(cat.finish(), 0);
    EXPECT_FALSE(cat.readLine().has_value());
    EXPECT_FALSE(cat.writeLine("after the end"));

    ChildProcess gone({"printf", "bye\\n"});
    EXPECT_EQ(gone.readLine().value_or(""), "bye");
    EXPECT_FALSE(gone.readLine().has_value()); // it closed its output
    for (int i = 0; i < 100; ++i)
        gone.writeLine(std::string(4096, 'x')); // no SIGPIPE, whatever it returns
    EXPECT_EQ(gone.finish(), 0);
    EXPECT_NE(gone.output().find("bye"), std::string::npos);

    ChildProcess stuck({"sleep", "600"}, 0.2);
    EXPECT_EQ(stuck.finish(), -1); // killed after 0.2 s
    EXPECT_FALSE(ChildProcess({"ssaolab-no-such-program"}).started());
}

TEST(Process, AChildPastItsTimeLimitIsKilledAndSaidToHaveTimedOut) {
    // Captured (the pipe stays open while it runs) and not: both end at the limit, not with the child.
    const ProgramRun captured = runProgram({"tail", "-f", "/dev/null"}, ChildStream::Capture, ChildStream::Discard, 0.2);
    EXPECT_TRUE(captured.started);
    EXPECT_TRUE(captured.timedOut);
    EXPECT_EQ(captured.exitCode, -1);
    const ProgramRun quiet = runProgram({"sleep", "600"}, ChildStream::Discard, ChildStream::Discard, 0.2);
    EXPECT_TRUE(quiet.timedOut);
    // One that ends in time is not.
    const ProgramRun fast = runProgram({"printf", "done"}, ChildStream::Capture, ChildStream::Discard, 30);
    EXPECT_FALSE(fast.timedOut);
    EXPECT_EQ(fast.exitCode, 0);
    EXPECT_EQ(fast.out, "done");
}
