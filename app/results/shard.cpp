#include "results/shard.h"

#include "util/error.h"

#include <cerrno>
#include <cstdlib>

namespace ssao {

namespace {
bool parseInt(const std::string& s, int& out) {
    if (s.empty() || s.size() > 5) return false;
    for (char c : s)
        if (c < '0' || c > '9') return false;
    out = std::atoi(s.c_str());
    return true;
}
} // namespace

ShardSpec parseShard(const std::string& text) {
    const auto slash = text.find('/');
    ShardSpec s;
    if (slash == std::string::npos || !parseInt(text.substr(0, slash), s.index) ||
        !parseInt(text.substr(slash + 1), s.count) || s.count < 1 || s.count > 10000 || s.index < 1 ||
        s.index > s.count)
        throw Error("--shard '" + text + "': expected K/N with 1 <= K <= N <= 10000 (e.g. 2/4)");
    return s;
}

std::vector<WorkUnit> shardUnits(size_t scenes, size_t viewsPerScene, size_t configs, ShardSpec shard) {
    const size_t total = scenes * viewsPerScene * configs;
    const size_t n = size_t(shard.count), k = size_t(shard.index - 1);
    const size_t begin = total * k / n, end = total * (k + 1) / n;
    std::vector<WorkUnit> out;
    out.reserve(end - begin);
    for (size_t i = begin; i < end; ++i)
        out.push_back({i / (viewsPerScene * configs), (i / configs) % viewsPerScene, i % configs});
    return out;
}

} // namespace ssao
