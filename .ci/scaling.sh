#!/usr/bin/env bash
# `make scaling`: how cost grows (docs/benchmarks.md, "Scaling"), on this machine's GL (llvmpipe in
# CI, a GPU where there is one):
#  1. AO + denoise time against pixels (640x360 .. 3840x2160), per technique (its medium preset)
#     and the learnopengl baseline, CornellBox;
#  2. against the radius in pixels (R = 1.25 % .. 20 % of the diagonal at 1280x720): the
#     texture-cache effect;
#  3. G-buffer time against triangles: a generated height field of 10 k .. 10 M triangles;
#  4. reference (Embree) time against rays per pixel and against pixels.
# Each curve's log-log slope is its exponent (.ci/scaling.py fits and plots them).
# Writes docs/bench/scaling.{md,json,png,svg}, then reassembles docs/benchmarks.md.
# Usage: .ci/scaling.sh BUILD_DIR [SCENES_DIR]; SCALING_RUN (the renders' folder, default
# BUILD_DIR/scaling-run), SCALING_FRAMES (3), SCALING_RENDERS_ONLY, PYTHON (one with numpy).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
RUN=${SCALING_RUN:-$BUILD/scaling-run}
PY=${PYTHON:-/usr/bin/python3} # the grid needs numpy
rm -rf "$RUN"
mkdir -p "$RUN"
SSAO="$BUILD/app/ssaolab"
SCENE="$SCENES/CornellBox/cornellBox.gltf"
# The learnopengl baseline and every technique's medium preset (`ssaolab techniques`: the registry).
PRESETS=(learnopengl)
TECHNIQUES=$("$SSAO" techniques)
for t in $TECHNIQUES; do
  if [ -f "assets/presets/$t-medium.json" ]; then PRESETS+=("$t-medium"); else echo "scaling: $t has no medium preset (make presets)"; fi
done
FR=${SCALING_FRAMES:-3}
render() { # OUT ARGS...: one render, its metrics.json kept
  local out=$1
  shift
  "$SSAO" render --quiet --timing-frames "$FR" --out "$RUN/tmp" "$@" >/dev/null
  cp "$RUN/tmp/metrics.json" "$out"
}
mkdir -p "$RUN/pixels" "$RUN/radius" "$RUN/triangles" "$RUN/reference"
for p in "${PRESETS[@]}"; do
  for size in 640x360 960x540 1280x720 1920x1080 2560x1440 3840x2160; do
    render "$RUN/pixels/${p}_${size}.json" --scene "$SCENE" --preset "$p" --size "$size"
  done
  for r in 0.0125 0.025 0.05 0.1 0.2; do
    render "$RUN/radius/${p}_${r}.json" --scene "$SCENE" --preset "$p" --size 1280x720 --set ao.radius_mode=scene \
      --set ao.radius_scene="$r"
  done
  echo "scaling: $p"
done
for n in 10000 100000 1000000 3000000 10000000; do
  "$PY" .ci/scaling.py grid "$n" "$RUN/grid_$n.gltf"
  render "$RUN/triangles/$n.json" --scene "$RUN/grid_$n.gltf" --preset vbao-medium --size 1280x720
  rm -f "$RUN/grid_$n.gltf" "$RUN/grid_$n.bin"
  echo "scaling: $n triangles"
done
# SCALING_RENDERS_ONLY=1 (.ci/gpu-run.sh on a GPU): the GL curves alone; the reference is the CPU's.
[ -n "${SCALING_RENDERS_ONLY:-}" ] && { rm -rf "$RUN/tmp" "$RUN/reference"; exit 0; }
# The reference, uncached (a private cache folder per run).
for rays in 32 64 128 256 512; do
  XDG_CACHE_HOME="$RUN/cache_r$rays" render "$RUN/reference/rays_$rays.json" --scene "$SCENE" --preset vbao-medium \
    --size 320x180 --reference --reference-rays "$rays"
done
for size in 160x90 320x180 640x360 1280x720; do
  XDG_CACHE_HOME="$RUN/cache_p$size" render "$RUN/reference/pixels_$size.json" --scene "$SCENE" --preset vbao-medium \
    --size "$size" --reference --reference-rays 32
done
rm -rf "$RUN"/cache_*
/usr/bin/python3 .ci/scaling.py report "$RUN" docs/bench
BENCH_REPORT_ONLY=1 bash .ci/bench.sh "$BUILD" "$SCENES"
