// `bench merge` treats every byte of a shard folder as foreign input: links planted in a shard or
// in --out are never followed, FIFOs never waited on, shards of another definition or with rows
// that another shard measured are refused naming the folder, and no name reaches a shell.
#include "cli_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

using namespace ssaotest;
namespace fs = std::filesystem;

namespace {

const char* kSecret = "SSAOLAB-PRIVATE-BYTES-0123456789ab"; // 33 bytes: its base64 has no padding

std::string b64(const std::string& s) {
    return base64(std::vector<unsigned char>(s.begin(), s.end()));
}

// Two shards of one small benchmark, measured once for every test here.
class Merge : public ::testing::Test {
  protected:
    // Per process: ctest runs each test of this suite in a process of its own, side by side.
    static std::string root() { return std::string(SSAOLAB_TEST_TMP) + "/merge_" + std::to_string(::getpid()); }
    static std::string shard(int k) { return root() + "/shard" + std::to_string(k); }

    static void SetUpTestSuite() {
        fs::remove_all(root());
        fs::create_directories(root());
        const std::string sweep =
            writeTemp("merge_sweep.json", R"({"name": "m", "groups": [{"name": "k", "vary": {"kernel.samples": [8, 16]}}]})");
        for (int k = 1; k <= 2; ++k) {
            CliRun r = ssaolab("bench --scene builtin:corner --size 64x36 --views 2 --frames 1 --warmup 0 "
                               "--reference-rays 4 --no-plot --quiet --sweep " + sweep + " --shard " + std::to_string(k) +
                               "/2 --out " + shard(k));
            ASSERT_EQ(r.exitCode, 0) << r.err;
        }
        std::ofstream(root() + "/private.txt") << kSecret;
        ::chmod((root() + "/private.txt").c_str(), 0600);
    }

    // A copy of shard k to plant things in.
    static std::string copyOf(int k, const std::string& name) {
        const std::string to = root() + "/" + name;
        fs::remove_all(to);
        fs::copy(shard(k), to, fs::copy_options::recursive);
        return to;
    }

    static nlohmann::json results(const std::string& dir) {
        return nlohmann::json::parse(slurp(dir + "/results.json"));
    }
    static void rewrite(const std::string& dir, const nlohmann::json& j) {
        std::ofstream(dir + "/results.json") << j.dump();
    }
};

} // namespace

TEST_F(Merge, LinksPlantedInAShardOrInTheOutputAreNeverFollowed) {
    // Every thumbnail of shard 1 replaced by a link to a private file; a linked folder beside them.
    const std::string s1 = copyOf(1, "planted1");
    int planted = 0;
    for (const auto& e : fs::recursive_directory_iterator(s1 + "/thumbs"))
        if (e.path().extension() == ".png") {
            fs::remove(e.path());
            fs::create_symlink(root() + "/private.txt", e.path());
            ++planted;
        }
    ASSERT_GT(planted, 0);
    fs::create_symlink(root(), s1 + "/thumbs/outside");
    // And in --out, before the merge: a link where a thumbnail will go, a FIFO where another will.
    const std::string out = root() + "/out_planted";
    fs::remove_all(out);
    std::vector<std::string> names; // the thumbnails are of each scene's first view: shard 1's
    for (const auto& e : fs::recursive_directory_iterator(shard(1) + "/thumbs"))
        if (e.path().extension() == ".png") names.push_back(fs::relative(e.path(), shard(1)).string());
    ASSERT_GE(names.size(), 2u);
    fs::create_directories(fs::path(out + "/" + names[0]).parent_path());
    fs::create_symlink(root() + "/private.txt", out + "/" + names[0]);
    ASSERT_EQ(::mkfifo((out + "/" + names[1]).c_str(), 0600), 0);

    CliRun r = ssaolab("bench merge " + s1 + " " + shard(2) + " --no-plot --quiet --out " + out, "timeout 60");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // The private bytes are nowhere in the output, raw or as the report's base64.
    for (const auto& e : fs::recursive_directory_iterator(out)) {
        if (!fs::is_regular_file(fs::symlink_status(e.path()))) continue;
        const std::string bytes = slurp(e.path().string());
        EXPECT_EQ(bytes.find(kSecret), std::string::npos) << e.path();
        EXPECT_EQ(bytes.find(b64(kSecret)), std::string::npos) << e.path();
    }
    EXPECT_FALSE(fs::exists(out + "/thumbs/outside"));
    EXPECT_TRUE(fs::is_symlink(out + "/" + names[0])); // left as it was: not written through
    EXPECT_EQ(slurp(root() + "/private.txt"), kSecret);
    EXPECT_NE(slurp(out + "/report.html").find("not a regular file inside the output folder"), std::string::npos);
}

