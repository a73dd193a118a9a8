// Output files are complete or absent: a full disk is an error naming the file and the reason,
// and the previous file is left as it was (before, a full disk left 0-byte files and "wrote ...").
#include "util/atomic_file.h"
#include "util/error.h"

#include "test_util.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

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

TEST(AtomicFile, AFullDiskIsAnErrorAndLeavesTheOldFile) {
    // The staging file is made to point at /dev/full, whose every write fails with ENOSPC.
    const std::string path = ssaotest::writeTemp("atomic_full.json", "old");
    const std::string staged = path + ".tmp" + std::to_string(::getpid());
    std::filesystem::remove(staged);
    ASSERT_EQ(::symlink("/dev/full", staged.c_str()), 0);
    std::string msg;
    try {
        writeFileAtomically(path, std::string(1 << 16, 'x'));
    } catch (const Error& e) {
        msg = e.what();
    }
    EXPECT_NE(msg.find("cannot write " + path), std::string::npos) << msg;
    EXPECT_NE(msg.find("No space left on device"), std::string::npos) << msg;
    EXPECT_EQ(slurp(path), "old");                          // untouched
    EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(staged))); // cleaned up
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
