#!/usr/bin/env python3
"""`make scaling` helper (.ci/scaling.sh).

  scaling.py grid N OUT.gltf   writes a height field of about N triangles (a gently waved grid,
                               one mesh, float positions and normals, 32-bit indices)
  scaling.py report RUN DOCS   fits each curve's exponent (least squares on log time against log
                               size) and writes DOCS/scaling.{md,json,png,svg}
"""
import glob
import json
import math
import os
import sys


def grid(n, out):
    import numpy as np
    q = max(2, int(math.sqrt(n / 2.0)))  # q x q quads, 2 triangles each
    xs = np.linspace(-1.0, 1.0, q + 1, dtype=np.float32)
    x, z = np.meshgrid(xs, xs)
    y = 0.05 * np.sin(6.0 * x) * np.cos(5.0 * z)
    pos = np.stack([x, y, z], -1).reshape(-1, 3).astype(np.float32)
    dydx = 0.3 * np.cos(6.0 * x) * np.cos(5.0 * z)
    dydz = -0.25 * np.sin(6.0 * x) * np.sin(5.0 * z)
    nrm = np.stack([-dydx, np.ones_like(x), -dydz], -1).reshape(-1, 3)
    nrm = (nrm / np.linalg.norm(nrm, axis=1, keepdims=True)).astype(np.float32)
    i = np.arange(q)
    a = (i[:, None] * (q + 1) + i[None, :]).reshape(-1)
    b, c, d = a + 1, a + q + 1, a + q + 2
    idx = np.stack([a, c, b, b, c, d], -1).reshape(-1).astype(np.uint32)
    base = os.path.splitext(out)[0]
    binname = os.path.basename(base) + ".bin"
    with open(base + ".bin", "wb") as f:
        f.write(pos.tobytes()); f.write(nrm.tobytes()); f.write(idx.tobytes())
    pb, nb, ib = pos.nbytes, nrm.nbytes, idx.nbytes
    j = {"asset": {"version": "2.0"},
         "buffers": [{"byteLength": pb + nb + ib, "uri": binname}],
         "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": pb},
                         {"buffer": 0, "byteOffset": pb, "byteLength": nb},
                         {"buffer": 0, "byteOffset": pb + nb, "byteLength": ib}],
         "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(pos), "type": "VEC3",
                        "min": pos.min(0).tolist(), "max": pos.max(0).tolist()},
                       {"bufferView": 1, "componentType": 5126, "count": len(nrm), "type": "VEC3"},
                       {"bufferView": 2, "componentType": 5125, "count": len(idx), "type": "SCALAR"}],
         "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
         "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0,
         "cameras": [{"type": "perspective", "perspective": {"yfov": 0.9, "znear": 0.05, "zfar": 20}}]}
    j["nodes"].append({"camera": 0, "translation": [0, 1.6, 1.6], "rotation": [-0.3826834, 0, 0, 0.9238795]})
    j["scenes"][0]["nodes"].append(1)
    json.dump(j, open(out, "w"))


def slope(xs, ys):
    """Least-squares exponent k of y = c x^k, and the fit's largest relative miss."""
    lx = [math.log(v) for v in xs]
    ly = [math.log(v) for v in ys]
    n = len(lx)
    mx, my = sum(lx) / n, sum(ly) / n
    k = sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)
    c = my - k * mx
    miss = max(abs(math.exp(c + k * a) / math.exp(b) - 1) for a, b in zip(lx, ly))
    return k, miss


def load(run, pattern):
    return {os.path.basename(p)[:-5]: json.load(open(p)) for p in glob.glob(os.path.join(run, pattern))}


