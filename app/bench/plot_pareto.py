#!/usr/bin/env python3
"""Draw the run-time-against-error (Pareto) plot of an ssaolab benchmark run.

Called by the C++ benchmark command after it has written summary.csv (one row
per configuration) and results.csv (one row per scene, viewpoint and
configuration). x is the AO + denoise GPU time per frame (log axis), y the
geometry-pixel RMSE against the ray-traced reference. Every configuration is a
grey dot, the Pareto front (flagged by the C++ side, not recomputed here) is
highlighted and joined by a step line, the learnopengl baseline is a black star.

Writes OUT.png (dpi 150) and OUT.svg, and with --results also
OUT_by_scene.png/.svg with one panel per scene.

Usage: plot_pareto.py --summary DIR/summary.csv [--results DIR/results.csv]
                      --out DIR/pareto [--title TEXT]
Standard library and matplotlib only; bad input gives one line on stderr and
exit status 2, never a traceback.
"""
import argparse
import csv
import math
import os
import sys
from collections import OrderedDict

PROG = "plot_pareto"
FRONT_COLOUR = "#d62728"
DOT_COLOUR = "#9a9a9a"


def fail(msg):
    print(f"{PROG}: error: {msg}", file=sys.stderr)
    sys.exit(2)


def warn(msg):
    print(f"{PROG}: warning: {msg}", file=sys.stderr)


def number(text):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def flag(text):
    return (text or "").strip().lower() in ("1", "true", "yes")


