#!/usr/bin/env python3
"""Every web engine tuned on every scene (`make engines`, .ci/engines.sh): per engine and scene, one
`ssaolab tune --engine` run at the view's radius, then one page - as shipped / lengths from R / tuned
on the held-out views, the screen-space oracle on the same views (what no screen-space AO can
remove), the tuned AO time against the shipped, and how long the tune took.

The view's radius: R = 5 % of the scene's diagonal unless `ssaolab render` at the scene's own camera
says that reaches past 60 % of what the view spans (metrics/radius_check.h); then the radius render
offers for the view (5 % of its extent), as a user following the warning would set it.

Usage: engines_table.py --ssaolab BIN --work DIR --page OUT.md [--size WxH] [--engines a,b]
                        SCENE.gltf ...   (the close-up city is added: tools/city_gltf.py)"""
import argparse
import json
import math
import os
import platform
import subprocess
import sys
import time

from markdown_cell import cell

TARGET_RMSE, TARGET_TIME = 0.7, 1.1


def run(args, what):
    """Runs a program (never through a shell); returns (exit code, the last line of its stderr)."""
    p = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, errors="replace")
    if p.returncode != 0:
        err = [l for l in p.stderr.splitlines() if l.strip()]
        sys.stderr.write("%s: %s\n" % (what, err[-1] if err else "exit %d" % p.returncode))
        return p.returncode, err[-1] if err else "exit %d" % p.returncode
    return 0, ""


def view_radius(ssaolab, scene, size, work, reuse=False):
    """(--radius-scene, where it comes from, render's metrics) for the scene's own camera; reuse: the
    render an earlier run left in `work`, when there is one."""
    out = os.path.join(work, "render", os.path.splitext(os.path.basename(scene))[0])
    if not (reuse and os.path.isfile(os.path.join(out, "metrics.json"))):
        code, err = run([ssaolab, "render", "--scene", scene, "--size", size, "--out", out, "--quiet"], "render " + scene)
        if code:
            return None, err, None
    m = json.load(open(os.path.join(out, "metrics.json")))
    r = m["radius"]
    extent, suggested, diagonal = r.get("view_extent"), r.get("for_view"), r["scene_diagonal"]
    if extent and suggested and 0.05 * diagonal > 0.6 * extent:
        return suggested / diagonal, "the view's: 5 %% of its %.3g units" % extent, m
    return 0.05, "5 % of the diagonal", m


def tune(ssaolab, engine, scene, size, radius_scene, out, resume):
    os.makedirs(os.path.dirname(out), exist_ok=True)
    if resume and os.path.isfile(out):
        j = json.load(open(out))
        j["wall"] = j["tuning_seconds"]
        return j
    args = [ssaolab, "tune", "--engine", engine, "--scene", scene, "--size", size, "--radius-scene", "%.6g" % radius_scene,
            "--save-overfit", "--quiet", "--out", out]
    start = time.monotonic()
    code, err = run(args, "tune --engine %s on %s" % (engine, scene))
    wall = time.monotonic() - start
    if code:
        return {"error": err, "wall": wall}
    j = json.load(open(out))
    j["wall"] = wall
    return j


def not_run(engines, scenes, rows):
    """The engine-scene pairs a stopped run left out, in one line ("" when none)."""
    done = {(r.split(" | ")[0][2:], r.split(" | ")[1]) for r in rows}
    missing = ["%s on %s" % (e, s) for s in scenes for e in engines if (cell(e), cell(s)) not in done]
    return "Not run: %s." % ", ".join(missing) if missing else ""


def fmt(x, f="%.4f"):
    return "–" if x is None or (isinstance(x, float) and not math.isfinite(x)) else f % x


def row(engine, scene, radius_text, j):
    if "error" in j:
        return "| %s | %s | %s | failed: %s | | | | | | | |" % (cell(engine), cell(scene), cell(radius_text), cell(j["error"]))
    s = j["scores"]
    h = s["held_out"]
    better = min(h["shipped"], h["defaults"])
    ratio = h["tuned"] / better if better else None
    refused = " (refused: the guard)" if s.get("overfit") else ""
    t, noise = s.get("time_ratio"), s.get("time_noise") or 0.0
    within = t is not None and abs(math.log(t)) <= max(noise, 0.02)
    time_text = "–" if t is None else ("%.2fx (within +-%.0f %%)" % (t, 100 * max(noise, 0.02)) if within else "%.2fx" % t)
    short = s.get("short_timings") or []
    if short and t is not None:  # a job whose frames hit the harness's cap: timed on fewer frames
        time_text += " (%d job(s) timed on fewer frames: %s)" % (len(short), cell("; ".join(short)))
    r_time = s["defaults"]["ao_ms"] / s["shipped"]["ao_ms"] if s["shipped"]["ao_ms"] and s["defaults"]["ao_ms"] else None
    met = ratio is not None and ratio <= TARGET_RMSE and (t is None or t <= TARGET_TIME or within)
    oracle = h.get("screen_oracle")
    floor = oracle / better if oracle is not None and better else None
    return "| %s | %s | %s | %s | %s | %s | %s | %s (%s) | %s | %s | %.0f | %s |" % (
        cell(engine), cell(scene), cell(radius_text), fmt(h["shipped"]), fmt(h["defaults"]), fmt(h["tuned"]),
        fmt(ratio, "%.3fx") + refused, fmt(oracle), fmt(floor, "%.2fx"), time_text, fmt(r_time, "%.2fx"), j["tuning_seconds"],
        "yes" if met else "no")


