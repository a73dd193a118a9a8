#!/usr/bin/env bash
# `make presets`: fits every technique's free parameters at each quality level with `ssaolab tune`
# on four of the shared scenes (even viewpoints train, odd ones are held out) and judges them on the
# other four (never fitted on), then writes the shipped presets assets/presets/TECHNIQUE-LEVEL.json
# with both scores. R stays the reference's 5 % of the diagonal and power 1: only the technique's own
# float rows are fitted (a larger radius or a darkening power would fit the numbers, not the
# physics), then rewrites the presets derived from them. The techniques, their levels and the rows
# fitted come from `ssaolab techniques` (each technique's registration), so a new one needs no edit here.
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

# One line per quality level, "ID LEVEL KEY=VALUE,... ROW,...": the rows that set the level and the
# rows tune fits, from each technique's registration (TechniqueInfo::levels and tuned).
mapfile -t LEVELS < <("$BUILD/app/ssaolab" techniques --levels)
[ "${#LEVELS[@]}" -gt 0 ] || { echo "tune-presets: no quality levels from $BUILD/app/ssaolab" >&2; exit 1; }
for line in "${LEVELS[@]}"; do
  read -r tech level sets knobs <<<"$line"
  args=()
  [ "$sets" = - ] || for s in ${sets//,/ }; do args+=(--set "$s"); done
  [ "$knobs" = - ] || for k in ${knobs//,/ }; do args+=(--knob "$k"); done
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
# each takes its technique's rows from the tuned preset it follows, with its own rows over them
# (TechniqueInfo::derived, `ssaolab techniques --derived`: "ID NAME FROM KEY=VALUE,..."). Only those
# rows are rewritten; names, descriptions and the other keys stay.
/usr/bin/python3 - "$("$BUILD/app/ssaolab" techniques --derived)" <<'PY'
import json, sys
def value(text):
    try:
        return json.loads(text)
    except ValueError:
        return text
for line in sys.argv[1].splitlines():
    tech, dst, src, sets = line.split()
    override = {} if sets == "-" else {k.split(".", 1)[1]: value(v) for k, v in (a.split("=", 1) for a in sets.split(","))}
    rows = dict(json.load(open(f"assets/presets/{src}.json"))[tech], **override)
    path = f"assets/presets/{dst}.json"
    out = json.load(open(path))
    out[tech] = rows
    json.dump(out, open(path, "w"), indent=2)
    open(path, "a").write("\n")
    print(f"{dst}: the {tech} rows of {src}" + (f" with {override}" if override else ""))
PY
