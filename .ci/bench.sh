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

# BENCH_REPORT_ONLY=1: reassemble docs/benchmarks.md from the last run's files without measuring
# again.
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
Each section is made by its own script from its own run and starts with that run's machine line.
Error is measured against the ray-traced reference ([guide](guide/reference.md)): geometry-pixel
RMSE of linear AO is the headline; PSNR is of sRGB-encoded AO (XeGTAO's convention). Every
configuration gets the same world radius R as the reference (5 % of the scene's diagonal). The
`learnopengl` preset is the baseline: every row gives its time and error as ratios to the
baseline measured in the same run, and those ratios are what compare across machines.

How to read the times: on llvmpipe (Mesa's CPU rasteriser) they rank configurations by their work,
not by what a GPU would take (texture fetches and arithmetic cost roughly alike there); "The GPU
column", where present, is the same sweep on a GPU.

## Reference tracer throughput (CornellBox, 640x360, R = 5 % of the diagonal)

```
MD
  grep -E "^(BM_|Benchmark|-)" "$OUT/reference_rays.txt"
  echo '```'
  echo
  echo "## Time against error (\`ssaolab bench\`, built-in sweep)"
  echo
  echo "How to read it: the front is every configuration that no other beats on both time and error;"
  echo "read across a row for its ratios to the baseline, and down the front for the cheapest way to a"
  echo "given error. A ratio below 1 is better on both axes. Per scene, the held-out scenes are the ones"
  echo "the tuned presets never saw: a preset that wins only on the training scenes has not won."
  echo
  echo "The page: [report.md](bench/report.md) (the front, where the time goes, what the screen cannot see, every"
  echo "configuration), its plot:"
  echo
  echo "![time against error](bench/pareto.png)"
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
  # A section made by its own make target: title, target, how to read it, its page (stored once,
  # in docs/bench/, and linked from here), the raw data.
  section() { # TITLE TARGET SCRIPT HOW_TO_READ PAGE_MD RAW
    [ -f "$5" ] || return 0
    echo
    echo "## $1"
    echo
    echo "Regenerate this section alone with \`make $2\` (it runs \`.ci/$3\`). $4"
    echo
    if [ "$(basename "$5")" = "$6" ]; then echo "The page: [$6](bench/$6)."
    else echo "The page: [$(basename "$5")](bench/$(basename "$5")). Raw data: [$6](bench/$6)."; fi
  }
  section "What the screen cannot see (\`make screen\`)" screen screen.sh \
    "How to read it: the screen share is what no technique reading one depth layer can fix; a remedy's column is what it closes of that share." \
    "$OUT/screen.md" screen.json
  section "The web peers (\`make peers\`)" peers peers.sh \
    "How to read it: each peer at its defaults with every length from R, judged by ssaolab's own metric on the same view; a preset listed beside it has at most half its RMSE in at most half its time." \
    "$OUT/peers.md" peers.json
  section "The explorer's frame times (\`make explorer\`)" explorer explorer.sh \
    "How to read it: still, drag and idle frames of the real UI; the ratios to the learnopengl seed's frames of the same run are what compare." \
    "$OUT/explorer.md" explorer.md
  section "Skipped work (\`ssaolab skips\`)" skips skips.sh \
    "How to read it: each skip against the same frame without it, alternating frame by frame; an exact skip changes no geometry pixel." \
    "$OUT/skips.md" skips.json
  section "Scaling (\`make scaling\`)" scaling scaling.sh \
    "How to read it: each curve's exponent is how cost grows with that quantity (1: linear)." \
    "$OUT/scaling.md" scaling.json
  section "The GPU column (\`.ci/gpu-run.sh\` on a GPU, then \`make gpu-column\`)" gpu-column gpu-column.sh \
    "How to read it: the same sweep, scaling and skips on a GPU; compare its ratios, not its times, with the llvmpipe sections." \
    "$OUT/gpu.md" gpu_summary.csv
} > docs/benchmarks.md
echo "wrote docs/benchmarks.md"
