#include "metrics/error_places.h"

#include "metrics/error_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ssao {

namespace {

constexpr unsigned char kSky = 255;
constexpr double kPi = 3.14159265358979323846;

struct V3 {
    double x = 0, y = 0, z = 0;
};
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

struct Frame {
    const PlaceView& v;
    bool geo(int x, int y) const {
        if (x < 0 || y < 0 || x >= v.width || y >= v.height) return false;
        const size_t i = size_t(y) * v.width + x;
        return (!v.geometry || v.geometry[i] > 0.0f) && v.depth[i] > 0.0f && std::isfinite(v.depth[i]);
    }
    double z(int x, int y) const { return v.depth[size_t(y) * v.width + x]; }
    // View-space position (camera looks down -z; top row first).
    V3 pos(int x, int y) const {
        const double aspect = double(v.width) / v.height, d = z(x, y);
        const double nx = 2.0 * (x + 0.5) / v.width - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / v.height;
        const double half = v.orthoHalfHeight > 0 ? v.orthoHalfHeight : v.tanHalfFovY * d;
        return {nx * half * aspect, ny * half, -d};
    }
    // The neighbour step (+1 or -1, 0 if none) along (dx, dy) that continues this pixel's surface:
    // the side whose 1/z (linear in screen space on a plane) extrapolates best.
    int side(int x, int y, int dx, int dy) const {
        auto err = [&](int s) {
            const int x1 = x + s * dx, y1 = y + s * dy, x2 = x + 2 * s * dx, y2 = y + 2 * s * dy;
            if (!geo(x1, y1)) return INFINITY;
            if (!geo(x2, y2)) return float(std::abs(1.0 / z(x1, y1) - 1.0 / z(x, y)) * z(x, y)); // one step: its change
            return float(std::abs(2.0 / z(x1, y1) - 1.0 / z(x2, y2) - 1.0 / z(x, y)) * z(x, y));
        };
        const float a = err(1), b = err(-1);
        if (!std::isfinite(a) && !std::isfinite(b)) return 0;
        return a <= b ? 1 : -1;
    }
};

// Unit normals from the depth, facing the camera; (0,0,0) where a direction has no neighbour.
std::vector<V3> depthNormals(const Frame& f) {
    const int w = f.v.width, h = f.v.height;
    std::vector<V3> n(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!f.geo(x, y)) continue;
            const int sx = f.side(x, y, 1, 0), sy = f.side(x, y, 0, 1);
            if (!sx || !sy) continue;
            const V3 p = f.pos(x, y), ex = f.pos(x + sx, y) - p, ey = f.pos(x, y + sy) - p;
            V3 c = cross(ex, ey);
            const double len = std::sqrt(dot(c, c));
            if (!(len > 0)) continue;
            c = {c.x / len, c.y / len, c.z / len};
            if (dot(c, p) > 0) c = {-c.x, -c.y, -c.z}; // facing the eye at the origin
            n[size_t(y) * w + x] = c;
        }
    return n;
}

// Crease seeds: for each 4-neighbour pair on one surface whose normals part by more than the
// threshold, both pixels, with the pair's opening angle (concave) or -1 (convex).
std::vector<float> creaseSeeds(const Frame& f, const std::vector<V3>& n, const PlaceOptions& o) {
    const int w = f.v.width, h = f.v.height;
    std::vector<float> seed(size_t(w) * h, 0.0f); // 0 none, > 0 concave opening angle, -1 convex
    const double cosMin = std::cos(o.creaseMinDeg * kPi / 180.0);
    auto mark = [&](size_t i, float a) {
        if (a > 0) seed[i] = seed[i] > 0 ? std::min(seed[i], a) : a;
        else if (seed[i] == 0.0f) seed[i] = -1.0f;
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
                const int x2 = x + dx, y2 = y + dy;
                if (!f.geo(x, y) || !f.geo(x2, y2)) continue;
                const size_t a = size_t(y) * w + x, b = size_t(y2) * w + x2;
                const double za = f.z(x, y), zb = f.z(x2, y2);
                if (std::abs(za - zb) > o.silhouetteRelDepth * std::min(za, zb)) continue; // a silhouette, not a crease
                if (dot(n[a], n[a]) == 0 || dot(n[b], n[b]) == 0) continue;
                const double c = std::clamp(dot(n[a], n[b]), -1.0, 1.0);
                if (c > cosMin) continue;
                const bool concave = dot(f.pos(x2, y2) - f.pos(x, y), n[a]) > 0; // b rises off a's plane
                const float opening = float(180.0 - std::acos(c) * 180.0 / kPi);
                mark(a, concave ? opening : -1.0f);
                mark(b, concave ? opening : -1.0f);
            }
    return seed;
}

} // namespace

