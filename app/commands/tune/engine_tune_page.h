// `tune --engine`'s report page (--out with .html): per scene and role, the engine as its package
// ships it and its defaults with lengths from R against its tuned settings and ssaolab's most
// accurate shipped preset within the tuned engine's time - RMSE and AO time, the tuned ones as a
// ratio to the shipped - and, for each scene's first held-out view, the AO and signed error
// thumbnails of each beside the reference. One self-contained
// file (PNG as data: URIs); every name escaped for HTML (output/escape.h).
#pragma once
#include "metrics/evaluate.h"
#include "reference/reference_ao.h"

#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

namespace ssao {

struct PageEntry {
    std::string label; // "defaults", "tuned", or the preset's name
    double rmse = 0, ms = 0;
    std::shared_ptr<const Evaluation> eval; // the shown view's AO (thumbnails); may be empty
};

struct PageRow {
    std::string scene, role; // "train", "held-out views", "held-out scene"
    int views = 0;
    PageEntry defaults, tuned, shipped; // defaults: with lengths from R
    bool hasSsaolab = false;
    PageEntry ssaolab;            // the shown view only (the preset chosen there)
    std::string shownView;        // its viewpoint ("" = no thumbnails for this row)
    const ReferenceImage* ref = nullptr;
};

struct EnginePage {
    std::string title, package, version, size;
    std::string metric;           // what the RMSE is of (the reference's definition, R, rays)
    nlohmann::json facts;         // bench_run.h runFacts, with the browser's renderer
    std::vector<std::vector<std::string>> settings; // name, shipped value, make-peers value, tuned value, role, unit
    double heldBefore = 0, heldAfter = 0, timeRatio = 0; // against the better baseline; time: x the shipped
    std::string baseline; // which baseline heldBefore is ("as shipped", "with lengths from R")
    std::string radius;   // one line: R per scene, its source and its unit
    double seconds = 0;
    std::vector<PageRow> rows;
};

std::string engineTunePageHtml(const EnginePage& page);

} // namespace ssao
