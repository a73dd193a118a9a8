#include "commands/tune/engine_tune_page.h"

#include "base/image.h"
#include "results/report_html.h"
#include "measure/thumbnails.h"
#include "output/escape.h"
#include "util/number_text.h"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <sstream>

namespace ssao {

namespace {

const char* kStyle = R"(<style>
body{font:14px/1.4 system-ui,sans-serif;margin:24px;color:#1a1a1a;max-width:1500px}
h1{font-size:22px}h2{font-size:18px;margin-top:28px}.machine{font-size:12px;color:#555}
table{border-collapse:collapse;font-size:12px}th,td{border:1px solid #ddd;padding:3px 6px}
th{background:#f4f4f4}td.n{text-align:right;font-variant-numeric:tabular-nums}
.thumbs td{vertical-align:top}.thumbs img{display:block;width:192px}.cap{font-size:11px;color:#555}
</style>)";

std::string num(double v, const char* fmt = "%.4f") {
    return numberText(v, fmt);
}

std::string ratio(double a, double b) {
    return b > 0 && std::isfinite(a) ? " <span class=\"cap\">x" + num(a / b, "%.3f") + "</span>" : "";
}

std::string img(const Image& im, const std::string& alt) {
    return "<img alt=\"" + htmlAttr(alt) + "\" src=\"data:image/png;base64," + base64(encodePng(im)) + "\">";
}

std::string factsLine(const nlohmann::json& f) {
    std::string s;
    for (const auto& [k, v] : f.items())
        s += (s.empty() ? "" : " · ") + k + ": " + (v.is_string() ? v.get<std::string>() : v.dump());
    return htmlText(s);
}

void settingsTable(std::ostringstream& h, const EnginePage& p) {
    h << "<h2>Settings</h2><table><tr><th>parameter</th><th>as shipped</th><th>defaults (lengths from R)</th><th>tuned</th><th>role</th>"
         "<th>unit</th></tr>";
    for (const auto& row : p.settings) {
        h << "<tr>";
        for (size_t i = 0; i < row.size(); ++i)
            h << (i >= 1 && i <= 3 ? "<td class=\"n\">" : "<td>") << htmlText(row[i]) << "</td>";
        h << "</tr>";
    }
    h << "</table>";
}

void scoresTable(std::ostringstream& h, const EnginePage& p) {
    h << "<h2>Error and time</h2><table><tr><th>scene</th><th>which views</th><th>views</th><th>RMSE as shipped</th>"
         "<th>RMSE lengths from R</th><th>RMSE tuned (x the baseline judged against)</th><th>AO ms as shipped</th><th>AO ms lengths from R</th>"
         "<th>AO ms tuned (x shipped)</th><th>ssaolab within the tuned time (shown view)</th><th>its RMSE</th><th>its ms</th></tr>";
    for (const PageRow& r : p.rows) {
        h << "<tr><td>" << htmlText(r.scene) << "</td><td>" << htmlText(r.role) << "</td><td class=\"n\">" << r.views << "</td>"
          << "<td class=\"n\">" << num(r.shipped.rmse) << "</td><td class=\"n\">" << num(r.defaults.rmse) << "</td><td class=\"n\">"
          << num(r.tuned.rmse) << ratio(r.tuned.rmse, p.baseline == "as shipped" ? r.shipped.rmse : r.defaults.rmse)
          << "</td><td class=\"n\">"
          << num(r.shipped.ms, "%.1f") << "</td><td class=\"n\">" << num(r.defaults.ms, "%.1f") << "</td><td class=\"n\">"
          << num(r.tuned.ms, "%.1f") << ratio(r.tuned.ms, r.shipped.ms) << "</td>";
        if (r.hasSsaolab)
            h << "<td>" << htmlText(r.ssaolab.label) << "</td><td class=\"n\">" << num(r.ssaolab.rmse) << "</td><td class=\"n\">"
              << num(r.ssaolab.ms, "%.1f") << "</td>";
        else
            h << "<td colspan=\"3\" class=\"cap\">" << (r.shownView.empty() ? "" : "no shipped preset this fast") << "</td>";
        h << "</tr>";
    }
    h << "</table>";
}

void thumbCell(std::ostringstream& h, const PageEntry& e, const ReferenceImage& ref, const std::string& what) {
    // This view's own RMSE under its thumbnail (the tables give the mean over the row's views).
    h << "<td><div class=\"cap\">" << htmlText(what) << " · this view's RMSE " << num(e.eval ? e.eval->metrics.rmse : e.rmse)
      << "</div>";
    if (e.eval) h << img(aoThumbnailImage(*e.eval, ref), what + " AO") << img(errorThumbnailImage(*e.eval, ref), what + " error");
    h << "</td>";
}

void thumbnails(std::ostringstream& h, const EnginePage& p) {
    h << "<h2>Thumbnails</h2><p>Each scene's first held-out view: the AO (top) and its signed error against the reference "
         "(bottom; blue: too dark, red: too bright, white: right).</p><table class=\"thumbs\">";
    for (const PageRow& r : p.rows) {
        if (r.shownView.empty() || !r.ref || !r.tuned.eval) continue;
        h << "<tr><td><div class=\"cap\">" << htmlText(r.scene + " · " + r.shownView) << " · reference</div>"
          << img(referenceThumbnailImage(*r.ref), "reference") << "</td>";
        thumbCell(h, r.shipped, *r.ref, p.title + " as shipped");
        thumbCell(h, r.defaults, *r.ref, p.title + " lengths from R");
        thumbCell(h, r.tuned, *r.ref, p.title + " tuned");
        if (r.hasSsaolab) thumbCell(h, r.ssaolab, *r.ref, "ssaolab " + r.ssaolab.label);
        h << "</tr>";
    }
    h << "</table>";
}

} // namespace

std::string engineTunePageHtml(const EnginePage& p) {
    std::ostringstream h;
    h << "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << htmlText(p.title) << " tuned</title>" << kStyle
      << "</head><body><h1>" << htmlText(p.title + " (" + p.package + " " + p.version + ") tuned against the ray-traced reference, " + p.size)
      << "</h1><p class=\"machine\">" << factsLine(p.facts) << "</p>"
      << "<p>Held-out geometry RMSE " << num(p.heldBefore) << " (the engine " << htmlText(p.baseline)
      << ", the better of its two baselines) → " << num(p.heldAfter) << " (x" << num(p.heldAfter / p.heldBefore, "%.3f")
      << ") at x" << num(p.timeRatio, "%.3f") << " the shipped AO time; tuning took " << num(p.seconds, "%.0f") << " s.</p>"
      << "<p>" << htmlText(p.radius) << "</p>"
      << "<p class=\"cap\">" << htmlText(p.metric) << ". Training views were fitted; held-out views and scenes were not: "
      << "their ratio is the gain that carries over. ssaolab's column is the most accurate shipped preset whose AO time on the "
         "shown view is at most the tuned engine's there (ssaolab: GL timer queries of AO + denoise; the engine: its frame with "
         "the pass minus without, in the browser).</p>";
    settingsTable(h, p);
    scoresTable(h, p);
    thumbnails(h, p);
    h << "</body></html>\n";
    return h.str();
}

} // namespace ssao
