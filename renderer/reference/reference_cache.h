// Disk cache of reference AO frames, keyed by everything the result depends on: the reference
// definition's version, the scene's content hash, the camera (as rendered: fitted clip planes),
// the size, R, the variant and the ray count. A second run with the same key loads in
// milliseconds instead of tracing for seconds or minutes.
#pragma once
#include "reference/reference_ao.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace ssao {

// Bumped whenever the reference's definition or sampling changes (old cache entries then miss).
// v2: hits backed off toward the eye (creases of interpenetrating solids), ambiguous pixels.
constexpr const char* kReferenceDefinition = "xegtao-v2";

// FNV-1a over the triangles' positions, normals and indices.
uint64_t sceneContentHash(const Scene& scene);

struct ReferenceKey {
    uint64_t sceneHash = 0;
    Camera camera;
    int width = 0, height = 0;
    ReferenceSettings settings;
    // The scene has MASK triangles, which the oracle holds as sheets (screen_layers.h): its entries
    // traced before that miss; other scenes' keys stay as they were.
    bool sheets = false;
    std::string text() const; // human-readable, exact (floats as hex bits)
    std::string fileStem() const; // "ref-" + 16 hex digits of the text's hash
};

// $SSAOLAB_CACHE_DIR, else $XDG_CACHE_HOME/ssaolab, else ~/.cache/ssaolab; then /reference.
std::string referenceCacheDir();

std::optional<ReferenceImage> loadCachedReference(const ReferenceKey& key, const std::string& dir);
// Writes atomically (temporary file + rename); a failure to write only costs the next run time.
bool storeCachedReference(const ReferenceKey& key, const ReferenceImage& img, const std::string& dir);

// One scene's references: the Embree BVH is built on the first cache miss only.
class ReferenceProvider {
  public:
    explicit ReferenceProvider(const Scene& scene, std::string cacheDir = referenceCacheDir());
    ~ReferenceProvider();
    // Loads or traces (then stores) the reference of a view. `cached` says which happened.
    ReferenceImage get(const Camera& camera, int width, int height, const ReferenceSettings& settings,
                       const ReferenceTracer::Progress& progress = {}, bool* cached = nullptr);
    const EmbreeScene& embree(); // builds it if needed
    uint64_t sceneHash() const { return hash_; }
    const std::string& cacheDir() const { return dir_; }

  private:
    const Scene& scene_;
    uint64_t hash_;
    bool sheets_; // any MASK draw (ReferenceKey::sheets)
    std::string dir_;
    std::unique_ptr<EmbreeScene> embree_;
};

} // namespace ssao
