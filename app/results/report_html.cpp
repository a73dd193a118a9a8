#include "results/report_html.h"

#include "measure/thumbnails.h"
#include "metrics/motion_metrics.h"
#include "results/bench_report.h"
#include "output/escape.h"
#include "util/error.h"
#include "util/files.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iterator>
#include <map>
#include <sstream>

namespace ssao {

std::string base64(const std::string& bytes) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const unsigned a = static_cast<unsigned char>(bytes[i]);
        const unsigned b = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0;
        const unsigned c = i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0;
        const unsigned n = (a << 16) | (b << 8) | c;
        out += k[(n >> 18) & 63];
        out += k[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? k[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? k[n & 63] : '=';
    }
    return out;
}

namespace {

std::string fmt(double v, int digits = 4) {
    if (!std::isfinite(v)) return "–";
    char b[32];
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    return b;
}

// A PNG file of the output folder as an <img> (data: URI), or a placeholder naming what is missing.
// Read as foreign input: a link or a FIFO planted in the folder is never followed or waited on.
std::string img(const std::string& root, const std::string& path, const std::string& alt) {
    const std::string relative = std::filesystem::path(path).lexically_relative(root).generic_string();
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec)))
        return "<div class=\"missing\">" + htmlText(alt) + ": not measured by these runs</div>";
    std::string bytes;
    try {
        bytes = readFileInside(root, relative, "thumbnail", size_t(4) << 20);
    } catch (const Error&) {
        return "<div class=\"missing\">" + htmlText(alt) + ": not a regular file inside the output folder</div>";
    }
    return "<img alt=\"" + htmlAttr(alt) + "\" title=\"" + htmlAttr(alt) + "\" src=\"data:image/png;base64," + base64(bytes) +
           "\">";
}

// "; also: vbao defaults" for a configuration listed under several names ("" for one).
std::string alsoKnownAs(const BenchConfig& c, const std::string& sep) {
    std::string out;
    for (const std::string& a : c.aliases)
        out += (out.empty() ? sep + "also: " : ", ") + a;
    return out;
}

struct Point {
    std::string label, hover;
    double t = 0, e = 0, tmin = 0, tmax = 0; // time as a multiple of the baseline's
    bool baseline = false, front = false;
};

// Labels: ~15 front points with 40-80-character keys cannot all be written on the plot
// without overlapping (they crowd at the low-error end). Each front point gets its number
// (fastest first) beside it, the baseline its name; the key under the plot (after "</svg>") spells
// them out. `front` is sorted fastest first; X, Y map a point to the plot.
void labelsAndKey(std::ostringstream& s, const std::vector<Point>& pts, const std::vector<const Point*>& front,
                  const std::function<double(double)>& X, const std::function<double(double)>& Y, double W,
                  const std::string& errName) {
    std::vector<std::array<double, 4>> taken;
    auto put = [&](const Point& p, const std::string& text) {
        const double w = 6.0 * double(text.size()) + 4, h = 12;
        for (auto [dx, dy] : std::vector<std::pair<double, double>>{{6, -5}, {6, 13}, {-6 - w, -5}, {-6 - w, 13}, {-w / 2, -9}, {-w / 2, 19}}) {
            const double x = X(p.t) + dx, y = Y(p.e) + dy;
            bool clash = x < 0 || x + w > W;
            for (const auto& r : taken)
                clash = clash || (x < r[2] && x + w > r[0] && y - h < r[3] && y > r[1]);
            if (clash && !(dx == -w / 2 && dy == 19)) continue;
            taken.push_back({x, y - h, x + w, y});
            s << "<text class=\"lbl" << (p.baseline ? " base" : "") << "\" x=\"" << x << "\" y=\"" << y << "\">"
              << htmlText(text) << "</text>";
            break;
        }
    };
    for (const Point& p : pts)
        if (p.baseline) put(p, p.label);
    for (size_t i = 0; i < front.size(); ++i)
        if (!front[i]->baseline) put(*front[i], std::to_string(i + 1));
    s << "</svg>";
    s << "<ol class=\"key\"" << (W < 600 ? " style=\"columns:1\"" : "") << ">";
    for (const Point* p : front)
        s << "<li>" << htmlText(p->label) << " <span class=\"num\">" << fmt(p->t, 3) << "x, " << errName << " " << fmt(p->e)
          << "</span></li>";
    s << "</ol>";
}

