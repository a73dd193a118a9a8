// Output files are complete or absent: a full disk is an error naming the file and the reason,
// and the previous file is left as it was (before, a full disk left 0-byte files and "wrote ...").
#include "util/atomic_file.h"
#include "util/error.h"

#include "test_util.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <csignal>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace ssao;

namespace {
std::string slurp(const std::string& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
} // namespace

TEST(AtomicFile, WritesTheWholeFileAndReplacesTheOldOne) {
    const std::string path = ssaotest::writeTemp("atomic_ok.json", "old");
    writeFileAtomically(path, "new contents\n");
    EXPECT_EQ(slurp(path), "new contents\n");
}

namespace {
// Files beside `path` whose names start with path + ".tmp": staging files left behind.
size_t stagingLeft(const std::string& path) {
    size_t n = 0;
    const std::string stem = std::filesystem::path(path).filename().string() + ".tmp";
    for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
        n += e.path().filename().string().rfind(stem, 0) == 0;
    return n;
}
} // namespace

TEST(AtomicFile, AFullDiskIsAnErrorAndLeavesTheOldFile) {
    // A write the file system cuts short (here: a 1 KB file-size limit in a child process, so the
    // kernel refuses the 64 KB write as a full disk would) is an error naming the file; the old
    // file stays and no staging file is left behind.
    const std::string path = ssaotest::writeTemp("atomic_full.json", "old");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::signal(SIGXFSZ, SIG_IGN); // the write returns EFBIG instead of killing the process
        struct rlimit lim{1024, 1024};
        ::setrlimit(RLIMIT_FSIZE, &lim);
        try {
            writeFileAtomically(path, std::string(1 << 16, 'x'));
        } catch (const Error& e) {
            const std::string msg = e.what();
            ::_exit(msg.find("cannot write " + path) != std::string::npos &&
                            msg.find("write failed") != std::string::npos
                        ? 0
                        : 2);
        }
        ::_exit(3); // wrote past the limit without an error
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "child status " << status;
    EXPECT_EQ(slurp(path), "old"); // untouched
    EXPECT_EQ(stagingLeft(path), 0u);
}

TEST(AtomicFile, APlantedLinkAtAStagingNameIsNeverWrittenThrough) {
    // Before: the staging name was path + ".tmp" + pid (EXR: path + ".exr-staged"), opened with
    // fopen: a symlink planted there made the write land outside --out. Now staging files are
    // created exclusively under names unique to the call, never through a link.
    const std::string victim = ssaotest::writeTemp("atomic_victim.txt", "precious");
    const std::string path = std::string(SSAOLAB_TEST_TMP) + "/atomic_linked.json";
    std::filesystem::remove(path);
    for (const std::string& planted : {path + ".tmp" + std::to_string(::getpid()), path + ".exr-staged",
                                       path + ".tmp-" + std::to_string(::getpid()) + "-0"}) {
        std::filesystem::remove(planted);
        ASSERT_EQ(::symlink(victim.c_str(), planted.c_str()), 0);
    }
    writeFileAtomically(path, "output");
    EXPECT_EQ(slurp(path), "output");
    EXPECT_EQ(slurp(victim), "precious");
}

TEST(AtomicFile, ADestinationThatIsNotARegularFileIsRefused) {
    // `tune --out /dev/null` once replaced the device node with a regular file (as root, the
    // system's). A device, a FIFO, a folder or a symlink at the destination is refused by name.
    EXPECT_NE(ssaotest::errorOf([] { checkOutputPath("/dev/null"); }).find("a device"), std::string::npos);
    const std::string fifo = std::string(SSAOLAB_TEST_TMP) + "/atomic_fifo";
    std::filesystem::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_NE(ssaotest::errorOf([&] { writeFileAtomically(fifo, "x"); }).find("a FIFO"), std::string::npos);
    const std::string link = std::string(SSAOLAB_TEST_TMP) + "/atomic_dest_link";
    const std::string victim = ssaotest::writeTemp("atomic_victim2.txt", "precious");
    std::filesystem::remove(link);
    ASSERT_EQ(::symlink(victim.c_str(), link.c_str()), 0);
    EXPECT_NE(ssaotest::errorOf([&] { writeFileAtomically(link, "x"); }).find("a symbolic link"), std::string::npos);
    EXPECT_EQ(slurp(victim), "precious");
    EXPECT_NE(ssaotest::errorOf([] { writeFileAtomically(SSAOLAB_TEST_TMP, "x"); }).find("a folder"),
              std::string::npos);
    EXPECT_EQ(ssaotest::errorOf([] { checkOutputPath(std::string(SSAOLAB_TEST_TMP) + "/absent.json"); }), "");
}

TEST(AtomicFile, AMissingFolderIsAnErrorNamingTheFile) {
    const std::string path = std::string(SSAOLAB_TEST_TMP) + "/no/such/folder/x.json";
    try {
        writeFileAtomically(path, "x");
        ADD_FAILURE() << "wrote into a missing folder";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
}
