#!/usr/bin/env bash
# The GPU column of docs/benchmarks.md, measured on a machine with a GPU (the device tool's, or
# yours): the renders of `make scaling` (AO + denoise against pixels and radius, G-buffer against
# triangles; the reference is Embree on the CPU and stays out) and the sweep of `make bench`, in
# three sequential shards so that a run cut short keeps the shards it finished, and the skips a GPU
# may answer differently (`ssaolab skips`, five scenes). Then, on any
# machine: `.ci/gpu-column.py OUT` writes docs/bench/gpu.md, gpu_summary.csv, gpu_pareto.png and
# scaling_gpu.json, and `BENCH_REPORT_ONLY=1 .ci/bench.sh` puts them on the page.
# Usage: .ci/gpu-run.sh SSAOLAB SCENES_DIR OUT   (SCENES_DIR holds the shared scenes' folders)
set -u
S=$1 SC=$2 OUT=$3
T0=$(date +%s)
el() { echo $(( $(date +%s) - T0 )); }
mkdir -p "$OUT"
SCAL=$(mktemp -d)
mkdir -p "$SCAL/pixels" "$SCAL/radius" "$SCAL/triangles"
"$S" render --quiet --scene "$SC/CornellBox/cornellBox.gltf" --size 640x360 --preset vbao-medium --timing-frames 10 \
  --out "$SCAL/tmp" || { echo "gpu-run: no GL" >&2; exit 3; }
cp "$SCAL/tmp/metrics.json" "$OUT/check.json"
render() { local out=$1; shift; "$S" render --quiet --timing-frames 10 --out "$SCAL/tmp" "$@" >/dev/null && cp "$SCAL/tmp/metrics.json" "$out"; }
for p in learnopengl kernel-medium sao-medium hbao-medium gtao-medium vbao-medium; do
  for size in 640x360 960x540 1280x720 1920x1080 2560x1440 3840x2160; do
    render "$SCAL/pixels/${p}_${size}.json" --scene "$SC/CornellBox/cornellBox.gltf" --preset "$p" --size "$size"
  done
  for r in 0.0125 0.025 0.05 0.1 0.2; do
    render "$SCAL/radius/${p}_${r}.json" --scene "$SC/CornellBox/cornellBox.gltf" --preset "$p" --size 1280x720 \
      --set ao.radius_mode=scene --set ao.radius_scene="$r"
  done
  echo "scaling $p $(el)s"
done
for n in 10000 100000 1000000 3000000 10000000; do # the generated height field of .ci/scaling.py (numpy)
  python3 "$(dirname "$0")/scaling.py" grid "$n" "$SCAL/grid_$n.gltf" &&
    render "$SCAL/triangles/$n.json" --scene "$SCAL/grid_$n.gltf" --preset vbao-medium --size 1280x720
  rm -f "$SCAL/grid_$n".*
  echo "scaling $n triangles $(el)s"
done
rm -rf "$SCAL/tmp"
tar czf "$OUT/scaling.tgz" -C "$SCAL" .
for k in 1 2 3; do # the sweep and scenes of .ci/bench.sh
  [ "$(el)" -gt "${GPU_RUN_BUDGET_S:-420}" ] && { echo "skip shard $k at $(el)s"; continue; }
  "$S" bench --scene "$SC/CornellBox/cornellBox.gltf" --scene "$SC/FlightHelmet/FlightHelmet.gltf" \
    --scene "$SC/2CylinderEngine/2CylinderEngine.gltf" --scene "$SC/Lantern/Lantern.gltf" \
    --scene "$SC/ReciprocatingSaw/ReciprocatingSaw.gltf" --scene "$SC/ShaderBall/shader_ball.gltf" \
    --size 640x360 --views 2 --frames 10 --shard $k/3 --out "$SCAL/shard-$k" > "$SCAL/shard-$k.log" 2>&1
  echo "shard $k rc=$? $(el)s"
  tar czf "$OUT/bench$k.tgz" -C "$SCAL" "shard-$k"
done
# The skips of `make skips` that a GPU may answer differently (deinterleaving, fused upsample,
# occlusion queries, sky, hidden faces), per scene at 1280x720.
mkdir -p "$SCAL/skips"
for s in CornellBox/cornellBox 2CylinderEngine/2CylinderEngine ReciprocatingSaw/ReciprocatingSaw Lantern/Lantern \
         FlightHelmet/FlightHelmet; do
  [ "$(el)" -gt "${GPU_RUN_BUDGET_S:-420}" ] && { echo "skip skips of $s at $(el)s"; continue; }
  "$S" skips --quiet --scene "$SC/$s.gltf" --size 1280x720 --frames 7 --out "$SCAL/sk" &&
    cp "$SCAL/sk/skips.json" "$SCAL/skips/skips_${s%%/*}.json"
  echo "skips ${s%%/*} $(el)s"
done
tar czf "$OUT/skips.tgz" -C "$SCAL/skips" .
echo "gpu-run: done in $(el)s"
