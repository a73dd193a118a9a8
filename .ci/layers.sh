#!/usr/bin/env bash
# `make layers`: one depth layer against two (gbuffer.second_layer) on every shared scene.
# One `ssaolab bench` of assets/bench/sweep_layers.json (640x360, R = 5 % of the diagonal, the scene
# camera and one orbit, 10 timed frames each, the screen-space oracle of one layer and, for the
# two-layer rows, of two). Prints and writes docs/bench/layers.md (tools/layers_page.py).
# Usage: .ci/layers.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
RUN="$BUILD/layers-run"
rm -rf "$RUN"
source .ci/shared_scenes.sh
ARGS=("${SCENE_ARGS[@]}")
"$BUILD/app/ssaolab" bench "${ARGS[@]}" --size "${LAYERS_SIZE:-640x360}" --views 2 --frames "${LAYERS_FRAMES:-10}" \
  --warmup 2 --reference-rays "${LAYERS_RAYS:-128}" --sweep assets/bench/sweep_layers.json --no-plot --quiet --out "$RUN"
/usr/bin/python3 tools/layers_page.py "$RUN/results.json" docs/bench/layers.md
