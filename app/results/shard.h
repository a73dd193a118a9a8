// Splitting a benchmark over machines: `bench --shard K/N` runs a deterministic 1/N of the work
// units, so a CI matrix, a Slurm array or GNU parallel can run the N parts anywhere, and
// `bench merge` joins them. Pure: no GL, no files.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace ssao {

struct ShardSpec {
    int index = 1, count = 1; // K of N, 1-based
    bool whole() const { return count == 1; }
    std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// "K/N" with 1 <= K <= N <= 10000. Throws ssao::Error naming the text.
ShardSpec parseShard(const std::string& text);

// A work unit: one configuration on one viewpoint of one scene.
struct WorkUnit {
    size_t scene = 0, view = 0, config = 0;
};

// The units of shard K/N: all units in scene-major order (scene, then viewpoint, then
// configuration), cut into N contiguous runs whose sizes differ by at most one. Contiguous, so a
// shard traces the reference of as few viewpoints as possible; every unit is in exactly one shard.
std::vector<WorkUnit> shardUnits(size_t scenes, size_t viewsPerScene, size_t configs, ShardSpec shard);

} // namespace ssao
