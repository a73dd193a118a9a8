#!/usr/bin/env python3
"""The benchmark's headline per scene (.ci/bench.sh prints it into the benchmark page, from a bench
run's results.csv): every shipped preset the sweep holds, its AO + denoise time and geometry RMSE as
ratios to the learnopengl baseline on the same views of the same run, each scene marked as one the
presets were tuned on (training) or held out from their tuning (assets/presets/*.json
scores.training_scenes).

Usage: heldout.py RESULTS_CSV PRESETS_DIR OUT_MD (- for standard output)
"""
import csv
import glob
import json
import math
import os
import sys


def main(results, presets_dir, out):
    training = set()
    for f in glob.glob(os.path.join(presets_dir, "*.json")):
        training.update(s.lower() for s in json.load(open(f)).get("scores", {}).get("training_scenes", []))
    rows = list(csv.DictReader(open(results)))
    scenes = []
    for r in rows:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    base = {}
    cells = {}  # (label, scene) -> [sum time ratio, sum rmse^2, sum base rmse^2, n]
    for r in rows:
        if r["baseline"] == "1":
            base[(r["scene"], r["viewpoint"])] = (float(r["gpu_ms"]), float(r["rmse"]))
    for r in rows:
        label = r["label"]
        if not (label.startswith("preset=") or r["baseline"] == "1"):
            continue
        b = base.get((r["scene"], r["viewpoint"]))
        if not b:
            continue
        c = cells.setdefault((label, r["scene"]), [0.0, 0.0, 0.0, 0])
        c[0] += float(r["gpu_ms"]) / b[0]
        c[1] += float(r["rmse"]) ** 2
        c[2] += b[1] ** 2
        c[3] += 1
    labels = sorted({k[0] for k in cells}, key=lambda l: (l != "learnopengl (baseline)", l))
    L = ["Per scene (RMS over its views), each shipped preset in the sweep: AO + denoise time / RMSE as ratios to "
         "the baseline on the same views. *held out*: a scene no preset was tuned on (`make presets` fits on "
         + ", ".join(sorted(training)) + ").", ""]
    L.append("| preset | " + " | ".join(f"{s} ({'training' if s.lower() in training else 'held out'})" for s in scenes) + " |")
    L.append("|---|" + "---:|" * len(scenes))
    for label in labels:
        cols = []
        for s in scenes:
            c = cells.get((label, s))
            if not c:
                cols.append("")
                continue
            rmse, brmse = math.sqrt(c[1] / c[3]), math.sqrt(c[2] / c[3])
            cols.append(f"{c[0] / c[3]:.2f}x / {rmse / brmse:.2f}x ({rmse:.3f})")
        L.append(f"| {label} | " + " | ".join(cols) + " |")
    text = "\n".join(L) + "\n"
    if out == "-":  # into the page being assembled (.ci/bench.sh)
        sys.stdout.write(text)
        return
    with open(out, "w") as fh:
        fh.write(text)
    print("wrote", out, file=sys.stderr)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3])
