#!/usr/bin/env python3
"""Draw the run-time-against-error (Pareto) plot of an ssaolab benchmark run.

Called by the C++ benchmark command once it has written summary.csv (one row per
configuration) and results.csv (one row per scene, viewpoint and configuration).
x: AO + denoise GPU time per frame as a multiple of the baseline's on the same view
and machine (the time_ratio column; log axis), so shards measured on different
machines plot together; y: geometry-pixel RMSE against the ray-traced reference, or with
--error motion_score the motion score along each view's camera path (bench --objective motion).
Every configuration is a grey dot with a thin min..max time bar; the Pareto front
(flagged by the C++ side, not recomputed) is highlighted and joined by a step line;
the baseline is a black star. Only the front and the baseline are labelled (the
built-in sweep has ~80 configurations; report.html names every point on hover).

Writes OUT.png (dpi 150) and OUT.svg, and with --results also
OUT_by_scene.png/.svg: one panel per scene, views averaged per configuration
(mean time, RMS of the per-view RMSE), front as flagged per configuration.

Usage: plot_pareto.py --summary S.csv [--results R.csv] --out DIR/pareto [--title T]
                      [--error rmse|motion_score]
Bad input: one line on stderr and exit status 2; unusable rows skipped with a warning.
"""
import argparse
import csv
import math
import os
import sys
import textwrap

PROG = "plot_pareto"
FRONT, DOT, BAR = "#d62728", "#9a9a9a", "#c8c8c8"  # front, other points, time bars


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
    return (text or "").strip().lower() in ("1", "true")


YLABEL = {"rmse": "RMSE vs ray-traced reference (geometry pixels)",
          "motion_score": "motion score: sqrt(per-frame RMSE^2 + instability^2) along the camera path"}


