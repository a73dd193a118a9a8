// Thumbnails of a benchmark's first viewpoint of each scene, for report.html: per configuration
// the AO judged and its signed error heat map, and the reference once. PNG files under
// OUT/thumbs/, so a shard's folder carries them and `bench merge` finds them.
#pragma once
#include "metrics/evaluate.h"
#include "reference/reference_ao.h"

#include <string>

namespace ssao {

constexpr int kThumbnailWidth = 192; // px; the height keeps the view's aspect (6 scenes x the front fit report.html in 2 MiB)

// OUT/thumbs/<scene>__<viewpoint> with every character but [A-Za-z0-9._-] replaced by '_' (and then
// a hash of the exact names appended, so no two scenes share a folder).
std::string thumbnailDir(const std::string& outDir, const std::string& scene, const std::string& viewpoint);
std::string aoThumbnail(const std::string& dir, size_t config);    // dir/c<config>.ao.png
std::string errorThumbnail(const std::string& dir, size_t config); // dir/c<config>.error.png
std::string referenceThumbnail(const std::string& dir);            // dir/reference.png

// Box-filtered to kThumbnailWidth: the AO (sky in the views' grey) and error.png's heat map.
// The same images in memory (a page that embeds them: tune --engine's).
Image aoThumbnailImage(const Evaluation& e, const ReferenceImage& ref);
Image errorThumbnailImage(const Evaluation& e, const ReferenceImage& ref);
Image referenceThumbnailImage(const ReferenceImage& ref);

void writeThumbnails(const std::string& dir, size_t config, const Evaluation& e, const ReferenceImage& ref);
void writeReferenceThumbnail(const std::string& dir, const ReferenceImage& ref);

} // namespace ssao
