#!/usr/bin/env python3
"""Temporal accumulation in motion, from two `ssaolab bench --motion` runs of
assets/bench/sweep_temporal.json (.ci/temporal.sh): an orbit and a dolly. Per shared scene and
path, GTAO high and the bitmask (vbao-high) without accumulation and with it at each memory in
motion (temporal.moving_frames), as the motion score (sqrt of the mean per-frame RMSE^2 +
instability^2) and its ratio to the same preset without accumulation; then, with the noise off,
each path's per-frame RMSE with accumulation against without (it must repeat the frame). Writes
the page given and prints it."""
import json
import math
import sys

from markdown_cell import cell

PRESETS = ["gtao-high", "vbao-high"]
MEMORIES = [1, 2, 4]


def score(v):
    i = v.get("motion_instability")
    r = v.get("motion_rmse_mean")
    if r is None:
        return float("nan")
    return math.sqrt(r * r + (i * i if i is not None and math.isfinite(i) else 0.0))


def index(run):
    """(scene, preset, temporal, memory, noise off) -> the result row (one view a scene)."""
    cfgs = run["configurations"]
    out = {}
    for v in run["results"]:
        keys = cfgs[v["config"]]["keys"]
        preset = keys.get("preset")
        if preset not in PRESETS:
            continue
        noise_off = any(k.endswith(".noise") and val == "none" for k, val in keys.items())
        temporal = bool(keys.get("temporal.enabled", False))
        memory = keys.get("temporal.moving_frames") if temporal and not noise_off else None
        out[(v["scene"], preset, temporal, memory, noise_off)] = v
    return out


def ratio(a, b):
    return "–" if not (math.isfinite(a) and math.isfinite(b) and b > 0) else "%.2fx" % (a / b)


def usual_noise(runs, scenes):
    lines = ["## With the usual noise", "",
             "| scene | path | preset | score, none | moving_frames 1 | 2 | 4 | noise off |",
             "|---|---|---|---:|---:|---:|---:|---:|"]
    better = {(p, m): 0 for p in PRESETS for m in MEMORIES}
    cases = 0
    for scene in scenes:
        for path, rows in runs:
            for p in PRESETS:
                off = rows.get((scene, p, False, None, False))
                if off is None:
                    continue
                cases += 1 if p == PRESETS[0] else 0
                cells = []
                for m in MEMORIES:
                    on = rows.get((scene, p, True, m, False))
                    s = score(on) if on else float("nan")
                    better[(p, m)] += 1 if s < score(off) else 0
                    cells.append(ratio(s, score(off)))
                quiet = rows.get((scene, p, False, None, True))  # the same preset without noise, no accumulation
                cells.append(ratio(score(quiet), score(off)) if quiet else "–")
                lines.append("| %s | %s | %s | %.4f | %s |" % (cell(scene), path, p, score(off), " | ".join(cells)))
    lines += ["", "Paths on which accumulation lowers the motion score, of %d:" % cases, ""]
    for p in PRESETS:
        lines.append("- %s: %s" % (p, ", ".join("moving_frames %d on %d" % (m, better[(p, m)]) for m in MEMORIES)))
    lines += ["", "*noise off*: the same preset with its noise off, without accumulation, against it with its noise: "
              "roughly what a perfect average of the noise would reach. Where it is near or above 1x, the error in "
              "motion is the technique's view-dependent bias, not noise: accumulation has little to average and adds "
              "what resampling the history costs on pixel-sized detail (an object small on screen), so it cannot "
              "lower the score there."]
    return lines


def noise_off(runs, scenes):
    lines = ["## With the noise off", "",
             "Every frame's AO is the same: accumulation can only repeat it. *mean* and *max* are the path's "
             "per-frame RMSE without accumulation; the ratios are with it against without.", "",
             "| scene | path | preset | mean | max | mean x | max x |", "|---|---|---|---:|---:|---:|---:|"]
    worst = 0.0
    for scene in scenes:
        for path, rows in runs:
            for p in PRESETS:
                off, on = rows.get((scene, p, False, None, True)), rows.get((scene, p, True, None, True))
                if off is None or on is None:
                    continue
                rm = on["motion_rmse_max"] / off["motion_rmse_max"]
                worst = max(worst, rm, on["motion_rmse_mean"] / off["motion_rmse_mean"])
                lines.append("| %s | %s | %s | %.4f | %.4f | %s | %.2fx |" % (
                    cell(scene), path, p, off["motion_rmse_mean"], off["motion_rmse_max"],
                    ratio(on["motion_rmse_mean"], off["motion_rmse_mean"]), rm))
    lines += ["", "The largest ratio: %.4fx." % worst]
    return lines


def main(orbit_json, dolly_json, page):
    orbit, dolly = json.load(open(orbit_json)), json.load(open(dolly_json))
    runs = [("orbit %g deg" % orbit["motion"]["orbit_deg"], index(orbit)),
            ("dolly %g" % dolly["motion"]["dolly"], index(dolly))]
    scenes = []
    for v in orbit["results"]:
        if v["scene"] not in scenes:
            scenes.append(v["scene"])
    out = ["# Temporal accumulation in motion", "",
           "Machine: %s, %s, %s hardware threads; %s, %d view a scene, %d frames along each path, R = %.0f %% of "
           "the diagonal, %s reference rays; %s build, git %s." % (
               cell(orbit["cpu"]), cell(orbit["gl_renderer"]), orbit["hardware_threads"], orbit["size"],
               orbit["views_per_scene"], orbit["motion"]["frames"], 100 * orbit["reference"]["radius_scene"],
               orbit["reference"]["rays"], orbit["build_type"], orbit["git_revision"]), "",
           "How to read it: each path starts at the scene's camera (accumulated to its end, as a still frame is) and "
           "moves on every frame after. The *score* is the motion score, sqrt(mean per-frame RMSE^2 + instability^2); "
           "lower is better. The ratios are each setting of `temporal.moving_frames` (how many frames the history "
           "counts as at most while the camera moves) against the same preset without accumulation on the same "
           "path: below 1x accumulation helps in motion. Generated by `make temporal`.", ""]
    out += usual_noise(runs, scenes) + [""] + noise_off(runs, scenes)
    text = "\n".join(out) + "\n"
    open(page, "w").write(text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main(*sys.argv[1:4])