// Time-against-error plot: log x (time x baseline), linear y (RMSE), the front as a step line,
// the reference's noise floor as a grey band from 0.
std::string svgPlot(const std::vector<Point>& pts, const std::string& title, double noise, double W = 720,
                    const std::string& yAxis = "RMSE vs ray-traced reference") {
    const double H = W * 0.6, L = 62, R = 18, T = 30, B = 50;
    double xlo = 1e300, xhi = 0, yhi = 0;
    for (const Point& p : pts) {
        xlo = std::min(xlo, std::min(p.t, p.tmin)), xhi = std::max(xhi, std::max(p.t, p.tmax));
        yhi = std::max(yhi, p.e);
    }
    if (pts.empty()) xlo = 0.5, xhi = 2, yhi = 1;
    xlo /= 1.15, xhi *= 1.15, yhi = std::max(yhi * 1.1, noise * 1.2);
    if (!(xhi > xlo)) xhi = xlo * 2;
    if (!(yhi > 0)) yhi = 1;
    auto X = [&](double t) { return L + (std::log(t) - std::log(xlo)) / (std::log(xhi) - std::log(xlo)) * (W - L - R); };
    auto Y = [&](double e) { return H - B - e / yhi * (H - T - B); };
    std::ostringstream s;
    s << "<svg class=\"plot\" viewBox=\"0 0 " << W << " " << H << "\" width=\"" << W << "\" height=\"" << H
      << "\" role=\"img\" aria-label=\"" << htmlAttr(title) << "\">";
    s << "<text x=\"" << W / 2 << "\" y=\"18\" class=\"title\">" << htmlText(title) << "</text>";
    if (noise > 0)
        s << "<rect class=\"noise\" x=\"" << L << "\" y=\"" << Y(noise) << "\" width=\"" << W - L - R << "\" height=\""
          << Y(0) - Y(noise) << "\"><title>the reference's own noise: RMSE below " << fmt(noise, 3)
          << " is not resolved</title></rect>";
    for (int d = int(std::floor(std::log10(xlo))); d <= int(std::ceil(std::log10(xhi))); ++d)
        for (double m : {1.0, 2.0, 5.0}) {
            const double v = m * std::pow(10.0, d);
            if (v < xlo || v > xhi) continue;
            s << "<line class=\"grid\" x1=\"" << X(v) << "\" x2=\"" << X(v) << "\" y1=\"" << T << "\" y2=\"" << H - B
              << "\"/><text class=\"tick\" x=\"" << X(v) << "\" y=\"" << H - B + 14 << "\">" << fmt(v, 3) << "x</text>";
        }
    const double ystep = std::pow(10.0, std::floor(std::log10(yhi / 4)));
    const double step = yhi / ystep > 20 ? 5 * ystep : yhi / ystep > 8 ? 2 * ystep : ystep;
    for (double v = 0; v <= yhi; v += step)
        s << "<line class=\"grid\" x1=\"" << L << "\" x2=\"" << W - R << "\" y1=\"" << Y(v) << "\" y2=\"" << Y(v)
          << "\"/><text class=\"tick y\" x=\"" << L - 5 << "\" y=\"" << Y(v) + 4 << "\">" << fmt(v, 3) << "</text>";
    s << "<text class=\"axis\" x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 12
      << "\">AO + denoise GPU time, x the baseline's on the same view and machine (log)</text>"
      << "<text class=\"axis\" transform=\"translate(14 " << (T + H - B) / 2
      << ") rotate(-90)\">" << htmlText(yAxis) << "</text>";
    std::vector<const Point*> front;
    for (const Point& p : pts)
        if (p.front) front.push_back(&p);
    std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->t < b->t; });
    if (!front.empty()) {
        s << "<polyline class=\"front\" points=\"";
        for (size_t i = 0; i < front.size(); ++i) {
            if (i) s << X(front[i]->t) << "," << Y(front[i - 1]->e) << " ";
            s << X(front[i]->t) << "," << Y(front[i]->e) << " ";
        }
        s << X(xhi) << "," << Y(front.back()->e) << "\"/>";
    }
    for (const Point& p : pts) {
        if (p.tmax > p.tmin)
            s << "<line class=\"bar\" x1=\"" << X(p.tmin) << "\" x2=\"" << X(p.tmax) << "\" y1=\"" << Y(p.e) << "\" y2=\""
              << Y(p.e) << "\"/>";
        s << "<circle class=\"pt" << (p.front ? " on" : "") << (p.baseline ? " base" : "") << "\" cx=\"" << X(p.t)
          << "\" cy=\"" << Y(p.e) << "\" r=\"" << (p.baseline ? 6 : p.front ? 4.5 : 3.2) << "\"><title>"
          << htmlText(p.hover) << "</title></circle>";
    }
    labelsAndKey(s, pts, front, X, Y, W, yAxis.rfind("motion score", 0) == 0 ? "motion score" : "RMSE");
    std::ostringstream box;
    box << "<div class=\"plotbox\" style=\"max-width:" << W + 10 << "px\">" << s.str() << "</div>";
    return box.str();
}

