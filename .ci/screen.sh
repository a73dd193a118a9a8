#!/usr/bin/env bash
# `make screen`: what a depth buffer cannot see, on every shared scene at 640x360.
#  1. `ssaolab bench` of the baseline, each technique at its defaults and the tuned presets, every
#     error split against the screen-space oracle (technique = AO vs oracle, screen = oracle vs truth);
#  2. what each remedy could close at best: the oracle of each view with a 64 px guard band, with a
#     deep G-buffer's second layer, and with both, against the truth (`render --reference`).
# Writes docs/bench/screen.md and docs/bench/screen.json, then reassembles docs/benchmarks.md.
# Usage: .ci/screen.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
SIZE=${SCREEN_SIZE:-640x360}
RAYS=${SCREEN_RAYS:-128}
RUN="$BUILD/screen-run"
rm -rf "$RUN"
mkdir -p "$RUN"
LIST=(CornellBox/cornellBox.gltf 2CylinderEngine/2CylinderEngine.gltf SciFiHelmet/SciFiHelmet.gltf
      AntiqueCamera/AntiqueCamera.gltf FlightHelmet/FlightHelmet.gltf Lantern/Lantern.gltf
      ReciprocatingSaw/ReciprocatingSaw.gltf ShaderBall/shader_ball.gltf)
ARGS=()
for s in "${LIST[@]}"; do ARGS+=(--scene "$SCENES/$s"); done
"$BUILD/app/ssaolab" bench "${ARGS[@]}" --size "$SIZE" --views 2 --frames "${SCREEN_FRAMES:-3}" --warmup 1 \
  --reference-rays "$RAYS" --sweep assets/bench/sweep_screen.json --no-plot --quiet --out "$RUN/split"
for s in "${LIST[@]}"; do
  for v in "1 0" "1 64" "2 0" "2 64"; do
    read -r layers guard <<<"$v"
    out="$RUN/remedy/$(basename "$s" .gltf)_l${layers}_g${guard}"
    "$BUILD/app/ssaolab" render --scene "$SCENES/$s" --size "$SIZE" --preset vbao-high --reference \
      --reference-rays "$RAYS" --oracle-layers "$layers" --oracle-guard "$guard" --timing-frames 1 --quiet \
      --out "$out" > /dev/null
  done
done
/usr/bin/python3 - "$RUN" docs/bench <<'PY'
import json, os, sys
run, out = sys.argv[1:]
md = open(os.path.join(run, "split", "report.md")).read()
def section(title):
    at = md.find(title)
    end = md.find("\n### ", at + 10)
    return "" if at < 0 else md[at:end if end > 0 else len(md)].strip()
split, places = section("### What the screen cannot see"), section("### Where the error lives")
rows, data = [], {}
for d in sorted(os.listdir(os.path.join(run, "remedy"))):
    m = json.load(open(os.path.join(run, "remedy", d, "metrics.json")))
    scene, rest = d.rsplit("_l", 1)
    layers, guard = rest.split("_g")
    data.setdefault(scene, {})[(int(layers), int(guard))] = m["error_split"]["screen"]
lines = ["| scene | screen RMSE, 1 layer | + 64 px guard band | + 2nd layer | both | guard closes | 2nd layer closes | both close |",
         "|---|---:|---:|---:|---:|---:|---:|---:|"]
for scene, v in data.items():
    base = v[(1, 0)]["rmse"]
    cells = [v[k]["rmse"] for k in [(1, 0), (1, 64), (2, 0), (2, 64)]]
    closes = ["%.0f %%" % (100 * (base - c) / base) if base > 0 else "–" for c in cells[1:]]
    lines.append("| %s | %s | %s |" % (scene, " | ".join("%.4f" % c for c in cells), " | ".join(closes)))
json.dump({s: {"%d layer(s), %d px" % k: e["rmse"] for k, e in v.items()} for s, v in data.items()},
          open(os.path.join(out, "screen.json"), "w"), indent=1)
with open(os.path.join(out, "screen.md"), "w") as f:
    f.write(split + "\n\n" + (places + "\n\n" if places else ""))
    f.write("#### What each remedy could close at best\n\n"
            "The screen share (the oracle against the truth) when the oracle's G-buffer also holds a 64 px guard "
            "band beyond each edge, a deep G-buffer's second layer (the nearest surface at least a separation "
            "behind the first), or both: the most a technique given that buffer could gain, before its own "
            "error. Camera view of each scene, " + os.path.basename(run) + "; `render --reference --oracle-layers "
            "L --oracle-guard G`.\n\n")
    f.write("\n".join(lines) + "\n")
print("wrote docs/bench/screen.md")
PY
BENCH_REPORT_ONLY=1 bash .ci/bench.sh "$BUILD" "$SCENES"