const char* placeName(Place p) {
    switch (p) {
    case Place::Border: return "border";
    case Place::Silhouette: return "silhouette";
    case Place::Crease: return "crease";
    case Place::Convex: return "convex";
    case Place::Open: return "open";
    }
    return "?";
}

PlaceMap classifyPlaces(const PlaceView& v, const PlaceOptions& o) {
    if (v.width <= 0 || v.height <= 0 || !v.depth || !(v.tanHalfFovY > 0) || !(v.radius > 0))
        throw std::invalid_argument("classifyPlaces: needs a size, the depth, the field of view and R");
    const Frame f{v};
    const int w = v.width, h = v.height;
    PlaceMap m{w, h, std::vector<unsigned char>(size_t(w) * h, kSky), std::vector<float>(size_t(w) * h, 0.0f),
               std::vector<float>(size_t(w) * h, 0.0f)};
    const std::vector<unsigned char> silhouette = edgeMask(v.geometry, v.depth, w, h, o.silhouettePx, o.silhouetteRelDepth);
    const std::vector<float> seed = creaseSeeds(f, depthNormals(f), o);
    const double pixelsPerUnitAtDepth1 = 0.5 * h / v.tanHalfFovY;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!f.geo(x, y)) continue;
            const size_t i = size_t(y) * w + x;
            m.radiusPx[i] = float(v.orthoHalfHeight > 0 ? v.radius * 0.5 * h / v.orthoHalfHeight
                                                        : v.radius * pixelsPerUnitAtDepth1 / f.z(x, y));
            const int toEdge = std::min({x, w - 1 - x, y, h - 1 - y});
            float nearest = 0; // the most acute concave seed within creasePx, or -1 for a convex one
            for (int yy = std::max(0, y - o.creasePx); yy <= std::min(h - 1, y + o.creasePx); ++yy)
                for (int xx = std::max(0, x - o.creasePx); xx <= std::min(w - 1, x + o.creasePx); ++xx) {
                    const float s = seed[size_t(yy) * w + xx];
                    if (s > 0) nearest = nearest > 0 ? std::min(nearest, s) : s;
                    else if (s < 0 && nearest == 0) nearest = -1;
                }
            Place p = Place::Open;
            if (toEdge + 0.5 < m.radiusPx[i]) p = Place::Border;
            else if (silhouette[i]) p = Place::Silhouette;
            else if (nearest > 0) p = Place::Crease, m.openingDeg[i] = nearest;
            else if (nearest < 0) p = Place::Convex;
            m.place[i] = static_cast<unsigned char>(p);
        }
    return m;
}

ErrorByPlace errorByPlace(const PlaceMap& m, const float* test, const float* reference, const float* oracle,
                          const float* exclude) {
    if (!test || !reference) throw std::invalid_argument("errorByPlace: needs the AO and the reference");
    ErrorByPlace out;
    out.hasOracle = oracle != nullptr;
    for (size_t i = 0; i < m.place.size(); ++i) {
        if (m.place[i] == kSky || (exclude && exclude[i] > 0.0f)) continue;
        const float t = std::isfinite(test[i]) ? test[i] : 1.0f;
        const double e = double(t) - reference[i], eo = oracle ? double(t) - oracle[i] : 0.0;
        auto add = [&](PlaceStats& s) { ++s.pixels, s.sumSq += e * e, s.sumSigned += e, s.sumSqOracle += eo * eo; };
        add(out.place[m.place[i]]);
        add(out.all);
        const float r = m.radiusPx[i];
        add(out.radius[r < 8.0f ? 0 : r <= 16.0f ? 1 : 2]);
        if (m.place[i] == static_cast<unsigned char>(Place::Crease)) {
            const float a = m.openingDeg[i];
            add(out.opening[a < 80.0f ? 0 : a <= 120.0f ? 1 : 2]);
        }
    }
    return out;
}

void accumulate(ErrorByPlace& into, const ErrorByPlace& v) {
    auto add = [](PlaceStats& a, const PlaceStats& b) {
        a.pixels += b.pixels, a.sumSq += b.sumSq, a.sumSigned += b.sumSigned, a.sumSqOracle += b.sumSqOracle;
    };
    for (int i = 0; i < kPlaces; ++i) add(into.place[size_t(i)], v.place[size_t(i)]);
    for (int i = 0; i < kRadiusBins; ++i) add(into.radius[size_t(i)], v.radius[size_t(i)]);
    for (int i = 0; i < kOpeningBins; ++i) add(into.opening[size_t(i)], v.opening[size_t(i)]);
    add(into.all, v.all);
    into.hasOracle = into.hasOracle || v.hasOracle;
}