// Per configuration over `rows`: geometric mean of the time ratios, RMS of the RMSE, the min..max
// bar in ratio units; the front of these points.
// Each point on the front of (time, error) or not.
void markFront(std::vector<Point>& pts) {
    std::vector<double> t, e;
    for (const Point& p : pts)
        t.push_back(p.t), e.push_back(p.e);
    const std::vector<bool> f = paretoFront(t, e);
    for (size_t i = 0; i < pts.size(); ++i)
        pts[i].front = f[i];
}

// bench --motion: each configuration's time against its motion score (over all scenes), with its
// own front: what a moving camera is answered with.
std::vector<Point> motionPoints(const BenchRun& run) {
    std::vector<Point> pts;
    for (const ConfigSummary& s : run.summary) {
        const double score = s.motionScore;
        if (!(s.timeRatio > 0) || !std::isfinite(score)) continue;
        Point p;
        p.label = run.sweep.configs[s.config].label;
        p.baseline = s.config == run.sweep.baseline;
        p.t = p.tmin = p.tmax = s.timeRatio, p.e = score;
        p.hover = p.label + "\ntime " + fmt(p.t, 3) + "x the baseline's\nmotion score " + fmt(score);
        pts.push_back(p);
    }
    markFront(pts);
    return pts;
}

// With motion columns: which error the front, the table's "front" column and the answers rank by.
std::string objectiveHtml(const BenchRun& run) {
    if (!run.facts.contains("motion")) return "";
    const Objective o = runObjective(run);
    return std::string("<p>Objective: <b>") + objectiveTitle(o) +
           "</b> (<code>--objective " + objectiveKey(o) + "</code>): the front marked in the table and the "
           "thumbnails, and every answer, rank by it; both fronts are plotted.</p>";
}

// With motion columns: the moving camera's answer beside the still one, and whether they differ.
std::string motionAnswerHtml(const BenchRun& run) {
    const size_t m = mostAccurateInMotion(run);
    if (m == std::string::npos) return "";
    const ConfigSummary& s = run.summary[m];
    const std::string differ = winnersDifferLine(run, [](const std::string& x) { return htmlText(x); });
    return "<p>Lowest error in motion (motion score): <b>" + htmlText(run.sweep.configs[m].label) + "</b>: " +
           fmt(s.motionScore) + " at " + fmt(s.timeRatio, 3) +
           "x the baseline's time. " + differ + "</p>";
}

// A view's error under the run's objective: its still RMSE or its motion score (NaN: not measured).
double viewError(const ViewResult& v, Objective o) {
    if (o == Objective::Still) return v.error.rmse;
    return v.hasMotion ? motionScore(v.motion.rmseMean, v.motion.instability) : std::nan("");
}