def curves(run):
    """(panel, label, x name, xs, ms) of every curve whose renders the run holds (a GPU run has no
    reference curves: .ci/gpu-column.py reads its curves through this too)."""
    out = []
    pixels, radius = load(run, "pixels/*.json"), load(run, "radius/*.json")
    for p in sorted({k.rsplit("_", 1)[0] for k in pixels}):
        pts = sorted((m["size"][0] * m["size"][1], m["gpu_ms"]["ao"] + m["gpu_ms"]["denoise"])
                     for k, m in pixels.items() if k.rsplit("_", 1)[0] == p)
        out.append(("pixels", p, "pixels", [a for a, _ in pts], [b for _, b in pts]))
        pts = sorted((m["radius"]["pixels_at_centre"], m["gpu_ms"]["ao"] + m["gpu_ms"]["denoise"])
                     for k, m in radius.items() if k.rsplit("_", 1)[0] == p)
        out.append(("radius", p, "radius px", [a for a, _ in pts], [b for _, b in pts]))
    tri = load(run, "triangles/*.json")
    pts = sorted((m["scene"]["triangles"], m["gpu_ms"]["gbuffer"]) for m in tri.values())
    out.append(("triangles", "G-buffer", "triangles", [a for a, _ in pts], [b for _, b in pts]))
    ref = load(run, "reference/*.json")
    pts = sorted((m["error"]["reference"]["rays_per_pixel"], 1000 * m["error"]["reference"]["trace_seconds"])
                 for k, m in ref.items() if k.startswith("rays_"))
    out.append(("reference", "reference vs rays (320x180)", "rays per pixel", [a for a, _ in pts], [b for _, b in pts]))
    pts = sorted((m["size"][0] * m["size"][1], 1000 * m["error"]["reference"]["trace_seconds"])
                 for k, m in ref.items() if k.startswith("pixels_"))
    out.append(("reference", "reference vs pixels (32 rays)", "pixels", [a for a, _ in pts], [b for _, b in pts]))
    return [c for c in out if len(c[3]) >= 2]


def report(run, docs):
    pixels = load(run, "pixels/*.json")
    renderer = next(iter(pixels.values()))["gl_renderer"] if pixels else "?"
    out = {"gl_renderer": renderer, "curves": []}
    md = ["### Scaling", "",
          f"GL: {renderer}: on llvmpipe every time is CPU rasterisation, and the reference's Embree runs on "
          "the same CPU. The same curves on a GPU, where one was measured: \"The GPU column\" below.", "",
          "Exponent k of time = c x size^k, least squares on log-log points; 'fit miss' is the largest "
          "relative distance of a point from the fitted line.", "",
          "| curve | x | points (x: ms) | exponent k | fit miss |", "|---|---|---|---:|---:|"]
    for panel, label, xname, xs, ys in curves(run):
        k, miss = slope(xs, ys)
        out["curves"].append({"panel": panel, "label": label, "x": xname, "xs": xs, "ms": ys, "exponent": k, "fit_miss": miss})
        pts = ", ".join(f"{x:.4g}: {y:.3g}" for x, y in zip(xs, ys))
        md.append(f"| {panel}: {label} | {xname} | {pts} | {k:.2f} | {miss:.0%} |")
    md += ["", "![scaling](scaling.png)", ""]
    os.makedirs(docs, exist_ok=True)
    json.dump(out, open(os.path.join(docs, "scaling.json"), "w"), indent=1)
    open(os.path.join(docs, "scaling.md"), "w").write("\n".join(md) + "\n")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = ["pixels", "radius", "triangles", "reference"]
    titles = {"pixels": "AO + denoise vs pixels (CornellBox)", "radius": "AO + denoise vs radius (1280x720)",
              "triangles": "G-buffer vs triangles (1280x720)", "reference": "reference trace vs rays and pixels"}
    fig, axes = plt.subplots(1, 4, figsize=(20, 4.6))
    for ax, panel in zip(axes, panels):
        for c in out["curves"]:
            if c["panel"] != panel:
                continue
            ax.loglog(c["xs"], c["ms"], "o-", label=f"{c['label']} (k = {c['exponent']:.2f})")
        ax.set_title(titles[panel]); ax.set_ylabel("ms"); ax.grid(True, which="both", alpha=0.3)
        ax.set_xlabel({"pixels": "pixels", "radius": "radius at the centre, px", "triangles": "triangles",
                       "reference": "rays per pixel / pixels"}[panel])
        ax.legend(fontsize=7)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(docs, "scaling." + ext), dpi=80)


if __name__ == "__main__":
    if sys.argv[1] == "grid":
        grid(int(sys.argv[2]), sys.argv[3])
    elif sys.argv[1] == "report":
        report(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
