#!/usr/bin/env python3
"""What `ssaolab stress` found, as docs/stability.md's summary: every number read from the run's
stress.json (the rows the page's tables show), none written by hand.

Usage: stress_findings.py STRESS.json   (Markdown on stdout)"""
import json
import re
import sys

from markdown_cell import cell


def rmse_max(rows):
    """(largest RMSE, its row) over the rows that were compared, or (None, None)."""
    best = None
    for r in rows:
        if r["status"] == "ok" and (r.get("compared") or r.get("invariant")) and r.get("rmse", -1) >= 0:
            if best is None or r["rmse"] > best["rmse"]:
                best = r
    return (best["rmse"], best) if best else (None, None)


def fmt(x):
    return "-" if x is None else "%.4f" % x


def where(r):
    return "%s, %s" % (cell(str(r["scene"])), cell(str(r["technique"]))) if r else "no row"


def near_values(rows, mapping):
    """Per near plane (in diagonals) of one depth mapping: the largest RMSE and where."""
    out = {}
    for r in rows:
        m = re.fullmatch(r"([0-9.e+-]+) x diag, (standard|reversed)", r["variant"])
        if r["axis"] == "near" and m and m.group(2) == mapping:
            out.setdefault(float(m.group(1)), []).append(r)
    return {k: rmse_max(v) for k, v in sorted(out.items(), reverse=True)}


def findings(doc):
    rows, tol = doc["rows"], doc["tolerance"]
    lines = []
    bad = sum(r.get("nonfinite", 0) + r.get("outside", 0) for r in rows)
    lines.append("- Non-finite or out-of-range values over every case: %d." % bad)
    scale, at = rmse_max([r for r in rows if r["axis"] == "scale"])
    lines.append("- Scale 1e-3 to 1e3 (the radius follows the scene): largest RMSE %s (%s); tolerance %.2g."
                 % (fmt(scale), where(at), tol))
    origin = [r for r in rows if r["axis"] == "translate" and "float positions" not in r["variant"]]
    moved, at = rmse_max(origin)
    lines.append("- Moved up to 1e7 units, positions kept relative to a double-precision scene origin "
                 "(renderer/scene/scene.h): largest RMSE %s." % fmt(moved))
    floats = sorted({r["variant"] for r in rows if r["axis"] == "translate" and "float positions" in r["variant"]})
    if floats:
        parts = ["%s: %s" % (cell(v.split(",")[0]), fmt(rmse_max([r for r in rows if r["variant"] == v])[0])) for v in floats]
        lines.append("  What the origin saves - the same moves with float positions, largest RMSE: " + "; ".join(parts) + ".")
    for mapping in ("standard", "reversed"):
        vals = near_values(rows, mapping)
        parts = ["%g: %s" % (k, fmt(v[0])) for k, v in vals.items()]
        worst = max(vals.values(), key=lambda v: -1 if v[0] is None else v[0], default=(None, None))
        lines.append("- Near plane (diagonals) with %s depth, largest RMSE against the fitted planes: %s (worst: %s)."
                     % (mapping, "; ".join(parts), where(worst[1])))
    refused = [r for r in rows if r["status"] == "refused"]
    lines.append("- Cases a guard refused with a clear error: %d." % len(refused))
    proj = [r for r in rows if r["axis"] == "projection"]
    pbad = sum(r.get("nonfinite", 0) + r.get("outside", 0) for r in proj)
    lines.append("- Orthographic and infinite-far projections: %d renders, %d non-finite or out-of-range values."
                 % (len(proj), pbad))
    geo = sorted({r["variant"] for r in rows if r["axis"] == "geometry"})
    parts = ["%s: %s" % (cell(v), fmt(rmse_max([r for r in rows if r["axis"] == "geometry" and r["variant"] == v])[0]))
             for v in geo]
    lines.append("- Geometry, largest RMSE: " + "; ".join(parts) + ".")
    return "\n".join(lines)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    try:
        with open(sys.argv[1], encoding="utf-8") as f:
            doc = json.load(f)
        text = findings(doc)
    except (OSError, ValueError, KeyError, TypeError) as e:
        sys.exit("stress_findings: error: %s: %s" % (sys.argv[1], e))
    print(text)


if __name__ == "__main__":
    main()