def read_rows(path, extra=(), error="rmse"):
    """Rows of a benchmark CSV as dicts with the plotted fields parsed; bad rows skipped."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            raw, fields = list(reader), reader.fieldnames or []
    except OSError as e:
        fail(f"cannot read {path}: {e.strerror or e}")
    except (csv.Error, UnicodeDecodeError) as e:
        fail(f"malformed CSV {path}: {e}")
    if not raw:
        fail(f"no rows in {path}")
    missing = [c for c in ("label", "gpu_ms", error) + tuple(extra) if c not in fields]
    if missing:
        fail(f"{path} lacks column(s) {', '.join(missing)}")
    rows = []
    ratio = "time_ratio" in fields
    for n, r in enumerate(raw, start=2):
        ms, e = number(r.get("gpu_ms")), number(r.get(error))
        t = number(r.get("time_ratio")) if ratio else ms
        if error != "rmse" and not (r.get(error) or "").strip():
            continue  # not measured for this row (a web engine is not scored in motion): not plotted
        if t is None or e is None or t <= 0 or ms is None or ms <= 0:
            warn(f"{path}:{n}: skipping '{r.get('label')}': gpu_ms={r.get('gpu_ms')!r}, "
                 f"{error}={r.get(error)!r} (need finite numbers, gpu_ms > 0)")
            continue
        scale = t / ms  # the min..max bar in the same unit as t
        tmin, tmax = number(r.get("gpu_ms_min")), number(r.get("gpu_ms_max"))
        rows.append({"label": (r.get("label") or "").strip() or f"row {n}",
                     "scene": (r.get("scene") or "").strip() or "(no scene)",
                     "t": t, "e": e,
                     "tmin": None if tmin is None else tmin * scale,
                     "tmax": None if tmax is None else tmax * scale,
                     "baseline": flag(r.get("baseline")), "pareto": flag(r.get("pareto"))})
    if not rows:
        fail(f"no plottable rows in {path}")
    return rows


def check_front(points, where):
    """Loose consistency check of the C++ flags; warns only, never changes them."""
    nbase = sum(p["baseline"] for p in points)
    if nbase != 1:
        warn(f"{where}: expected exactly one baseline row, found {nbase}")
    for p in (p for p in points if p["pareto"]):
        for q in points:
            if q["t"] < p["t"] * 0.999 and q["e"] < p["e"] * 0.999:
                warn(f"{where}: front point '{p['label']}' is dominated by '{q['label']}'")
                break


def place_labels(ax, points):
    """Annotate the front and the baseline; each label takes the candidate offset that
    overlaps the legend, markers and earlier labels least (the baseline first)."""
    from matplotlib.transforms import Bbox
    renderer = ax.figure.canvas.get_renderer()
    axbox = ax.get_window_extent(renderer)
    taken = [ax.get_legend().get_window_extent(renderer)] if ax.get_legend() else []
    marks = {}  # marker footprints in pixels; a label may touch its own marker only
    for p in points:
        x, y = ax.transData.transform((p["t"], p["e"]))
        r = 10 if p["baseline"] else 5 if p["pareto"] else 4
        marks[id(p)] = Bbox([[x - r, y - r], [x + r, y + r]])
    offsets = [(dx, dy, {1: "left", 0: "center", -1: "right"}[(dx > 0) - (dx < 0)],
                "bottom" if dy > 0 else "top")  # nearest first, then further out
               for dx, dy in ((6, 4), (6, -4), (-6, 4), (-6, -4), (0, 8), (0, -8),
                              (12, 12), (-12, -12), (12, -12), (-12, 12))]

    def cost(box, own):
        out = sum(max(0.0, d) for d in (axbox.x0 - box.x0, box.x1 - axbox.x1,
                                        axbox.y0 - box.y0, box.y1 - axbox.y1))
        area = sum(max(0.0, min(box.x1, b.x1) - max(box.x0, b.x0)) *
                   max(0.0, min(box.y1, b.y1) - max(box.y0, b.y0)) for b in taken + [m for k, m in marks.items() if k != own])
        return area + 1e4 * out

    for p in sorted((p for p in points if p["baseline"] or p["pareto"]),
                    key=lambda p: (not p["baseline"], p["t"])):
        strong = True
        style = dict(fontsize=7 if strong else 5.5, color="#1a1a1a" if strong else "#666666",
                     fontweight="bold" if p["baseline"] else "normal", zorder=6,
                     textcoords="offset points",
                     bbox=dict(boxstyle="square,pad=0.05", fc="white", ec="none", alpha=0.6))
        best = None  # (cost, annotation, box)
        for dx, dy, ha, va in offsets:
            k = 1.7 if p["baseline"] else 1.0  # clear the big star
            ann = ax.annotate(p["label"], (p["t"], p["e"]), xytext=(k * dx, k * dy), ha=ha,
                              va=va, **style)
            box = ann.get_window_extent(renderer).padded(1.5)
            c = cost(box, id(p))
            if best is None or c < best[0]:
                if best:
                    best[1].remove()
                best = (c, ann, box)
            else:
                ann.remove()
            if c == 0:
                break
        taken.append(best[2])


def draw(ax, points, title, front_label, legend=True, error="rmse"):
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter
    xs, ys = [p["t"] for p in points], [p["e"] for p in points]
    bars = [p for p in points if p["tmin"] is not None and p["tmax"] is not None
            and 0 < p["tmin"] <= p["t"] <= p["tmax"] and p["tmax"] > p["tmin"]]
    if bars:
        ax.errorbar([p["t"] for p in bars], [p["e"] for p in bars], fmt="none",
                    xerr=[[p["t"] - p["tmin"] for p in bars], [p["tmax"] - p["t"] for p in bars]],
                    ecolor=BAR, elinewidth=0.8, capsize=2, zorder=1, label="GPU time min..max")
    ax.scatter(xs, ys, s=18, color=DOT, edgecolors="none", zorder=3, label="configuration")
    front = sorted((p for p in points if p["pareto"]), key=lambda p: (p["t"], p["e"]))
    if front:
        fx, fy = [p["t"] for p in front], [p["e"] for p in front]
        ax.step(fx + [max(xs)], fy + [fy[-1]], where="post", color=FRONT, lw=1.4, alpha=0.85,
                zorder=4)
        ax.scatter(fx, fy, s=34, color=FRONT, edgecolors="white", linewidths=0.6, zorder=5)
        ax.plot([], [], color=FRONT, lw=1.4, marker="o", ms=5, mec="white", label=front_label)
    for p in (p for p in points if p["baseline"]):
        ax.scatter([p["t"]], [p["e"]], marker="*", s=170, color="black", edgecolors="white",
                   linewidths=0.6, zorder=7, label=f"baseline: {p['label']}")
    lo, hi = min([p["tmin"] for p in bars] + xs), max([p["tmax"] for p in bars] + xs)
    ax.set_xscale("log")
    ax.set_xlim(lo / 1.2, hi * 1.2)
    ylo, yhi = min(ys), max(ys)
    span = (yhi - ylo) or max(abs(yhi), 1e-3) * 0.2
    ax.set_ylim(max(0.0, ylo - 0.08 * span), yhi + 0.12 * span)
    fmt = FuncFormatter(lambda v, _: f"{v:g}")
    ax.xaxis.set_major_formatter(fmt)
    if hi / lo < 70:  # under two decades on screen: label the 2x, 3x and 5x ticks too
        ax.xaxis.set_minor_locator(LogLocator(base=10, subs=(2.0, 3.0, 5.0)))
        ax.xaxis.set_minor_formatter(fmt)
    else:
        ax.xaxis.set_minor_formatter(NullFormatter())
    ax.tick_params(axis="both", which="both", labelsize=8)
    ax.grid(True, which="major", color="#dddddd", lw=0.8)
    ax.grid(True, which="minor", axis="x", color="#eeeeee", lw=0.6)
    ax.set_axisbelow(True)
    ax.set_xlabel("AO + denoise GPU time per frame (x the baseline's on the same view and machine)", fontsize=9)
    ax.set_ylabel(YLABEL[error], fontsize=9)
    ax.set_title("\n".join(textwrap.wrap(title, 70)), fontsize=9)
    if legend:
        ax.legend(loc="upper right", fontsize=7, framealpha=0.9)


def save(fig, out):
    fig.savefig(out + ".png", dpi=150)
    fig.savefig(out + ".svg", metadata={"Date": None})


def by_scene(rows):
    """Per scene, one point per label: mean time, RMS of per-view RMSE, time range."""
    scenes = {}
    for r in rows:
        scenes.setdefault(r["scene"], {}).setdefault(r["label"], []).append(r)
    out = {}
    for scene, groups in scenes.items():
        out[scene] = [{"label": label, "t": math.exp(sum(math.log(r["t"]) for r in g) / len(g)),
                       "e": math.sqrt(sum(r["e"] ** 2 for r in g) / len(g)),
                       "tmin": min(r["t"] if r["tmin"] is None else r["tmin"] for r in g),
                       "tmax": max(r["t"] if r["tmax"] is None else r["tmax"] for r in g),
                       "baseline": any(r["baseline"] for r in g),
                       "pareto": False} for label, g in groups.items()]
        # This scene's own front (the C++ flag is for all scenes together): not dominated here.
        pts = out[scene]
        for p in pts:
            p["pareto"] = not any(q is not p and q["t"] <= p["t"] and q["e"] <= p["e"]
                                  and (q["t"] < p["t"] or q["e"] < p["e"]) for q in pts)
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n")[0])
    ap.add_argument("--summary", required=True, help="summary.csv, one row per configuration")
    ap.add_argument("--results", help="results.csv, per scene/viewpoint; adds OUT_by_scene")
    ap.add_argument("--out", required=True, help="output path without extension: DIR/pareto")
    ap.add_argument("--title", default="SSAO run time against error", help="figure title")
    ap.add_argument("--error", default="rmse", choices=sorted(YLABEL),
                    help="the y axis: the still RMSE, or the motion score (bench --objective motion)")
    args = ap.parse_args(argv)
    out = args.out[:-4] if args.out.lower().endswith((".png", ".svg")) else args.out
    summary = read_rows(args.summary, error=args.error)
    results = read_rows(args.results, extra=("scene",), error=args.error) if args.results else None
    check_front(summary, args.summary)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        fail(f"matplotlib is not available to {sys.executable} ({e})")
    try:
        os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
        fig, ax = plt.subplots(figsize=(10, 6.5))
        name = "motion score" if args.error == "motion_score" else "RMSE"
        draw(ax, summary, args.title, f"Pareto front (best {name} at this time)", error=args.error)
        fig.tight_layout()  # before labelling: placement works on final pixel positions
        place_labels(ax, summary)
        save(fig, out)
        if results is not None:
            scenes = by_scene(results)
            cols, rows = min(len(scenes), 2), math.ceil(len(scenes) / 2)
            fig, axes = plt.subplots(rows, cols, figsize=(7.5 * cols, 5.2 * rows), squeeze=False)
            for i, (ax, (scene, pts)) in enumerate(zip(axes.flat, scenes.items())):
                draw(ax, pts, scene, "Pareto front (this scene)", legend=(i == 0), error=args.error)
            for ax in list(axes.flat)[len(scenes):]:
                ax.set_visible(False)
            fig.suptitle("\n".join(textwrap.wrap(f"{args.title}: per scene (mean over views; {name} as RMS)", 110)),
                         fontsize=10)
            fig.tight_layout()
            for ax, pts in zip(axes.flat, scenes.values()):
                place_labels(ax, pts)
            save(fig, out + "_by_scene")
    except OSError as e:
        fail(f"cannot write {out}: {e.strerror or e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
