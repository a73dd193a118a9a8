#!/usr/bin/env bash
# `make skips`: every skip of unneeded work measured against the same frame without it
# (`ssaolab skips`) on the built-in showcase and shared scenes at 1280x720, written to
# docs/bench/skips.{json,md} and assembled into docs/benchmarks.md ("Skipped work").
# Usage: .ci/skips.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
source .ci/scenes.sh
scene_args=(--scene builtin:showcase)
for s in "${SKIPS_SCENES[@]}"; do scene_args+=(--scene "$SCENES/$s"); done
"$BUILD/app/ssaolab" skips --size "${BENCH_SIZE:-1280x720}" --frames "${SKIPS_FRAMES:-7}" --out docs/bench \
  "${scene_args[@]}"
BENCH_REPORT_ONLY=1 bash .ci/bench.sh "$BUILD" "$SCENES"
