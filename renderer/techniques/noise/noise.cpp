#include "techniques/noise/noise.h"

namespace ssao {

std::vector<std::pair<std::string, AoNoise>> aoNoiseChoices() {
    return {{"ign", AoNoise::Ign}, {"r2", AoNoise::R2}, {"blue", AoNoise::Blue}, {"tile4", AoNoise::Tile4},
            {"none", AoNoise::None}};
}

const char* const kAoNoiseHelp =
    "Per-pixel rotation and step offset: interleaved gradient noise (Jimenez 2014), the R2 "
    "low-discrepancy sequence (Roberts 2018), a 64x64 blue-noise tile (void and cluster), a 4x4 random "
    "tile (the seeds' texture), or none (banding). All move per temporal frame.";

const char* const kPyramidHelp =
    "Taps far from the pixel read a coarser level of a position MIP pyramid (SAO, XeGTAO's depth "
    "prefilter): wide radii touch far fewer cache lines; nearby taps stay exact.";

void packNoise(gpu::AoCommon& c, AoNoise n) {
    static_assert(int(AoNoise::Ign) == SSAO_NOISE_IGN && int(AoNoise::R2) == SSAO_NOISE_R2 &&
                      int(AoNoise::Blue) == SSAO_NOISE_BLUE && int(AoNoise::Tile4) == SSAO_NOISE_TILE4 &&
                      int(AoNoise::None) == SSAO_NOISE_NONE,
                  "AoNoise follows SSAO_NOISE_*");
    c.estimator.y = float(int(n));
}

} // namespace ssao