TEST_F(Merge, AResultsFileThatIsALinkOrAFifoIsRefusedWithOneLine) {
    const std::string linked = copyOf(1, "linked");
    fs::remove(linked + "/results.json");
    fs::create_symlink(fs::absolute(shard(1) + "/results.json"), linked + "/results.json");
    expectCleanFailure(ssaolab("bench merge " + linked + " " + shard(2) + " --no-plot --quiet --out " + root() + "/o1"),
                       "symbolic link");
    const std::string fifo = copyOf(1, "fifo");
    fs::remove(fifo + "/results.json");
    ASSERT_EQ(::mkfifo((fifo + "/results.json").c_str(), 0600), 0);
    CliRun r = ssaolab("bench merge " + fifo + " " + shard(2) + " --no-plot --quiet --out " + root() + "/o2", "timeout 30");
    expectCleanFailure(r, "is a FIFO, not a regular file");
    // A FIFO where merge writes report.html: refused, not waited on.
    const std::string out = root() + "/o3";
    fs::remove_all(out);
    fs::create_directories(out);
    ASSERT_EQ(::mkfifo((out + "/report.html").c_str(), 0600), 0);
    r = ssaolab("bench merge " + shard(1) + " " + shard(2) + " --no-plot --quiet --out " + out, "timeout 30");
    expectCleanFailure(r, "not a regular file");
}

TEST_F(Merge, ShardsOfAnotherDefinitionOrWithRowsAnotherShardMeasuredAreRefused) {
    // Another oracle: not one benchmark.
    const std::string oracle = copyOf(2, "oracle");
    nlohmann::json j = results(oracle);
    j["oracle"]["layers"] = 2;
    rewrite(oracle, j);
    expectCleanFailure(ssaolab("bench merge " + shard(1) + " " + oracle + " --no-plot --quiet --out " + root() + "/o4"),
                       oracle + ": its 'oracle'");
    // Another reference definition.
    const std::string ref = copyOf(2, "reference");
    j = results(ref);
    j["reference"]["definition"] = "another tracer";
    rewrite(ref, j);
    expectCleanFailure(ssaolab("bench merge " + shard(1) + " " + ref + " --no-plot --quiet --out " + root() + "/o5"),
                       ref + ": its 'reference'");
    // Shard 1's rows again, under the name of shard 2.
    const std::string dup = copyOf(1, "duplicate");
    j = results(dup);
    j["shards"][0]["shard"] = "2/2";
    rewrite(dup, j);
    expectCleanFailure(ssaolab("bench merge " + shard(1) + " " + dup + " --no-plot --quiet --out " + root() + "/o6"),
                       "is also in " + shard(1));
    // An impossible metric, named with its file and field.
    const std::string bad = copyOf(2, "impossible");
    j = results(bad);
    j["results"][0]["rmse"] = -1;
    rewrite(bad, j);
    expectCleanFailure(ssaolab("bench merge " + shard(1) + " " + bad + " --no-plot --quiet --out " + root() + "/o7"),
                       bad + "/results.json: results[0].rmse");
}

