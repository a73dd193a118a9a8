#!/usr/bin/env bash
# `make peers`: the four web peers (three.js SSAOPass, SAOPass, GTAOPass; N8AO) against every
# shipped ssaolab preset, in one run on this machine's GL (llvmpipe without a GPU; the peers run in
# Debian's Chromium through ANGLE on the same Mesa). Same scene, camera, size and R as the
# reference; errors from `ssaolab render --reference --score` (one metric code for both sides).
# Writes docs/bench/peers.{md,json}, then reassembles docs/benchmarks.md.
# Usage: .ci/peers.sh BUILD_DIR [SCENES_DIR]; PEERS_SCENES (folders of SCENES_DIR: CornellBox, the
# issue's scene, and three held out from the presets' tuning), PEERS_SIZE (640x360), PEERS_FRAMES (20).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
SIZE=${PEERS_SIZE:-640x360}
FR=${PEERS_FRAMES:-20}
SSAO="$BUILD/app/ssaolab"
TECHNIQUES=$("$SSAO" techniques) # the registry's ids, one a line
RUN="$BUILD/peers-run"
MODS="$BUILD/peers"
for tool in node npm /usr/bin/chromium; do
  command -v "$tool" >/dev/null || { echo "peers: $tool not found (Node.js with npm, and Debian's chromium)" >&2; exit 1; }
done
# The peers' packages, at the versions the lock pins (from the npm registry, once per lock).
bash .ci/engine-modules.sh "$BUILD"
# Every configuration at the same R, 5 % of the scene's diagonal (as `bench`): the baseline's own
# preset has a world radius of 0.5.
R_SET=(--set ao.radius_mode=scene --set ao.radius_scene=0.05)
rm -rf "$RUN"
for name in ${PEERS_SCENES:-CornellBox FlightHelmet Lantern ShaderBall}; do
  files=("$SCENES/$name"/*.gltf "$SCENES/$name"/*.glb)
  scene=""
  for f in "${files[@]}"; do [[ -f $f && $f != *upstream* ]] && { scene=$f; break; }; done
  [ -n "$scene" ] || { echo "peers: no .gltf/.glb in $SCENES/$name" >&2; exit 1; }
  dir="$RUN/$name"
  mkdir -p "$dir/ours"
  ours() { # PRESET: one render against the reference, its metrics.json kept
    "$SSAO" render --quiet --scene "$scene" --size "$SIZE" --preset "$1" "${R_SET[@]}" --reference \
      --timing-frames "$FR" --out "$dir/tmp"
    cp "$dir/tmp/metrics.json" "$dir/ours/$1.json"
  }
  # The baseline first: its metrics.json gives the peers the camera (clip planes included) and R.
  ours learnopengl
  R=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['error']['reference']['radius'])" \
    "$dir/ours/learnopengl.json")
  node tools/peers/run_peers.mjs --modules "$MODS/node_modules" --scene "$scene" \
    --metrics "$dir/ours/learnopengl.json" --radius "$R" --size "$SIZE" --frames "$FR" \
    --peers ssao,ssao:min=0.25,ssao:min=0.5,ssao:min=0.75,sao,gtao,n8ao --out "$dir/peers"
  scored=()
  for f in "$dir"/peers/*.pgm; do scored+=(--score "$f"); done
  "$SSAO" render --quiet --scene "$scene" --size "$SIZE" --preset learnopengl "${R_SET[@]}" --reference \
    --timing-frames 1 --out "$dir/scored" "${scored[@]}"
  for t in $TECHNIQUES; do # every technique's shipped presets
    for f in assets/presets/"$t"-*.json; do
      if [ -f "$f" ]; then ours "$(basename "$f" .json)"; fi
    done
  done
  echo "peers: $name"
done
/usr/bin/python3 .ci/peers.py "$RUN" docs/bench
BENCH_REPORT_ONLY=1 bash .ci/bench.sh "$BUILD" "$SCENES"
