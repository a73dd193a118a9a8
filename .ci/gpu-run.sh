#!/usr/bin/env bash
# The GPU column of docs/benchmarks.md, measured on a machine with a GPU: the GL renders of
# `make scaling` (.ci/scaling.sh with SCALING_RENDERS_ONLY: the reference is Embree on the CPU and
# stays out), the sweep and scenes of `make bench` in three sequential shards (a run cut short
# keeps the shards it finished), and the skips a GPU may answer differently (`ssaolab skips` on
# the scenes of `make skips`, one scene at a time). Then, on any machine:
# `make gpu-column GPU_RUN=OUT` puts them on the page beside the llvmpipe run.
# Usage: .ci/gpu-run.sh BUILD_DIR SCENES_DIR OUT   (BUILD_DIR/app/ssaolab; PYTHON: one with numpy)
set -u
cd "$(dirname "$0")/.."
BUILD=$1 SCENES=$2 OUT=$3
S="$BUILD/app/ssaolab"
T0=$(date +%s)
el() { echo $(( $(date +%s) - T0 )); }
late() { [ "$(el)" -gt "${GPU_RUN_BUDGET_S:-420}" ] && echo "gpu-run: skipping $1 at $(el)s (GPU_RUN_BUDGET_S)"; }
source .ci/scenes.sh
mkdir -p "$OUT"
W=$(mktemp -d)
"$S" render --quiet --scene "$SCENES/CornellBox/cornellBox.gltf" --size 640x360 --preset vbao-medium \
  --timing-frames 10 --out "$W/check" || { echo "gpu-run: no GL" >&2; exit 3; }
cp "$W/check/metrics.json" "$OUT/check.json"
SCALING_RUN="$W/scaling" SCALING_RENDERS_ONLY=1 SCALING_FRAMES=10 bash .ci/scaling.sh "$BUILD" "$SCENES"
tar czf "$OUT/scaling.tgz" -C "$W/scaling" .
echo "gpu-run: scaling $(el)s"
scene_args=()
for s in "${BENCH_SCENES[@]}"; do scene_args+=(--scene "$SCENES/$s"); done
for k in 1 2 3; do
  late "bench shard $k" && continue
  "$S" bench "${scene_args[@]}" --size 640x360 --views 2 --frames 10 --shard $k/3 --out "$W/shard-$k" \
    > "$W/shard-$k.log" 2>&1
  echo "gpu-run: bench shard $k rc=$? $(el)s"
  tar czf "$OUT/bench$k.tgz" -C "$W" "shard-$k"
done
mkdir -p "$W/skips"
for s in "${SKIPS_SCENES[@]}"; do
  late "skips of $s" && continue
  n=$(basename "$(dirname "$s")")
  "$S" skips --quiet --scene "$SCENES/$s" --size 1280x720 --frames 7 --out "$W/sk" &&
    cp "$W/sk/skips.json" "$W/skips/skips_$n.json"
  echo "gpu-run: skips $n $(el)s"
done
tar czf "$OUT/skips.tgz" -C "$W/skips" .
echo "gpu-run: done in $(el)s"