TEST_F(Merge, NamesWithShellSyntaxRunNothing) {
    // The plot step starts python from an argv vector: quotes, $(...), backticks, ';' and newlines
    // in the output folder's name are a name. A shell would make the marker in its folder (this
    // process's) or in root().
    const std::string marker = "PWNED";
    auto ran = [&] { return fs::exists(marker) || fs::exists(root() + "/" + marker); };
    fs::remove(marker);
    fs::remove(root() + "/" + marker);
    for (const std::string& name : {"q'$(touch " + marker + ")'", "b`touch " + marker + "`", "s; touch " + marker + ";",
                                    "n\ntouch " + marker}) {
        std::string quoted = "'";
        for (char c : root() + "/" + name)
            quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
        quoted += "'";
        CliRun r = ssaolab("bench merge " + shard(1) + " " + shard(2) + " --quiet --out " + quoted);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(fs::exists(root() + "/" + name + "/report.html")) << name;
        EXPECT_TRUE(fs::exists(root() + "/" + name + "/pareto.png")) << name << ": the plot was not drawn";
    }
    // bench itself, with the same syntax in a scene's file name (it reaches the plot's title) and
    // in --out.
    const std::string scene = root() + "/c'$(touch " + marker + ")`touch " + marker + "`;.gltf";
    fs::remove(scene);
    fs::create_symlink(std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf", scene);
    const std::string out = root() + "/o'$(touch " + marker + ")'";
    auto q = [](const std::string& s) {
        std::string quoted = "'";
        for (char c : s)
            quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return quoted + "'";
    };
    CliRun r = ssaolab("bench --scene " + q(scene) + " --size 64x36 --views 1 --frames 1 --warmup 0 --reference-rays 4 "
                       "--quiet --sweep " + writeTemp("merge_sweep1.json", R"({"name": "m", "groups": [{"name": "k", "set": {}}]})") +
                       " --out " + q(out));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(out + "/pareto.png")) << "the plot was not drawn";
    EXPECT_FALSE(ran()) << "a name ran as a shell command";
}

TEST_F(Merge, ShardsOfOneViewMergeWhetherTheirReferenceWasTracedOrCached) {
    // Both shards measure configurations of the one view: the first traces its reference, the
    // second finds it in the cache. The view is the same (name and camera); the rest is the shard's.
    const std::string sweep =
        writeTemp("merge_one_view.json", R"({"name": "one", "groups": [{"name": "k", "vary": {"kernel.samples": [8, 16, 32]}}]})");
    const std::string cache = root() + "/one_view_cache"; // empty: shard 1 traces, shard 2 reads the cache
    fs::remove_all(cache);
    for (int k = 1; k <= 2; ++k) {
        const std::string out = root() + "/one_view_" + std::to_string(k);
        fs::remove_all(out);
        CliRun r = ssaolab("bench --scene builtin:corner --size 64x36 --views 1 --frames 1 --warmup 0 --reference-rays 4 "
                           "--no-plot --quiet --sweep " + sweep + " --shard " + std::to_string(k) + "/2 --out " + out,
                           "SSAOLAB_CACHE_DIR=" + cache);
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    EXPECT_NE(results(root() + "/one_view_1")["scenes"][0]["viewpoints"][0]["reference_cached"],
              results(root() + "/one_view_2")["scenes"][0]["viewpoints"][0]["reference_cached"]);
    CliRun r = ssaolab("bench merge " + root() + "/one_view_1 " + root() + "/one_view_2 --no-plot --quiet --out " + root() + "/one_view");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    // A camera that differs is another view: refused, naming the folder.
    const std::string moved = root() + "/one_view_moved";
    fs::remove_all(moved);
    fs::copy(root() + "/one_view_2", moved, fs::copy_options::recursive);
    nlohmann::json j = results(moved);
    j["scenes"][0]["viewpoints"][0]["camera"]["eye"][0] = 123.0;
    rewrite(moved, j);
    expectCleanFailure(ssaolab("bench merge " + root() + "/one_view_1 " + moved + " --no-plot --quiet --out " + root() + "/o8"),
                       "differs from another folder's");
}