// Per configuration over `rows`, the error of objective `o`.
std::vector<Point> pointsOf(const BenchRun& run, const std::vector<const ViewResult*>& rows, Objective o) {
    const size_t n = run.sweep.configs.size();
    std::vector<double> logT(n, 0), mse(n, 0), lo(n, 1e300), hi(n, 0);
    std::vector<int> count(n, 0);
    for (const ViewResult* v : rows) {
        const double e = viewError(*v, o);
        if (!(v->timeRatio > 0) || !std::isfinite(e)) continue;
        const double scale = v->timeRatio / v->gpuMs;
        logT[v->config] += std::log(v->timeRatio), mse[v->config] += e * e;
        lo[v->config] = std::min(lo[v->config], v->gpuMsMin * scale);
        hi[v->config] = std::max(hi[v->config], v->gpuMsMax * scale);
        ++count[v->config];
    }
    std::vector<Point> pts;
    for (size_t c = 0; c < n; ++c) {
        if (!count[c]) continue;
        Point p;
        p.label = run.sweep.configs[c].label;
        p.baseline = c == run.sweep.baseline;
        p.t = std::exp(logT[c] / count[c]), p.e = std::sqrt(mse[c] / count[c]);
        p.tmin = lo[c], p.tmax = hi[c];
        const double base = run.summary.size() > run.sweep.baseline ? objectiveError(run.summary[run.sweep.baseline], o) : NAN;
        p.hover = p.label + alsoKnownAs(run.sweep.configs[c], "\n") + "\ntime " + fmt(p.t, 3) + "x the baseline's\n" +
                  objectiveErrorName(o) + " " + fmt(p.e) + " (" + fmt(p.e / base, 3) + "x the baseline's over all scenes)";
        pts.push_back(p);
    }
    markFront(pts);
    return pts;
}

double noiseOf(const std::vector<const ViewResult*>& rows) {
    double sum = 0;
    for (const ViewResult* v : rows)
        sum += v->error.referenceNoise * v->error.referenceNoise;
    return rows.empty() ? 0 : std::sqrt(sum / double(rows.size()));
}

