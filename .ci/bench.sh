#!/usr/bin/env bash
# `make bench`: the reference tracer's rays/s (Google Benchmark) and `ssaolab bench` (built-in sweep
# on the shared scenes at 640x360), assembled into docs/benchmarks.md with the plot in docs/bench/.
# Usage: .ci/bench.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
SIZE=${BENCH_SIZE:-640x360}
OUT=docs/bench
mkdir -p "$OUT"

# BENCH_REPORT_ONLY=1: reassemble docs/benchmarks.md from the last run's files (e.g. after editing
# docs/bench-discussion.md) without measuring again.
if [ -z "${BENCH_REPORT_ONLY:-}" ]; then
"$BUILD/tests/bench_reference" --benchmark_min_time=2 2>/dev/null | tee "$OUT/reference_rays.txt"
# The run writes a thumbnail of every configuration (for merging shards); the page keeps the
# self-contained report.html, which embeds those of the front and the baseline only.
RUN="$BUILD/bench-run"
rm -rf "$RUN"
source .ci/scenes.sh
scene_args=()
for s in "${BENCH_SCENES[@]}"; do scene_args+=(--scene "$SCENES/$s"); done
"$BUILD/app/ssaolab" bench "${scene_args[@]}" --size "$SIZE" --views 2 --frames "${BENCH_FRAMES:-10}" --out "$RUN"
for f in results.csv summary.csv results.json report.md report.html pareto.png pareto.svg \
         pareto_by_scene.png pareto_by_scene.svg; do
  cp "$RUN/$f" "$OUT/$f"
done
fi

{
  cat <<'MD'
# Benchmarks: run time against error

Regenerate everything on this page with one command: `make bench` (it runs `.ci/bench.sh`).
Error is measured against the ray-traced reference (README, "Ground truth"): geometry-pixel RMSE
of linear AO is the headline; PSNR is of sRGB-encoded AO (XeGTAO's convention; XeGTAO's own
GTAO "High" scores about 21.4 dB full-frame against its 512-ray reference on Bistro). Every
configuration gets the same world radius R as the reference (5 % of the scene's diagonal). The
`learnopengl` preset is the baseline: every row gives its time and error as ratios to the
baseline measured in the same run.

Times on llvmpipe (Mesa's CPU rasteriser) rank configurations by their work, not by what a GPU
would take: texture fetches and ALU cost roughly alike there. No GPU was lent to the session
that made this page; a GPU measured apart is in "The GPU column" below.

## Reference tracer throughput (CornellBox, 640x360, R = 5 % of the diagonal)

```
MD
  grep -E "^(BM_|Benchmark|-)" "$OUT/reference_rays.txt"
  echo '```'
  echo
  echo "## Time against error (\`ssaolab bench\`, built-in sweep)"
  echo
  # The hand-written reading of the front (docs/bench-discussion.md), dated to the run it reads.
  if [ -f docs/bench-discussion.md ]; then cat docs/bench-discussion.md; echo; fi
  sed -e 's#](pareto.png)#](bench/pareto.png)#' "$OUT/report.md"
  echo
  echo "### Per scene: training and held-out scenes"
  echo
  /usr/bin/python3 .ci/heldout.py "$OUT/results.csv" assets/presets -
  echo
  echo "Per scene: ![per scene](bench/pareto_by_scene.png)"
  echo
  echo "The same run as a page to look at: [report.html](bench/report.html) (offline: the plots, every point named on"
  echo "hover, the AO, signed error and reference of every front configuration and the baseline, a sortable table)."
  echo
  echo "Raw data: [results.csv](bench/results.csv), [summary.csv](bench/summary.csv), [results.json](bench/results.json)."
  # A section made by its own make target: title, target, the hand-written reading, the data.
  section() { # TITLE TARGET SCRIPT DISCUSSION DATA_MD RAW
    [ -f "$5" ] || return 0
    echo
    echo "## $1"
    echo
    echo "Regenerate this section alone with \`make $2\` (it runs \`.ci/$3\`)."
    if [ -f "$4" ]; then echo; cat "$4"; fi
    echo
    # the section's page links its images beside itself (docs/bench/); this page is one folder up
    sed -e 's/^### What the screen cannot see$/### The split per scene/' -e 's#](\([a-z_]*\.png\))#](bench/\1)#g' "$5"
    echo
    echo "Raw data: [$6](bench/$6)."
  }
  section "What the screen cannot see (\`make screen\`, every shared scene, 640x360)" screen screen.sh \
    docs/screen-discussion.md "$OUT/screen.md" screen.json
  section "The web peers (\`make peers\`, four scenes, one run)" peers peers.sh docs/peers-discussion.md \
    "$OUT/peers.md" peers.json
  section "The explorer's frame times (\`make explorer\`)" explorer explorer.sh docs/explorer-discussion.md \
    "$OUT/explorer.md" explorer.md
  section "Skipped work (\`ssaolab skips\`)" skips skips.sh docs/skips-discussion.md "$OUT/skips.md" skips.json
  section "Scaling (\`make scaling\`)" scaling scaling.sh docs/scaling-discussion.md "$OUT/scaling.md" scaling.json
  section "The GPU column (\`.ci/gpu-run.sh\` on a GPU, then \`make gpu-column\`)" gpu-column gpu-column.sh \
    docs/gpu-discussion.md "$OUT/gpu.md" gpu_summary.csv
} > docs/benchmarks.md
echo "wrote docs/benchmarks.md"
