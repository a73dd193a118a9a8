#include "reference/reference_cache.h"

#include "base/image.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/json_file.h"
#include "util/user_dirs.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace fs = std::filesystem;

namespace ssao {

namespace {
constexpr uint64_t kFnvOffset = 1469598103934665603ull, kFnvPrime = 1099511628211ull;

uint64_t fnv(uint64_t h, const void* data, size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i)
        h = (h ^ p[i]) * kFnvPrime;
    return h;
}

std::string bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    return hex(u);
}

std::string vec(const glm::vec3& v) { return bits(v.x) + "," + bits(v.y) + "," + bits(v.z); }
} // namespace

uint64_t sceneContentHash(const Scene& scene) {
    uint64_t h = kFnvOffset;
    h = fnv(h, scene.vertices.data(), scene.vertices.size() * sizeof(Vertex));
    h = fnv(h, scene.indices.data(), scene.indices.size() * sizeof(uint32_t));
    // MASK cut-outs change what occludes (scenes without them hash as before).
    h = fnv(h, scene.uvs.data(), scene.uvs.size() * sizeof(glm::vec2));
    for (const Draw& d : scene.draws)
        if (d.mask) {
            h = fnv(h, &d.firstIndex, sizeof d.firstIndex);
            h = fnv(h, &d.alphaCutoff, sizeof d.alphaCutoff);
            h = fnv(h, &d.baseColor.w, sizeof d.baseColor.w);
            if (d.alphaTexture >= 0) {
                const AlphaTexture& t = scene.alphaTextures[size_t(d.alphaTexture)];
                const int32_t meta[4] = {t.width, t.height, int32_t(t.wrapS), int32_t(t.wrapT)};
                h = fnv(h, meta, sizeof meta);
                h = fnv(h, t.alpha.data(), t.alpha.size());
            }
        }
    return h;
}

std::string ReferenceKey::text() const {
    std::ostringstream s;
    s << kReferenceDefinition << " scene=" << std::hex << sceneHash << std::dec << " eye=" << vec(camera.eye)
      << " target=" << vec(camera.target) << " up=" << vec(camera.up) << " fov=" << bits(camera.fovYDeg)
      << " near=" << bits(camera.nearZ) << " far=" << bits(camera.farZ) << " size=" << width << "x" << height
      << " R=" << bits(settings.radius) << " variant=" << variantName(settings.variant)
      << " rays=" << settings.samples;
    if (camera.orthographic()) s << " projection=orthographic"; // perspective keys stay as they were
    if (settings.visibility == ReferenceVisibility::Screen)
        s << " visibility=screen layers=" << settings.layers << " thickness=" << bits(settings.thickness)
          << " separation=" << bits(settings.layerSeparation) << " guard=" << settings.guardBand
          << " second=backface-v5" // the second layer: the back face when it is next (screen_layers.h)
          << (sheets ? " sheets=mask" : "");
    return s.str();
}

std::string ReferenceKey::fileStem() const {
    const std::string t = text();
    char buf[32];
    std::snprintf(buf, sizeof buf, "ref-%016llx", (unsigned long long)fnv(kFnvOffset, t.data(), t.size()));
    return buf;
}

std::string referenceCacheDir() {
    std::string base = envValue("SSAOLAB_CACHE_DIR");
    if (base.empty()) base = xdgUserDir("XDG_CACHE_HOME", ".cache");
    if (base.empty()) base = ".ssaolab-cache";
    return base + "/reference";
}

namespace {

// A cache entry is data from disk: anything a trace cannot have produced makes it a miss (then the
// trace overwrites it) - never a "RMSE 6.01" from an AO of 7, or a ray count of -2147483648.
bool validEntry(const nlohmann::json& meta, const Image& px, const ReferenceKey& key) {
    if (px.width != key.width || px.height != key.height || px.channels != 4) return false;
    const auto& samples = meta.at("samples");
    const auto& seconds = meta.at("seconds");
    const auto& rays = meta.at("ao_rays");
    if (!samples.is_number_integer() || samples.get<long long>() != key.settings.samples) return false;
    if (!seconds.is_number() || !std::isfinite(seconds.get<double>()) || seconds.get<double>() < 0) return false;
    const double maxRays = double(key.settings.samples) * double(px.width) * double(px.height);
    if (!rays.is_number_integer() || rays.get<long long>() < 0 || double(rays.get<long long>()) > maxRays) return false;
    for (size_t i = 0; i < size_t(px.width) * size_t(px.height); ++i) {
        const float ao = px.data[4 * i], se = px.data[4 * i + 1], depth = px.data[4 * i + 2], g = px.data[4 * i + 3];
        if (!(ao >= 0.0f && ao <= 1.0f) || !(se >= 0.0f && se <= 0.5f) || !(depth >= 0.0f) || !std::isfinite(depth))
            return false;
        if (g != 0.0f && g != 1.0f && g != 2.0f) return false; // sky, geometry, ambiguous geometry
    }
    return true;
}

} // namespace