def read_rows(path, extra=()):
    """Rows of a benchmark CSV as dicts with numeric fields parsed; bad rows skipped."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            raw = list(csv.DictReader(f))
            fields = raw and list(raw[0].keys())
    except OSError as e:
        fail(f"cannot read {path}: {e.strerror or e}")
    except (csv.Error, UnicodeDecodeError) as e:
        fail(f"malformed CSV {path}: {e}")
    if not raw:
        fail(f"no rows in {path}")
    missing = [c for c in ("label", "gpu_ms", "rmse") + tuple(extra) if c not in fields]
    if missing:
        fail(f"{path} lacks column(s) {', '.join(missing)}")
    rows = []
    for n, r in enumerate(raw, start=2):
        t, e = number(r.get("gpu_ms")), number(r.get("rmse"))
        if t is None or e is None or t <= 0:
            warn(f"{path}:{n}: skipping '{r.get('label')}': gpu_ms={r.get('gpu_ms')!r} "
                 f"rmse={r.get('rmse')!r} not a finite number (gpu_ms must be > 0)")
            continue
        rows.append({
            "label": (r.get("label") or "").strip() or f"row {n}",
            "scene": (r.get("scene") or "").strip(),
            "t": t, "e": e,
            "tmin": number(r.get("gpu_ms_min")), "tmax": number(r.get("gpu_ms_max")),
            "baseline": flag(r.get("baseline")), "pareto": flag(r.get("pareto")),
        })
    if not rows:
        fail(f"no plottable rows in {path}")
    return rows


def check_front(points, where):
    """Loose consistency check of the C++ Pareto flags; warns only."""
    base = [p for p in points if p["baseline"]]
    if len(base) != 1:
        warn(f"{where}: expected exactly one baseline row, found {len(base)}")
    tol = 1e-9
    for p in points:
        if not p["pareto"]:
            continue
        for q in points:
            if (q is not p and q["t"] < p["t"] * (1 - 1e-3) - tol
                    and q["e"] < p["e"] * (1 - 1e-3) - tol):
                warn(f"{where}: front point '{p['label']}' is dominated by '{q['label']}'")
                break


def place_labels(ax, points):
    """Annotate every point, trying a few offsets to avoid overlapping earlier labels.

    Front points and the baseline are placed first in a legible font; the others
    follow in a smaller, lighter font."""
    from matplotlib.transforms import Bbox
    fig = ax.figure
    renderer = fig.canvas.get_renderer()
    taken = [ax.get_legend().get_window_extent(renderer)] if ax.get_legend() else []
    # Marker footprints count as taken so labels do not sit on other points.
    for p in points:
        x, y = ax.transData.transform((p["t"], p["e"]))
        taken.append(Bbox([[x - 3, y - 3], [x + 3, y + 3]]))
    axbox = ax.get_window_extent(renderer)
    offsets = [(6, 4, "left", "bottom"), (6, -4, "left", "top"),
               (-6, 4, "right", "bottom"), (-6, -4, "right", "top"),
               (0, 9, "center", "bottom"), (0, -9, "center", "top"),
               (12, 12, "left", "bottom"), (-12, -12, "right", "top"),
               (12, -14, "left", "top"), (-12, 14, "right", "bottom")]
    order = sorted(points, key=lambda p: (not (p["baseline"] or p["pareto"]), p["t"]))
    for p in order:
        strong = p["baseline"] or p["pareto"]
        style = dict(fontsize=7 if strong else 5.5, color="#202020" if strong else "#6e6e6e",
                     fontweight="bold" if p["baseline"] else "normal")
        chosen = None
        for i, (dx, dy, ha, va) in enumerate(offsets):
            ann = ax.annotate(p["label"], (p["t"], p["e"]), xytext=(dx, dy),
                              textcoords="offset points", ha=ha, va=va, zorder=6, **style)
            box = ann.get_window_extent(renderer)
            inside = (box.x0 >= axbox.x0 and box.x1 <= axbox.x1
                      and box.y0 >= axbox.y0 and box.y1 <= axbox.y1)
            free = inside and not any(box.overlaps(b) for b in taken)
            if free or i == len(offsets) - 1:
                if not free:  # nowhere free: fall back to the first offset with a leader line
                    ann.remove()
                    dx, dy, ha, va = offsets[0]
                    ann = ax.annotate(p["label"], (p["t"], p["e"]), xytext=(dx, dy),
                                      textcoords="offset points", ha=ha, va=va, zorder=6,
                                      **style)
                    box = ann.get_window_extent(renderer)
                chosen = ann
                break
            ann.remove()
        taken.append(chosen.get_window_extent(renderer))


def draw(ax, points, title):
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter
    xs = [p["t"] for p in points]
    ys = [p["e"] for p in points]
    # Thin min..max run-time bars behind everything.
    bars = [p for p in points if p["tmin"] is not None and p["tmax"] is not None
            and 0 < p["tmin"] <= p["t"] <= p["tmax"] and p["tmax"] > p["tmin"]]
    if bars:
        ax.errorbar([p["t"] for p in bars], [p["e"] for p in bars],
                    xerr=[[p["t"] - p["tmin"] for p in bars], [p["tmax"] - p["t"] for p in bars]],
                    fmt="none", ecolor="#c8c8c8", elinewidth=0.8, capsize=2, zorder=1,
                    label="GPU time min..max")
    ax.scatter(xs, ys, s=18, color=DOT_COLOUR, zorder=3, label="configuration",
               edgecolors="none")
    front = sorted((p for p in points if p["pareto"]), key=lambda p: (p["t"], p["e"]))
    if front:
        fx = [p["t"] for p in front] + [max(xs)]
        fy = [p["e"] for p in front] + [front[-1]["e"]]
        ax.step(fx, fy, where="post", color=FRONT_COLOUR, lw=1.4, alpha=0.85, zorder=4)
        ax.scatter(fx[:-1], fy[:-1], s=34, color=FRONT_COLOUR, zorder=5,
                   edgecolors="white", linewidths=0.6,
                   label="Pareto front (best RMSE at this time)")
    for p in points:
        if p["baseline"]:
            ax.scatter([p["t"]], [p["e"]], marker="*", s=170, color="black", zorder=7,
                       edgecolors="white", linewidths=0.6, label=f"baseline: {p['label']}")
    ax.set_xscale("log")
    lo, hi = min(xs), max(xs)
    for p in points:
        lo = min(lo, p["tmin"] or lo) if (p["tmin"] or 0) > 0 else lo
        hi = max(hi, p["tmax"] or hi)
    pad = 1.25 if hi / lo < 50 else 1.5
    ax.set_xlim(lo / pad, hi * pad)
    ylo, yhi = min(ys), max(ys)
    span = (yhi - ylo) or max(abs(yhi), 1e-3) * 0.1
    ax.set_ylim(max(0.0, ylo - 0.08 * span), yhi + 0.12 * span)
    fmt = FuncFormatter(lambda v, _: f"{v:g}")
    ax.xaxis.set_major_formatter(fmt)
    if hi * pad / (lo / pad) < 100:  # under two decades: label 2x and 5x ticks as well
        ax.xaxis.set_minor_locator(LogLocator(base=10, subs=(2.0, 3.0, 5.0)))
        ax.xaxis.set_minor_formatter(fmt)
    else:
        ax.xaxis.set_minor_formatter(NullFormatter())
    ax.tick_params(axis="x", which="minor", labelsize=7)
    ax.grid(True, which="major", color="#dddddd", lw=0.8)
    ax.grid(True, which="minor", axis="x", color="#eeeeee", lw=0.6)
    ax.set_axisbelow(True)
    ax.set_xlabel("AO + denoise GPU time per frame (ms)")
    ax.set_ylabel("RMSE vs ray-traced reference (geometry pixels)")
    ax.set_title(title, fontsize=10)
    ax.legend(loc="upper right", fontsize=7, framealpha=0.9)


def save(fig, out):
    fig.savefig(out + ".png", dpi=150)
    fig.savefig(out + ".svg", metadata={"Date": None})


def by_scene(rows):
    """Per (scene, label): mean time, RMS of per-view RMSE, time range over views."""
    scenes = OrderedDict()
    for r in rows:
        scenes.setdefault(r["scene"] or "(no scene)", OrderedDict()).setdefault(
            r["label"], []).append(r)
    out = OrderedDict()
    for scene, groups in scenes.items():
        pts = []
        for label, g in groups.items():
            mins = [r["tmin"] if r["tmin"] is not None else r["t"] for r in g]
            maxs = [r["tmax"] if r["tmax"] is not None else r["t"] for r in g]
            pts.append({
                "label": label, "scene": scene,
                "t": sum(r["t"] for r in g) / len(g),
                "e": math.sqrt(sum(r["e"] ** 2 for r in g) / len(g)),
                "tmin": min(mins), "tmax": max(maxs),
                "baseline": any(r["baseline"] for r in g),
                "pareto": any(r["pareto"] for r in g),
            })
        out[scene] = pts
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n")[0])
    ap.add_argument("--summary", required=True, help="summary.csv (one row per configuration)")
    ap.add_argument("--results", help="results.csv (per scene/viewpoint rows); adds OUT_by_scene")
    ap.add_argument("--out", required=True, help="output path without extension, e.g. DIR/pareto")
    ap.add_argument("--title", default="SSAO run time against error", help="figure title")
    args = ap.parse_args(argv)

    out = args.out[:-4] if args.out.lower().endswith((".png", ".svg")) else args.out
    summary = read_rows(args.summary)
    results = read_rows(args.results, extra=("scene",)) if args.results else None
    check_front(summary, args.summary)

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        fail(f"matplotlib is not available ({e})")
    try:
        os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
        fig, ax = plt.subplots(figsize=(10, 6.5))
        draw(ax, summary, args.title)
        fig.tight_layout()  # before labelling: placement works in final pixel positions
        place_labels(ax, summary)
        save(fig, out)
        plt.close(fig)
        if results is not None:
            scenes = by_scene(results)
            n = len(scenes)
            cols = min(n, 2)
            nrows = math.ceil(n / cols)
            fig, axes = plt.subplots(nrows, cols, figsize=(7.5 * cols, 5.2 * nrows),
                                     squeeze=False)
            for ax, (scene, pts) in zip(axes.flat, scenes.items()):
                draw(ax, pts, scene)
            for ax in list(axes.flat)[n:]:
                ax.set_visible(False)
            fig.suptitle(f"{args.title}: per scene (views averaged, RMSE as RMS over views)",
                         fontsize=11)
            fig.tight_layout()
            for ax, pts in zip(axes.flat, scenes.values()):
                place_labels(ax, pts)
            save(fig, out + "_by_scene")
            plt.close(fig)
    except OSError as e:
        fail(f"cannot write {out}: {e.strerror or e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
