#!/usr/bin/env bash
# `make objective`: the still and the motion answer on every shared scene. One `ssaolab bench
# --objective motion` run of assets/bench/sweep_objective.json (640x360, the scene camera, an orbit
# of 4 degrees over 8 frames, 128-ray references); tools/objective_page.py writes, per scene, the
# lowest still RMSE and the lowest motion score at most the baseline's time, and how far apart they
# are, to docs/bench/objective.md (and prints it).
# Usage: .ci/objective.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
source .ci/shared_scenes.sh
ARGS=("${SCENE_ARGS[@]}")
rm -rf "$BUILD/objective"
"$BUILD/app/ssaolab" bench "${ARGS[@]}" --size "${OBJECTIVE_SIZE:-640x360}" --views 1 --frames "${OBJECTIVE_FRAMES:-5}" \
  --warmup 1 --reference-rays "${OBJECTIVE_RAYS:-128}" --objective motion --motion-frames 8 --motion-orbit 4 \
  --motion-dolly 0 --budget-ratio 1 --sweep assets/bench/sweep_objective.json --no-oracle --no-plot --quiet \
  --out "$BUILD/objective"
/usr/bin/python3 tools/objective_page.py "$BUILD/objective/results.json" docs/bench/objective.md