std::optional<ReferenceImage> loadCachedReference(const ReferenceKey& key, const std::string& dir) {
    const fs::path stem = fs::path(dir) / key.fileStem();
    std::error_code ec;
    if (!fs::is_regular_file(stem.string() + ".json", ec) || !fs::is_regular_file(stem.string() + ".exr", ec))
        return std::nullopt;
    try {
        const nlohmann::json meta = readJsonFile(stem.string() + ".json", "reference cache entry");
        if (!meta.is_object() || meta.value("key", std::string()) != key.text()) return std::nullopt; // a collision
        // Budgeted to the key's own size: a larger header is not this entry, and is never decoded.
        const ImageBudget exactly{uint64_t(key.width) * uint64_t(key.height), 0, "this entry", ""};
        const Image px = readExr(stem.string() + ".exr", exactly, "reference cache entry");
        if (!validEntry(meta, px, key)) return std::nullopt;
        ReferenceImage img;
        img.width = px.width;
        img.height = px.height;
        img.samples = meta.at("samples").get<int>();
        img.seconds = meta.at("seconds").get<double>();
        img.aoRays = meta.at("ao_rays").get<long long>();
        const size_t n = size_t(px.width) * px.height;
        for (auto* v : {&img.ao, &img.stdErr, &img.depth, &img.geometry, &img.ambiguous})
            v->resize(n);
        for (size_t i = 0; i < n; ++i) {
            img.ao[i] = px.data[4 * i];
            img.stdErr[i] = px.data[4 * i + 1];
            img.depth[i] = px.data[4 * i + 2];
            const float a = px.data[4 * i + 3]; // 0 sky, 1 geometry, 2 ambiguous geometry
            img.geometry[i] = a > 0.5f ? 1.0f : 0.0f;
            img.ambiguous[i] = a > 1.5f ? 1.0f : 0.0f;
        }
        return img;
    } catch (const std::exception&) {
        return std::nullopt; // a corrupt entry is a miss; the trace overwrites it
    }
}

bool storeCachedReference(const ReferenceKey& key, const ReferenceImage& img, const std::string& dir) {
    try {
        fs::create_directories(dir);
        const fs::path stem = fs::path(dir) / key.fileStem();
        Image px{img.width, img.height, 4, std::vector<float>(size_t(img.width) * img.height * 4)};
        for (size_t i = 0; i < img.ao.size(); ++i) {
            px.data[4 * i] = img.ao[i];
            px.data[4 * i + 1] = img.stdErr[i];
            px.data[4 * i + 2] = img.depth[i];
            px.data[4 * i + 3] =
                img.geometry[i] + (i < img.ambiguous.size() && img.ambiguous[i] > 0.0f ? 1.0f : 0.0f);
        }
        // Each file atomically; the JSON last, so a reader never pairs it with a half-written image
        // (and a mismatched pair fails validation: a miss).
        writeExr(px, stem.string() + ".exr");
        const nlohmann::json meta = {{"key", key.text()},     {"samples", img.samples},
                                     {"seconds", img.seconds}, {"ao_rays", img.aoRays},
                                     {"channels", "R=ao G=stderr B=depth A=geometry (2 = ambiguous)"}};
        writeFileAtomically(stem.string() + ".json", dumpJson(meta) + "\n");
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

ReferenceProvider::ReferenceProvider(const Scene& scene, std::string cacheDir)
    : scene_(scene), hash_(sceneContentHash(scene)),
      sheets_(std::any_of(scene.draws.begin(), scene.draws.end(), [](const Draw& d) { return d.mask; })),
      dir_(std::move(cacheDir)) {}

ReferenceProvider::~ReferenceProvider() = default;

const EmbreeScene& ReferenceProvider::embree() {
    if (!embree_) embree_ = std::make_unique<EmbreeScene>(scene_);
    return *embree_;
}

ReferenceImage ReferenceProvider::get(const Camera& camera, int width, int height,
                                      const ReferenceSettings& settings, const ReferenceTracer::Progress& progress,
                                      bool* cached) {
    const ReferenceKey key{hash_, camera, width, height, settings, sheets_};
    if (!dir_.empty())
        if (auto hit = loadCachedReference(key, dir_)) {
            if (cached) *cached = true;
            return *hit;
        }
    if (cached) *cached = false;
    ReferenceImage img = traceReference(embree(), camera, width, height, settings, progress);
    if (!dir_.empty()) storeCachedReference(key, img, dir_);
    return img;
}

} // namespace ssao