def machine(ssaolab, metrics):
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), platform.machine())
    p = subprocess.run(["/usr/bin/chromium", "--version"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    git = subprocess.run(["git", "rev-parse", "--short", "HEAD"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    return "%s, %d hardware threads; ssaolab on %s; %s; git %s" % (
        cpu, os.cpu_count() or 0, (metrics or {}).get("gl_renderer", "?"), p.stdout.strip() or "chromium ?", git.stdout.strip() or "?")


def page(rows, size, facts, engines, scenes):
    out = ["# Web engines: as shipped, lengths from R, tuned", "",
           "Machine: %s. %s, `ssaolab tune --engine` defaults (8 viewpoints a scene about its own camera: even ones "
           "fitted, odd ones held out; 256 reference rays). Generated by `make engines`." % (cell(facts), size), "",
           "How to read it: each row is one engine tuned on one scene. *as shipped* is the package's defaults verbatim, "
           "*lengths from R* its defaults with every length the harness derives from R, *tuned* what `tune --engine` "
           "saved; all three are geometry RMSE against the ray-traced reference on the held-out views only. *x better* "
           "is tuned over the better of the two baselines (the target is %.1fx or less; *refused* where the fit raised "
           "the held-out error, which `tune` does not save without `--save-overfit`); *screen oracle* is the error a "
           "perfect estimator still has on the same views, seeing only what one G-buffer holds - where it is close to "
           "the baseline, no screen-space setting of any engine can reach the target, and its ratio says how close one "
           "could get. *time* is the tuned AO time over the shipped one, measured in the same run (within the timing's "
           "own spread when it says so; the target is %.1fx or less), each the mean over the views, so one view whose "
           "frame takes a minute weighs as it would in a user's frame budget; a job whose frames reached the harness's "
           "cap was timed on fewer frames, and the cell names it; *R time* the same for lengths from R. *R* is the "
           "radius the row ran at and where it came from." % (TARGET_RMSE, TARGET_TIME), "",
           "| engine | scene | R | as shipped | lengths from R | tuned | x better | screen oracle (x better) | time | R time "
           "| tune s | target |",
           "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    out += rows
    met = sum(r.endswith("| yes |") for r in rows)
    ran = lambda k: len({r.split(" | ")[k] for r in rows})
    out += ["", "%d of %d engine-scene pairs reach the target (%d engine(s), %d scene(s))." % (met, len(rows), ran(0), ran(1))]
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ssaolab", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--page", required=True)
    ap.add_argument("--size", default="320x180")
    ap.add_argument("--engines", default="")
    ap.add_argument("--resume", action="store_true", help="keep the tunes already in --work")
    ap.add_argument("--page-only", action="store_true", help="no tune: the page from what --work holds")
    ap.add_argument("scenes", nargs="*")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    city = os.path.join(a.work, "city", "city.gltf")
    os.makedirs(os.path.dirname(city), exist_ok=True)
    if not (a.page_only and os.path.isfile(city)):
        subprocess.run([sys.executable, os.path.join(os.path.dirname(__file__), "city_gltf.py"), city], check=True)
    tables = os.path.join(os.path.dirname(os.path.abspath(__file__)), "peers", "engines")
    engines = [e for e in a.engines.split(",") if e] or sorted(f[:-5] for f in os.listdir(tables) if f.endswith(".json"))
    scenes = [city] + a.scenes
    rows, metrics = [], None
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        radius_scene, source, m = view_radius(a.ssaolab, scene, a.size, a.work, a.page_only)
        metrics = metrics or m
        if radius_scene is None:
            rows += ["| %s | %s | failed: %s | | | | | | | | | |" % (cell(e), cell(name), cell(source)) for e in engines]
            continue
        radius_text = "%.4g (%s)" % (radius_scene * m["radius"]["scene_diagonal"], source)
        for e in engines:
            out = os.path.join(a.work, "tune", e, name + ".json")
            if a.page_only and not os.path.isfile(out):
                continue
            j = tune(a.ssaolab, e, scene, a.size, radius_scene, out, a.resume or a.page_only)
            rows.append(row(e, name, radius_text, j))
            sys.stdout.write(rows[-1] + "\n")
            sys.stdout.flush()
    names = [os.path.splitext(os.path.basename(s))[0] for s in scenes]
    text = page(rows, a.size, machine(a.ssaolab, metrics), engines, scenes)
    if not_run(engines, names, rows):
        text += "\n" + not_run(engines, names, rows) + "\n"
    open(a.page, "w").write(text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