namespace {
nlohmann::json orNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json statsJson(const PlaceStats& s, const ErrorByPlace& e) {
    const double n = double(s.pixels);
    nlohmann::json j = {{"pixels", s.pixels},
                        {"pixel_share", orNull(e.all.pixels ? n / double(e.all.pixels) : NAN)},
                        {"rmse", orNull(s.pixels ? std::sqrt(s.sumSq / n) : NAN)},
                        {"bias", orNull(s.pixels ? s.sumSigned / n : NAN)},
                        {"share", orNull(e.all.sumSq > 0 ? s.sumSq / e.all.sumSq : NAN)}};
    if (e.hasOracle) j["technique_rmse"] = orNull(s.pixels ? std::sqrt(s.sumSqOracle / n) : NAN);
    return j;
}
} // namespace

nlohmann::json errorByPlaceJson(const ErrorByPlace& e) {
    nlohmann::json places, radius, opening;
    for (int i = 0; i < kPlaces; ++i) places[placeName(Place(i))] = statsJson(e.place[size_t(i)], e);
    const char* rNames[kRadiusBins] = {"under_8", "8_to_16", "over_16"};
    for (int i = 0; i < kRadiusBins; ++i) radius[rNames[i]] = statsJson(e.radius[size_t(i)], e);
    const char* oNames[kOpeningBins] = {"under_80", "80_to_120", "over_120"};
    for (int i = 0; i < kOpeningBins; ++i) opening[oNames[i]] = statsJson(e.opening[size_t(i)], e);
    return {{"how_to_read", "share: the place's part of the view's squared error (the shares add to 1); pixel_share: its "
                            "part of the geometry pixels; bias: mean(AO - truth), + too bright; places by priority: border "
                            "(nearer the frame's edge than R in pixels), silhouette (within 2 px of a depth discontinuity), "
                            "crease (within 2 px of a concave normal discontinuity; by opening angle), convex (an outer "
                            "edge), open"},
            {"places", places}, {"radius_px", radius}, {"crease_opening_deg", opening}, {"all", statsJson(e.all, e)}};
}

namespace {
const char* const kRadiusNames[kRadiusBins] = {"r_under_8", "r_8_to_16", "r_over_16"};
const char* const kOpeningNames[kOpeningBins] = {"crease_under_80", "crease_80_to_120", "crease_over_120"};

// Every place and bin with its stats, in one order (writer and reader).
template <typename E, typename F>
void eachSum(E& e, F&& f) {
    for (int i = 0; i < kPlaces; ++i) f(placeName(Place(i)), e.place[size_t(i)]);
    for (int i = 0; i < kRadiusBins; ++i) f(kRadiusNames[i], e.radius[size_t(i)]);
    for (int i = 0; i < kOpeningBins; ++i) f(kOpeningNames[i], e.opening[size_t(i)]);
    f("all", e.all);
}
} // namespace

nlohmann::json placeSumsJson(const ErrorByPlace& e) {
    nlohmann::json j = {{"has_oracle", e.hasOracle}};
    eachSum(e, [&](const char* name, const PlaceStats& s) { j[name] = {s.pixels, s.sumSq, s.sumSigned, s.sumSqOracle}; });
    return j;
}

ErrorByPlace placeSumsFromJson(const nlohmann::json& j) {
    if (!j.is_object() || !j.contains("has_oracle") || !j["has_oracle"].is_boolean())
        throw std::invalid_argument("'has_oracle' is not true or false");
    ErrorByPlace e;
    e.hasOracle = j["has_oracle"].get<bool>();
    eachSum(e, [&](const char* name, PlaceStats& s) {
        const auto it = j.find(name);
        if (it == j.end() || !it->is_array() || it->size() != 4 || !(*it)[0].is_number_integer())
            throw std::invalid_argument(std::string("'") + name + "' is not [pixels, sum of squares, signed sum, sum of squares vs the oracle]");
        for (int k = 1; k < 4; ++k)
            if (!(*it)[size_t(k)].is_number() || !std::isfinite((*it)[size_t(k)].get<double>()))
                throw std::invalid_argument(std::string("'") + name + "' holds a value that is not a finite number");
        s = {(*it)[0].get<long>(), (*it)[1].get<double>(), (*it)[2].get<double>(), (*it)[3].get<double>()};
        if (s.pixels < 0 || s.sumSq < 0 || s.sumSqOracle < 0) throw std::invalid_argument(std::string("'") + name + "' is negative");
    });
    return e;
}

std::string errorByPlaceLine(const ErrorByPlace& e) {
    std::string out = "error by place (share of the squared error, RMSE, share of the pixels):";
    char b[96];
    for (int i = 0; i < kPlaces; ++i) {
        const PlaceStats& s = e.place[size_t(i)];
        if (!s.pixels) continue;
        std::snprintf(b, sizeof b, " %s %.0f%% %.4f (%.0f%%)", placeName(Place(i)),
                      e.all.sumSq > 0 ? 100.0 * s.sumSq / e.all.sumSq : 0.0, std::sqrt(s.sumSq / double(s.pixels)),
                      100.0 * double(s.pixels) / double(e.all.pixels));
        out += b;
    }
    return out;
}

} // namespace ssao
