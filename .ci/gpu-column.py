#!/usr/bin/env python3
"""The GPU column of docs/benchmarks.md from a `.ci/gpu-run.sh` run (merged bench shards and the
scaling renders), set beside this page's llvmpipe run (docs/bench/summary.csv, scaling.json).
Usage: gpu-column.py MERGED_BENCH_DIR SCALING_RUN_DIR CHECK_JSON GPU_NOTE DOCS_BENCH_DIR [SKIPS_DIR]
Writes DOCS_BENCH_DIR/{gpu.md, gpu_summary.csv, gpu_pareto.png, scaling_gpu.json}."""
import csv
import glob
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scaling  # noqa: E402  (the llvmpipe page's curves and least-squares exponent)


def rows(path):
    return {r["label"]: r for r in csv.DictReader(open(path))}


def scaling_curves(run):
    out = []
    for panel, label, x, xs, ms in scaling.curves(run):
        k, miss = scaling.slope(xs, ms)
        out.append({"panel": panel, "label": label, "x": x, "xs": xs, "ms": ms, "exponent": k, "fit_miss": miss})
    return out


def skips_table(skips_dir, cpu_json):
    """The skips a GPU may answer differently, beside the llvmpipe run's ratio for the same row."""
    kinds = ("deinterleave", "fused", "occluded", "faces", "sky")
    key = lambda r: (os.path.basename(r["scene"]).rsplit(".", 1)[0].lower(), r["skip"], r["variant"], r["view"])
    cpu = {key(r): r for r in json.load(open(cpu_json))["rows"]} if os.path.exists(cpu_json) else {}
    md = ["", "#### Skipped work on the GPU (`ssaolab skips`, 1280x720, 7 frames)", "",
          "Time with the skip (or the option) over time without it: below 1 pays.", "",
          "| scene | skip | variant | view | GPU ms with / without | ratio GPU | ratio llvmpipe | RMSE change |",
          "|---|---|---|---|---:|---:|---:|---:|"]
    for f in sorted(glob.glob(os.path.join(skips_dir, "skips_*.json"))):
        for r in json.load(open(f))["rows"]:
            if r["skip"] not in kinds:
                continue
            c = cpu.get(key(r))
            md.append(f"| {os.path.basename(r['scene']).rsplit('.', 1)[0]} | {r['skip']} | {r['variant']} | {r['view']} | "
                      f"{r['with_ms']:.3f} / {r['without_ms']:.3f} | {r['ratio']:.2f} | "
                      + (f"{c['ratio']:.2f}" if c else "-") + f" | {r.get('error_change', 0.0):+.4f} |")
    return md


def main(merged, scal_run, check, note, docs, skips=None):
    chk = json.load(open(check))
    gpu, cpu = rows(os.path.join(merged, "summary.csv")), rows(os.path.join(docs, "summary.csv"))
    base = next(r for r in gpu.values() if r["baseline"] == "1")
    head = open(os.path.join(merged, "report.md")).readline().strip()
    md = ["### The GPU column", "",
          f"GL renderer **{chk['gl_renderer']}** ({chk['gl_platform']}); {note}", "",
          "Measured with `.ci/gpu-run.sh` (the sweep, scenes, views, size and frames of `make bench`, in three "
          "shards merged by `ssaolab bench merge`; the renders of `make scaling`) and written here by "
          "`.ci/gpu-column.py`. The bench run's own line: " + head.replace("**", ""), "",
          "#### Time against error on the GPU", "",
          f"Baseline learnopengl: {float(base['gpu_ms']):.3f} ms AO + denoise, geometry RMSE "
          f"{float(base['rmse']):.4f}. Ratios are to the baseline measured in the same run (GPU, or llvmpipe "
          "in the run above); the errors of the two runs agree to the reference's noise.", "",
          "![GPU front](gpu_pareto.png)", "",
          "| configuration | GPU ms | x baseline | GPU front | llvmpipe ms | x baseline | llvmpipe front | RMSE GPU | RMSE llvmpipe | x baseline |",
          "|---|---:|---:|:-:|---:|---:|:-:|---:|---:|---:|"]
    shown = [r for r in gpu.values() if r["pareto"] == "1" or r["baseline"] == "1" or
             (r["label"] in cpu and cpu[r["label"]]["pareto"] == "1")]
    shown.sort(key=lambda r: float(r["time_ratio"]))
    for r in shown:
        c = cpu.get(r["label"])
        md.append("| {} | {:.3f} | {:.3f} | {} | {} | {} | {} | {:.4f} | {} | {:.3f} |".format(
            r["label"], float(r["gpu_ms"]), float(r["time_ratio"]), "yes" if r["pareto"] == "1" else "",
            f"{float(c['gpu_ms']):.2f}" if c else "-", f"{float(c['time_ratio']):.3f}" if c else "-",
            "yes" if c and c["pareto"] == "1" else "", float(r["rmse"]),
            f"{float(c['rmse']):.4f}" if c else "-", float(r["rmse_ratio"])))
    curves = scaling_curves(scal_run)
    cpu_k = {(c["panel"], c["label"]): c["exponent"]
             for c in json.load(open(os.path.join(docs, "scaling.json")))["curves"]}
    md += ["", "#### Scaling on the GPU", "",
           "| curve | x | GPU points (x: ms) | exponent k, GPU | fit miss | exponent k, llvmpipe |",
           "|---|---|---|---:|---:|---:|"]
    for c in curves:
        pts = ", ".join(f"{x:.4g}: {y:.3g}" for x, y in zip(c["xs"], c["ms"]))
        k0 = cpu_k.get((c["panel"], c["label"]))
        md.append(f"| {c['panel']}: {c['label']} | {c['x']} | {pts} | {c['exponent']:.2f} | {c['fit_miss']:.0%} | "
                  + (f"{k0:.2f}" if k0 is not None else "-") + " |")
    md += skips_table(skips, os.path.join(docs, "skips.json")) if skips else []
    open(os.path.join(docs, "gpu.md"), "w").write("\n".join(md) + "\n")
    json.dump({"gl_renderer": chk["gl_renderer"], "note": note, "curves": curves},
              open(os.path.join(docs, "scaling_gpu.json"), "w"), indent=1)
    shutil.copy(os.path.join(merged, "summary.csv"), os.path.join(docs, "gpu_summary.csv"))
    shutil.copy(os.path.join(merged, "pareto.png"), os.path.join(docs, "gpu_pareto.png"))
    print(f"wrote {docs}/gpu.md, gpu_summary.csv, gpu_pareto.png, scaling_gpu.json")


if __name__ == "__main__":
    if len(sys.argv) not in (6, 7):
        sys.exit(__doc__)
    main(*sys.argv[1:])
