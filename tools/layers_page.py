#!/usr/bin/env python3
"""One depth layer against two, from one `ssaolab bench` run of assets/bench/sweep_layers.json
(.ci/layers.sh): per scene, each configuration's RMSE and AO + denoise time (the layer's own passes
counted) as ratios to the baseline on the same views, the layer's time, and the error split against
the screen-space oracle of its own depth (one layer, or two for the two-layer rows); then per scene
the best candidates and whether any two-layer row is worse than its one-layer twin. Writes the page
given and prints it."""
import json
import math
import os
import sys

from markdown_cell import cell

FAMILIES = ["vbao-high", "vbao-ultra", "vbao-half-ultra", "gtao-high"]


def rms(xs):
    xs = [x for x in xs if x is not None]
    return math.sqrt(sum(x * x for x in xs) / len(xs)) if xs else float("nan")


def mean(xs):
    xs = [x for x in xs if x is not None]
    return sum(xs) / len(xs) if xs else float("nan")


def name(cfg):
    """The row's name: its group, with the build of a two-layer row, or what the study changed."""
    keys, group = cfg["keys"], cfg["group"]
    if cfg.get("baseline"):
        return "learnopengl (baseline)"
    if group.startswith("nested"):
        extra = ", ".join("%s=%s" % (k, json.dumps(v)) for k, v in sorted(keys.items())
                          if k not in ("preset", "gbuffer.second_layer"))
        return "%s, %s layer%s, %s" % (keys.get("preset", "?"), "2" if keys.get("gbuffer.second_layer") else "1",
                                      "s" if keys.get("gbuffer.second_layer") else "", extra)
    if keys.get("gbuffer.second_layer"):
        build = keys.get("gbuffer.second_layer_build", "peel")
        return "%s, 2 layers (%s)" % (group.replace(" 2L", ""), "one pass" if build == "previous" else "peel")
    return group if group in FAMILIES else cfg["label"]


def summarise(run):
    """(scene, row name) -> the row's numbers over the scene's views."""
    cfgs = run["configurations"]
    rows = {}
    for v in run["results"]:
        cfg = cfgs[v["config"]]
        if cfg["group"] == "technique defaults" and not cfg.get("baseline"):
            continue
        r = rows.setdefault((v["scene"], name(cfg)), {"views": [], "two": bool(cfg["keys"].get("gbuffer.second_layer"))})
        r["views"].append(v)
    out = {}
    for key, r in rows.items():
        vs = r["views"]
        out[key] = {"two": r["two"], "rmse": rms([v["rmse"] for v in vs]),
                    "time": mean([v["time_ratio"] for v in vs]), "layer": mean([v["pass_ms"]["layers"] for v in vs]),
                    "screen": rms([v["rmse_screen"] for v in vs]), "technique": rms([v["rmse_vs_oracle"] for v in vs])}
    return out


def fmt(x, spec):
    return "–" if x is None or (isinstance(x, float) and math.isnan(x)) else spec % x


def places_section(results_json):
    """The run's report.md section "Where the error lives" (the error by place), or ""."""
    report = os.path.join(os.path.dirname(results_json), "report.md")
    if not os.path.isfile(report):
        return ""
    md = open(report).read()
    at = md.find("### Where the error lives")
    if at < 0:
        return ""
    end = md.find("\n### ", at + 10)
    return "\n" + md[at:end if end > 0 else len(md)].strip() + "\n"


def main(results_json, page):
    run = json.load(open(results_json))
    rows = summarise(run)
    scenes = []
    for v in run["results"]:
        if v["scene"] not in scenes:
            scenes.append(v["scene"])
    out = ["# One depth layer against two", "",
           "Machine: %s, %s, %s hardware threads; %s, %s views a scene, %s timed frames each (median), R = %.0f %% of "
           "the diagonal, %s reference rays; %s build, git %s." % (
               cell(run["cpu"]), cell(run["gl_renderer"]), run["hardware_threads"], run["size"], run["views_per_scene"],
               run["frames"], 100 * run["reference"]["radius_scene"], run["reference"]["rays"], run["build_type"],
               run["git_revision"]), "",
           "How to read it: *RMSE x* and *time x* are ratios to the baseline (learnopengl) on the same views; time is "
           "AO + denoise with the layer's own passes counted (for the one-pass build, its share of the G-buffer "
           "pass: that pass's time less the one-layer G-buffer's on the same view), the mean of the views' ratios. "
           "*layer ms* is that layer time. *screen* is the screen-space oracle against the truth - one layer's "
           "for one-layer rows, a two-layer G-buffer's for two-layer rows - and *technique* the AO against that "
           "oracle: what the technique's settings can still fix. *closed* is the part of the one-layer screen's "
           "squared error the two-layer oracle no longer has; negative where the two-layer oracle, whose second "
           "surface is also taken as 1 R thick, lets rays pass behind it that further hidden parts would stop "
           "(nested parts). The rows named *vbao-ultra, 1 layer / 2 layers, ...* are the study of what nested "
           "parts need: the back-face layer (a solid reaches at least to its far side), the true thickness "
           "(`vbao.true_thickness`: it may also end short of the assumed one) and a thin assumed thickness. "
           "Generated by `make layers`.", ""]
    summary = ["## Per scene", "",
               "| scene | best, one layer, time x <= 1 | best, two layers, time x <= 1 | best, two layers | "
               "worst two-layer row against its one-layer twin (RMSE) |", "|---|---|---|---|---|"]
    for sc in scenes:
        base = rows[(sc, "learnopengl (baseline)")]
        one_screen = base["screen"]
        out += ["## %s" % cell(sc), "", "| configuration | RMSE | RMSE x | time x | layer ms | screen | closed | technique |",
                "|---|---:|---:|---:|---:|---:|---:|---:|"]
        mine = sorted(((n, r) for (s, n), r in rows.items() if s == sc), key=lambda nr: nr[0])
        for n, r in mine:
            closed = 100.0 * (1.0 - r["screen"] ** 2 / one_screen ** 2) if r["two"] and one_screen > 0 else None
            out.append("| %s | %.4f | %.2f | %.2f | %s | %s | %s | %s |" % (
                cell(n), r["rmse"], r["rmse"] / base["rmse"], r["time"], fmt(r["layer"], "%.1f"), fmt(r["screen"], "%.4f"),
                fmt(closed, "%.0f %%"), fmt(r["technique"], "%.4f")))
        out.append("")

        def best(two, budget):
            sel = [(r["rmse"], n, r) for n, r in mine if n != "learnopengl (baseline)" and r["two"] == two
                   and (budget is None or r["time"] <= budget)]
            if not sel:
                return "–"
            e, n, r = min(sel)
            return "%s: %.2fx at %.2fx time" % (cell(n), e / base["rmse"], r["time"])
        worst, worst_name = -1.0, ""
        for fam in FAMILIES:
            one = rows.get((sc, fam))
            for build in ("peel", "one pass"):
                two = rows.get((sc, "%s, 2 layers (%s)" % (fam, build)))
                if one and two and two["rmse"] - one["rmse"] > worst:
                    worst, worst_name = two["rmse"] - one["rmse"], "%s, %s" % (fam, build)
        summary.append("| %s | %s | %s | %s | %+.4f (%s) |" % (cell(sc), best(False, 1.0), best(True, 1.0),
                                                             best(True, None), worst, cell(worst_name)))
    text = "\n".join(out[:6] + summary + [""] + out[6:]) + places_section(results_json)
    open(page, "w").write(text)
    print(text)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: layers_page.py RESULTS_JSON PAGE")
    main(*sys.argv[1:])
