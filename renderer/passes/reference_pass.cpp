#include "passes/reference_pass.h"

#include "base/image.h"

namespace ssao {

void ReferencePass::setup(PassBuilder& b, const Settings&) const {
    // No reads: the error is computed on the CPU against ao.denoised when the app decides (not on
    // every AO change while a slider is dragged), so this pass never re-runs with the AO chain.
    b.write(describe("reference.ao", GL_R32F, 1, Display::Unit,
                     "ray-traced reference AO of this view (cosine-weighted visibility within the AO's "
                     "world radius, Embree), refined in the background"));
    b.write(
        describe("reference.error", GL_R32F, 1, Display::Signed,
                 "signed error ao.denoised - reference.ao: red too bright (under-occluded), blue too dark"));
}

namespace {
// Uploads a top-row-first CPU image into `tex`; nearest texel when the sizes differ (the graph's
// base size is reduced while the camera moves, the reference is traced at the full size).
void upload(const gl::Texture2D& tex, const std::vector<float>& src, int sw, int sh) {
    const int w = tex.width(), h = tex.height();
    std::vector<float> rows(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y) {
        const int sy = mapPixel(y, h, sh);
        float* dst = &rows[size_t(h - 1 - y) * size_t(w)]; // GL rows are bottom-up
        for (int x = 0; x < w; ++x)
            dst[x] = src[size_t(sy) * size_t(sw) + size_t(mapPixel(x, w, sw))];
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glTextureSubImage2D(tex.id(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, rows.data());
}
} // namespace

void ReferencePass::run(PassContext& ctx, const NoConfig&) {
    const ReferenceBuffers* b = buffers_.get();
    const gl::Texture2D& ao = ctx.in("reference.ao");
    const gl::Texture2D& error = ctx.in("reference.error");
    const bool have = b && b->width > 0 && b->height > 0 &&
                      b->ao.size() == size_t(b->width) * size_t(b->height) && b->error.size() == b->ao.size();
    if (!have) { // no reference of this view yet
        const float zero = 0.0f;
        glClearTexImage(ao.id(), 0, GL_RED, GL_FLOAT, &zero);
        glClearTexImage(error.id(), 0, GL_RED, GL_FLOAT, &zero);
        return;
    }
    upload(ao, b->ao, b->width, b->height);
    upload(error, b->error, b->width, b->height);
}

} // namespace ssao
