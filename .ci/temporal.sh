#!/usr/bin/env bash
# `make temporal`: temporal accumulation in motion on every shared scene. Two `ssaolab bench --motion`
# runs of assets/bench/sweep_temporal.json (640x360, the scene camera, 8 frames along the path,
# 128-ray references): an orbit of 4 degrees and a dolly of 0.1 toward the target. Prints and writes
# docs/bench/temporal.md (tools/temporal_page.py).
# Usage: .ci/temporal.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
source .ci/shared_scenes.sh
ARGS=("${SCENE_ARGS[@]}")
for path in orbit dolly; do
  if [ "$path" = orbit ]; then MOVE=(--motion-orbit 4 --motion-dolly 0); else MOVE=(--motion-orbit 0 --motion-dolly 0.1); fi
  rm -rf "$BUILD/temporal-$path"
  "$BUILD/app/ssaolab" bench "${ARGS[@]}" --size "${TEMPORAL_SIZE:-640x360}" --views 1 --frames "${TEMPORAL_FRAMES:-3}" \
    --warmup 1 --reference-rays "${TEMPORAL_RAYS:-128}" --motion --motion-frames 8 "${MOVE[@]}" \
    --sweep assets/bench/sweep_temporal.json --no-plot --quiet --out "$BUILD/temporal-$path"
done
/usr/bin/python3 tools/temporal_page.py "$BUILD/temporal-orbit/results.json" "$BUILD/temporal-dolly/results.json" docs/bench/temporal.md
