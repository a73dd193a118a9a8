#!/usr/bin/env bash
# `make engines`: every web engine tuned on every shared scene and on a close-up city block
# (tools/city_gltf.py), each at its view's radius; tools/engines_table.py writes, per engine and
# scene, as shipped / lengths from R / tuned on held-out views, the screen-space oracle and the time
# ratios to docs/bench/engines.md (and prints it). ENGINES_SIZE (320x180), ENGINES (all: a,b,...),
# ENGINES_RESUME=1 keeps the tunes a stopped run left in BUILD/engines-run.
# Usage: .ci/engines.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
source .ci/shared_scenes.sh
bash .ci/engine-modules.sh "$BUILD"
FILES=()
for s in "${SCENE_LIST[@]}"; do FILES+=("$SCENES/$s"); done
RESUME=()
if [ "${ENGINES_RESUME:-0}" = 1 ]; then RESUME=(--resume); else rm -rf "$BUILD/engines-run"; fi
/usr/bin/python3 tools/engines_table.py --ssaolab "$BUILD/app/ssaolab" --work "$BUILD/engines-run" "${RESUME[@]}" \
  --page docs/bench/engines.md --size "${ENGINES_SIZE:-320x180}" --engines "${ENGINES:-}" "${FILES[@]}"
