#!/usr/bin/env bash
# `make user-twins`: what a user technique costs against its built-in twin (docs/own-technique.md).
# One `ssaolab bench` of assets/bench/sweep_user_twins.json over the shared scenes (640x360, the
# scene camera and one orbit, 20 timed frames each): the kernel at the learnopengl preset beside
# examples/techniques/learnopengl.ao.glsl, GTAO high beside examples/techniques/xegtao.ao.glsl, each
# pair on the same frames. Prints and writes docs/bench/user-twins.md: per pair and scene the AO
# pass's median ms of each and their ratio, and the RMSE of each against the reference.
# Usage: .ci/user-twins.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
SIZE=${TWINS_SIZE:-640x360}
RUN="$BUILD/user-twins-run"
rm -rf "$RUN"
LIST=(CornellBox/cornellBox.gltf SciFiHelmet/SciFiHelmet.gltf FlightHelmet/FlightHelmet.gltf Lantern/Lantern.gltf
      ShaderBall/shader_ball.gltf)
ARGS=()
for s in "${LIST[@]}"; do ARGS+=(--scene "$SCENES/$s"); done
"$BUILD/app/ssaolab" --technique-dir examples/techniques bench "${ARGS[@]}" --size "$SIZE" --views 2 \
  --frames "${TWINS_FRAMES:-20}" --warmup 2 --reference-rays "${TWINS_RAYS:-64}" \
  --sweep assets/bench/sweep_user_twins.json --no-plot --quiet --out "$RUN"
/usr/bin/python3 tools/user_twins.py "$RUN/results.json" "$RUN/results.csv" docs/bench/user-twins.md
