#!/usr/bin/env bash
# `make presets`: fits every technique's free parameters at each quality level with `ssaolab tune`
# on four of the shared scenes (even viewpoints train, odd ones are held out) and judges them on the
# other four (never fitted on), then writes the shipped presets assets/presets/TECHNIQUE-LEVEL.json
# with both scores. R stays the reference's 5 % of the diagonal and power 1: only the technique's own
# float rows are fitted (a larger radius or a darkening power would fit the numbers, not the
# physics), then rewrites the presets derived from them (vbao-half-*, vbao-max).
# Usage: .ci/tune-presets.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# Training: a box of slabs, a CAD assembly in millimetres, a hard-surface model and a photogrammetry-
# like prop. Held out: the benchmark's FlightHelmet and Lantern, the saw (CAD) and ShaderBall.
SCENE_ARGS=(--scene "$SCENES/CornellBox/cornellBox.gltf" --scene "$SCENES/2CylinderEngine/2CylinderEngine.gltf"
            --scene "$SCENES/SciFiHelmet/SciFiHelmet.gltf" --scene "$SCENES/AntiqueCamera/AntiqueCamera.gltf"
            --held-out-scene "$SCENES/FlightHelmet/FlightHelmet.gltf" --held-out-scene "$SCENES/Lantern/Lantern.gltf"
            --held-out-scene "$SCENES/ReciprocatingSaw/ReciprocatingSaw.gltf"
            --held-out-scene "$SCENES/ShaderBall/shader_ball.gltf")

# technique level "KEY=VALUE ..." "knob ..."
LEVELS=(
  "kernel low    kernel.samples=16                      kernel.bias"
  "kernel medium kernel.samples=32                      kernel.bias"
  "kernel high   kernel.samples=64                      kernel.bias"
  "sao    low    sao.samples=8,sao.turns=3              sao.intensity,sao.bias"
  "sao    medium sao.samples=11,sao.turns=7             sao.intensity,sao.bias"
  "sao    high   sao.samples=24,sao.turns=7             sao.intensity,sao.bias"
  "sao    ultra  sao.samples=48,sao.turns=11            sao.intensity,sao.bias"
  "hbao   low    hbao.directions=4,hbao.steps=3         hbao.tangent_bias"
  "hbao   medium hbao.directions=6,hbao.steps=4         hbao.tangent_bias"
  "hbao   high   hbao.directions=8,hbao.steps=4         hbao.tangent_bias"
  "hbao   ultra  hbao.directions=8,hbao.steps=8         hbao.tangent_bias"
  "gtao   low    gtao.quality=low                       gtao.radius_multiplier,gtao.falloff_range,gtao.distribution_power"
  "gtao   medium gtao.quality=medium                    gtao.radius_multiplier,gtao.falloff_range,gtao.distribution_power"
  "gtao   high   gtao.quality=high                      gtao.radius_multiplier,gtao.falloff_range,gtao.distribution_power"
  "gtao   ultra  gtao.quality=ultra                     gtao.radius_multiplier,gtao.falloff_range,gtao.distribution_power"
  "vbao   low    vbao.slices=2,vbao.steps=4             vbao.thickness,vbao.distribution_power"
  "vbao   medium vbao.slices=2,vbao.steps=8             vbao.thickness,vbao.distribution_power"
  "vbao   high   vbao.slices=4,vbao.steps=8             vbao.thickness,vbao.distribution_power"
  "vbao   ultra  vbao.slices=4,vbao.steps=16            vbao.thickness,vbao.distribution_power"
)
for line in "${LEVELS[@]}"; do
  read -r tech level sets knobs <<<"$line"
  args=()
  for s in ${sets//,/ }; do args+=(--set "$s"); done
  for k in ${knobs//,/ }; do args+=(--knob "$k"); done
  echo "== $tech $level"
  "$BUILD/app/ssaolab" tune --technique "$tech" "${args[@]}" "${SCENE_ARGS[@]}" --views 4 --quiet \
    --out "$TMP/$tech-$level.json"
  # Keep what the preset is about: the technique, its rows, the radius rule and the denoiser.
  /usr/bin/python3 - "$TMP/$tech-$level.json" "assets/presets/$tech-$level.json" "$tech" "$level" <<'PY'
import json, sys
src, dst, tech, level = sys.argv[1:]
t = json.load(open(src))
# Rows that do nothing at a named quality level are left out (ssaolab warns about such keys).
if t[tech].get("quality", "custom") != "custom":
    t[tech] = {k: v for k, v in t[tech].items() if k not in ("slices", "steps")}
out = {"name": f"{tech}-{level}",
       "description": f"{tech} at {level} quality; " + t["description"].replace("ssaolab tune: ", "free parameters tuned by `ssaolab tune` (make presets): "),
       "ao": {k: t["ao"][k] for k in ("technique", "radius_mode", "radius_scene", "power")},
       tech: t[tech],
       "denoise": {"kind": t["denoise"]["kind"]},
       "scores": t["scores"]}
json.dump(out, open(dst, "w"), indent=2)
open(dst, "a").write("\n")
PY
  grep -o '"description": "[^"]*"' "assets/presets/$tech-$level.json"
done

# The presets derived from the tuned ones follow them (tests/cpu/test_params.cpp checks they do):
# vbao-half-LEVEL is vbao-LEVEL with the AO at half resolution; vbao-max is vbao-ultra's fitted rows
# at 8 slices x 24 steps. Only their vbao rows are rewritten; names and descriptions stay.
/usr/bin/python3 - <<'PY'
import json
def derive(src, dst, **override):
    rows = dict(json.load(open(f"assets/presets/{src}.json"))["vbao"], **override)
    path = f"assets/presets/{dst}.json"
    out = json.load(open(path))
    out["vbao"] = rows
    json.dump(out, open(path, "w"), indent=2)
    open(path, "a").write("\n")
    print(f"{dst}: the vbao rows of {src}" + (f" with {override}" if override else ""))
for level in ("low", "medium", "high", "ultra"):
    derive(f"vbao-{level}", f"vbao-half-{level}")
derive("vbao-ultra", "vbao-max", slices=8, steps=24)
PY