const char* kStyle = R"(<style>
body{font:14px/1.4 system-ui,sans-serif;margin:24px;color:#1a1a1a;max-width:1500px}
h1{font-size:22px}h2{font-size:18px;margin-top:28px}
svg.plot{background:#fff;border:1px solid #ddd;margin:4px 8px 8px 0}
svg .title{font-size:13px;text-anchor:middle;font-weight:600}svg .tick{font-size:10px;text-anchor:middle;fill:#555}
svg .tick.y{text-anchor:end}svg .axis{font-size:11px;text-anchor:middle;fill:#333}
svg .grid{stroke:#eee}svg .noise{fill:#e8e8e8}svg .bar{stroke:#ccc}
svg .pt{fill:#9a9a9a}svg .pt.on{fill:#d62728;stroke:#fff}svg .pt.base{fill:#000;stroke:#fff}
svg .pt:hover{stroke:#000;stroke-width:2}
svg .front{fill:none;stroke:#d62728;stroke-width:1.5;opacity:.8}svg .lbl{font-size:10px}.plotbox{display:inline-block;vertical-align:top}ol.key{font-size:11px;margin:0 0 12px 0;padding-left:26px;columns:2;column-gap:18px}ol.key .num{color:#777}svg .lbl.base{font-weight:700}
.plots{display:flex;flex-wrap:wrap}
table{border-collapse:collapse;font-size:12px}th,td{border:1px solid #ddd;padding:3px 6px}
th{background:#f4f4f4;cursor:pointer;position:sticky;top:0}td.n{text-align:right;font-variant-numeric:tabular-nums}
tr.on td:first-child{border-left:4px solid #d62728}tr.base td{font-weight:700}
.thumbs td{vertical-align:top}.thumbs img{display:block;width:192px;image-rendering:auto}
.missing{width:240px;color:#999;font-size:11px}.cap{font-size:11px;color:#555}
</style>)";

// First in <head>: records every error from here on, then checks the page once it has loaded: every
// image decodes, the plots are drawn, every table row is as wide as its first (no name split a row).
const char* kCheck = R"(<script>
window.__errors=[];window.addEventListener('error',function(e){__errors.push(String(e.message||e.type));},true);
(function(){var ce=console.error;console.error=function(){__errors.push([].join.call(arguments,' '));ce.apply(console,arguments);};})();
window.addEventListener('load',function(){
 var bad=[].filter.call(document.images,function(i){return !(i.complete&&i.naturalWidth>0);}).map(function(i){return i.alt;});
 var plots=document.querySelectorAll('svg.plot').length,pts=document.querySelectorAll('svg.plot circle.pt').length;
 var width=function(r){return [].reduce.call(r.cells,function(n,c){return n+c.colSpan;},0);};
 var uneven=[].filter.call(document.querySelectorAll('table'),function(t){return [].some.call(t.rows,function(r){return width(r)!==width(t.rows[0]);});}).length;
 var b=document.body;b.dataset.images=document.images.length;b.dataset.plots=plots;b.dataset.points=pts;
 b.dataset.check=bad.length?'images that did not decode: '+bad.join(', '):!plots||!pts?'no plot drawn':uneven?uneven+' table(s) with a row wider or narrower than the first':__errors.length?'errors: '+__errors.join('; '):'ok';
});
</script>)";

const char* kSort = R"(<script>
document.querySelectorAll('table.sortable').forEach(function(t){
 t.querySelectorAll('th').forEach(function(th,i){th.addEventListener('click',function(){
  var body=t.tBodies[0],rows=[].slice.call(body.rows),up=th.dataset.dir!=='up';th.dataset.dir=up?'up':'down';
  rows.sort(function(a,b){var x=a.cells[i].dataset.v,y=b.cells[i].dataset.v;
   if(x!==undefined&&y!==undefined){return up?x-y:y-x;}
   x=a.cells[i].textContent;y=b.cells[i].textContent;return up?x.localeCompare(y):y.localeCompare(x);});
  rows.forEach(function(r){body.appendChild(r);});});});});
</script>)";

std::string cell(double v, int digits = 4) {
    return std::string("<td class=\"n\" data-v=\"") + (std::isfinite(v) ? fmt(v, 10) : "1e300") + "\">" + fmt(v, digits) +
           "</td>";
}

// A time whose frames varied past kUnsureTimeSpread x their median on some view: marked, and why.
std::string unsureCell(double v) {
    char why[160];
    std::snprintf(why, sizeof why, "unsure: on a view, the slowest timed frame took more than %.3gx the median",
                  kUnsureTimeSpread);
    return std::string("<td class=\"n\" data-v=\"") + (std::isfinite(v) ? fmt(v, 10) : "1e300") + "\" title=\"" + why +
           "\">" + fmt(v, 4) + " (!)</td>";
}

// Every configuration, sortable by any column (click a header); with bench --motion, its error in motion.
std::string table(const BenchRun& run) {
    const bool motion = run.facts.contains("motion");
    std::ostringstream s;
    s << "<table class=\"sortable\"><thead><tr><th>configuration</th><th>group</th><th>technique</th>"
         "<th>x baseline time</th><th>ms (mean)</th><th>RMSE</th><th>x baseline RMSE</th><th>bias</th>"
         "<th>edge RMSE</th><th>PSNR geo dB</th><th>SSIM</th>"
      << (motion ? "<th title=\"RMS over views of the mean per-frame RMSE along the camera path\">motion RMSE</th>"
                   "<th title=\"RMS of the frame-to-frame AO change minus the reference's\">instability</th>"
                   "<th title=\"mean |error| in the first frames after a disocclusion minus at stable pixels\">"
                   "ghosting</th><th title=\"sqrt(motion RMSE^2 + instability^2)\">motion score</th>"
                   "<th>x baseline score</th>"
                 : "")
      << "<th>front" << (motion ? std::string(" (") + objectiveWhere(runObjective(run)) + ")" : "") << "</th></tr></thead><tbody>";
    for (const ConfigSummary& c : run.summary) {
        const BenchConfig& cfg = run.sweep.configs[c.config];
        s << "<tr class=\"" << (c.pareto ? "on" : "") << (cfg.baseline ? " base" : "") << "\"><td title=\""
          << htmlAttr(cfg.label + alsoKnownAs(cfg, "; ")) << "\">" << htmlText(cfg.label)
          << "</td><td>" << htmlText(cfg.group) << "</td><td>" << htmlText(cfg.technique()) << "</td>" << cell(c.timeRatio, 3)
          << (c.unsureTimeViews ? unsureCell(c.gpuMs) : cell(c.gpuMs)) << cell(c.rmse) << cell(c.rmseRatio, 3) << cell(c.bias, 3) << cell(c.rmseEdge)
          << cell(c.psnrGeometrySrgb) << cell(c.ssim);
        if (motion)
            s << cell(c.motion.rmseMean) << cell(c.motion.instability) << cell(c.motion.ghosting, 3) << cell(c.motionScore)
              << cell(c.motionRatio, 3);
        s << "<td>" << (c.pareto ? "yes" : "") << "</td></tr>";
    }
    s << "</tbody></table>";
    return s.str();
}

// The first viewpoint of each scene (the one with thumbnails), in the run's order.
std::vector<std::pair<std::string, std::string>> thumbViews(const BenchRun& run) {
    std::vector<std::pair<std::string, std::string>> out;
    if (run.facts.contains("scenes"))
        for (const auto& sc : run.facts["scenes"])
            if (sc.contains("viewpoints") && !sc["viewpoints"].empty())
                out.emplace_back(sc.value("name", ""), sc["viewpoints"][0].value("name", ""));
    return out;
}

// Thumbnails: the reference of each scene, then per front configuration and the baseline (fastest
// first) its AO and signed error on each scene, with its numbers.
std::string thumbnails(const BenchRun& run, const std::string& dir) {
    const auto views = thumbViews(run);
    std::vector<const ConfigSummary*> rows;
    for (const auto& c : run.summary) // and every web engine's row (bench --engines), beside them
        if (c.pareto || c.config == run.sweep.baseline || run.sweep.configs[c.config].isEngine()) rows.push_back(&c);
    std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return a->timeRatio < b->timeRatio; });
    std::ostringstream s;
    s << "<table class=\"thumbs\"><tr><td></td>";
    for (const auto& [scene, vp] : views)
        s << "<td colspan=\"2\"><b>" << htmlText(scene) << "</b> (" << htmlText(vp) << ")<br>"
          << img(dir, referenceThumbnail(thumbnailDir(dir, scene, vp)), scene + " reference")
          << "<div class=\"cap\">reference</div></td>";
    s << "</tr>";
    for (const ConfigSummary* c : rows) {
        const BenchConfig& cfg = run.sweep.configs[c->config];
        s << "<tr><td><b>" << htmlText(cfg.label) << "</b><br>" << fmt(c->timeRatio, 3) << "x the baseline's time ("
          << fmt(c->gpuMs) << " ms)<br>RMSE " << fmt(c->rmse) << " (" << fmt(c->rmseRatio, 3) << "x)"
          << (std::isfinite(c->motionScore) ? "<br>motion score " + fmt(c->motionScore) + " (" + fmt(c->motionRatio, 3) + "x)" : "")
          << "<br>bias "
          << fmt(c->bias, 3) << "</td>";
        for (const auto& [scene, vp] : views) {
            const std::string d = thumbnailDir(dir, scene, vp);
            s << "<td>" << img(dir, aoThumbnail(d, c->config), scene + ": " + cfg.label + " AO") << "<div class=\"cap\">AO</div></td><td>"
              << img(dir, errorThumbnail(d, c->config), scene + ": " + cfg.label + " error")
              << "<div class=\"cap\">error: blue too dark, red too bright (±0.25)</div></td>";
        }
        s << "</tr>";
    }
    s << "</table>";
    return s.str();
}

} // namespace

std::string benchHtml(const BenchRun& run, const std::string& dir, const Answer* answer) {
    std::vector<const ViewResult*> all;
    std::map<std::string, std::vector<const ViewResult*>> byScene;
    std::vector<std::string> sceneOrder;
    for (const ViewResult& v : run.views) {
        all.push_back(&v);
        if (!byScene.count(v.scene)) sceneOrder.push_back(v.scene);
        byScene[v.scene].push_back(&v);
    }
    const nlohmann::json f = run.facts.is_object() ? run.facts : nlohmann::json::object();
    std::ostringstream h;
    h << "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>ssaolab bench: "
      << htmlText(run.sweep.name) << "</title>" << kCheck << kStyle << "</head><body>";
    h << "<h1>Run time against error: " << htmlText(run.sweep.name) << "</h1>" << (answer ? answerHtml(run, *answer) : "")
      << "<p>" << htmlText(f.value("date", "")) << ", git "
      << htmlText(f.value("git_revision", "")) << "; " << htmlText(f.value("gl_renderer", "")) << " on " << htmlText(f.value("cpu", ""))
      << "; " << htmlText(f.value("size", "")) << "; " << f.value("frames", 0) << " timed frames (median) per configuration and view; "
      << run.sweep.configs.size() << " configurations; baseline <b>" << htmlText(run.sweep.configs[run.sweep.baseline].label)
      << "</b>. Hover a point for its configuration and numbers; red: the Pareto front (no configuration is both "
         "faster and more accurate); grey band: the reference's own noise.</p>";
    if (run.shards.size() > 1) {
        h << "<p>Merged from " << run.shards.size()
          << " shards; every row is timed against the baseline its own shard measured on the same view.</p>"
             "<table><tr><th>shard</th><th>host</th><th>CPU</th><th>GL renderer</th><th>rows</th></tr>";
        for (const auto& sh : run.shards)
            h << "<tr><td>" << htmlText(sh.value("shard", "")) << "</td><td>" << htmlText(sh.value("hostname", "")) << "</td><td>"
              << htmlText(sh.value("cpu", "")) << "</td><td>" << htmlText(sh.value("gl_renderer", "")) << "</td><td class=\"n\">"
              << sh.value("rows", 0) << "</td></tr>";
        h << "</table>";
    }
    const std::vector<Point> moving = motionPoints(run);
    const Objective o = runObjective(run);
    const char* kMotionAxis = "motion score: sqrt(RMSE^2 + instability^2)";
    const std::string stillPlot = svgPlot(pointsOf(run, all, Objective::Still),
                                          moving.empty() ? "all scenes" : "all scenes, still camera", noiseOf(all));
    const std::string motionPlot = moving.empty() ? "" : svgPlot(moving, "all scenes, in motion", 0.0, 720, kMotionAxis);
    h << "<h2>All scenes</h2>" << objectiveHtml(run) << motionAnswerHtml(run) << "<div class=\"plots\">"
      << (o == Objective::Motion ? motionPlot + stillPlot : stillPlot + motionPlot) << "</div>";
    h << "<h2>Per scene" << (moving.empty() ? "" : std::string(", ") + objectiveWhere(o)) << "</h2><div class=\"plots\">";
    for (const auto& sc : sceneOrder)
        h << (o == Objective::Motion ? svgPlot(pointsOf(run, byScene[sc], o), sc, 0.0, 560, kMotionAxis)
                                     : svgPlot(pointsOf(run, byScene[sc], o), sc, noiseOf(byScene[sc]), 560));
    const bool engines = std::any_of(run.sweep.configs.begin(), run.sweep.configs.end(), [](const BenchConfig& c) { return c.isEngine(); });
    h << "</div><h2>The front" << (engines ? ", the web engines" : "") << " and the baseline, side by side</h2>"
      << (engines ? "<p>Web engines (rows 'engine NAME'): run in Chromium on the same views, camera, size and R, scored "
                    "against the same reference; their time is the frame with the pass minus the frame without on "
                    "Chromium's WebGL (median), not a GL timer query.</p>"
                  : "")
      << thumbnails(run, dir)
      << "<h2>Every configuration</h2><p>Click a column to sort.</p>" << table(run) << kSort << "</body></html>\n";
    return h.str();
}

} // namespace ssao
