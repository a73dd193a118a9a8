#include "closed_form.h"

#include "gl/readback.h"
#include "output/reference_report.h"

#include <cmath>
#include <map>

namespace ssaotest {

using namespace ssao;

double wallClosedForm(double d, double R) {
    const double a = std::min(d / R, 1.0);
    return 1.0 - (std::acos(a) - a * std::sqrt(1.0 - a * a)) / M_PI;
}

Evaluation judgeAgainstReference(Renderer& r, const EmbreeScene& rt, int rays) {
    const ReferenceImage ref = traceReference(rt, r.camera(), r.width(), r.height(),
                                              referenceSettingsFor(r.radiusAtCentre(), rays, ReferenceVariant::Visibility));
    return evaluate(readBack(r.texture("ao.denoised"), 1), ref);
}

CornerProfile cornerProfile(const Settings& s, const std::string& scene) {
    const int w = 320, h = 240;
    Rendered r = render(scene, s, w, h);
    const float R = s.ao.radius; // the tests give the corner a world radius
    const glm::mat4 invView = glm::inverse(r.camera.view());
    const glm::vec3 up = glm::normalize(glm::mat3(r.camera.view()) * glm::vec3(0, 1, 0));
    std::map<int, std::pair<double, int>> bins;
    for (int y = h - 1; y >= 0; --y)
        for (int x = w / 2 - 8; x <= w / 2 + 8; ++x) {
            if (r.position.at(x, y, 3) == 0.0f) continue;
            glm::vec3 n(r.normal.at(x, y, 0), r.normal.at(x, y, 1), r.normal.at(x, y, 2));
            if (glm::dot(n, up) < 0.99f) continue; // the wall
            const glm::vec3 pw = glm::vec3(invView * glm::vec4(r.position.at(x, y, 0), r.position.at(x, y, 1),
                                                               r.position.at(x, y, 2), 1.0f));
            const float d = pw.z + 2.0f; // wall face at z = -2
            if (d > 2.0f * R) continue;
            auto& b = bins[int(d / 0.05f)];
            b.first += r.ao.at(x, y);
            b.second += 1;
        }
    CornerProfile p;
    double se = 0, wall = 0, far = 0;
    int nWall = 0, nFar = 0;
    for (auto& [bin, acc] : bins) {
        const double d = (bin + 0.5) * 0.05, mean = acc.first / acc.second;
        const double e = mean - wallClosedForm(d, R);
        se += e * e;
        if (d < 0.1 * R) wall += mean, ++nWall;
        if (d > 1.5 * R) far += mean, ++nFar;
    }
    p.bins = bins.size();
    p.rmse = bins.empty() ? 1.0 : std::sqrt(se / double(bins.size()));
    p.atWall = nWall ? wall / nWall : 1.0;
    p.far = nFar ? far / nFar : 0.0;
    return p;
}

} // namespace ssaotest
