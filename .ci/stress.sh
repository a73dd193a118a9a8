#!/usr/bin/env bash
# `make stress`: docs/stability.md, every technique under the stress cases (app/commands/stress/) on the
# built-in showcase and two shared scenes at 320x180. Usage: .ci/stress.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
rc=0
# STRESS_REPORT_ONLY=1: reassemble docs/stability.md from the last run's files without rendering.
if [ -z "${STRESS_REPORT_ONLY:-}" ]; then
"$BUILD/app/ssaolab" stress --quiet --out docs/stress \
  --scene builtin:showcase --scene "$SCENES/CornellBox/cornellBox.gltf" \
  --scene "$SCENES/2CylinderEngine/2CylinderEngine.gltf" || rc=$?
fi
{
  cat <<'MD'
# Numerical stability: `ssaolab stress`

Regenerate with `make stress` (it runs `.ci/stress.sh`; under a minute on llvmpipe). Every
technique at its defaults is rendered under each case below and checked: no NaN or infinity
anywhere in `ao.raw` or `ao.denoised`, every value in [0, 1]; where AO must not change (the whole
scene and its radius scaled by 1e-3..1e3; the scene moved 1e3..1e6 units from the origin) the RMSE
of `ao.denoised` against the benign render is given, in bold above the stated tolerance (0.02).
Cases a guard refuses (a depth range the depth buffer cannot resolve) are listed with the
one-line error the user sees. Raw rows: [stress/stress.json](stress/stress.json).

What it found and what was done:
- No case produces a non-finite or out-of-range value (after the denoisers' clamp at 1: the
  gaussian summed ones to 1.0000001-1.0000004 before).
- Scale is invariant to RMSE ≤ 0.0051 from 1e-3 to 1e3 (the radius follows the scene).
- Translation is exact to 1e7 units (RMSE 0.0000): positions are stored relative to a
  double-precision scene origin (renderer/scene/scene.h), so a scene far from the file's origin
  keeps full float precision. The rows "float positions (no scene origin)" show what that saves:
  RMSE 0.0051 at 1e5 and 0.0277 at 1e6, where 32-bit floats are 1/16 unit apart (the showcase's
  radius is 0.86).
- Clip planes (in units of the scene's diagonal) from near 1e-6 to far 1e5, in both depth
  mappings. A standard depth buffer loses surfaces as near shrinks: RMSE against the fitted planes
  0.024 at near 1e-4, 0.19 at 1e-5 and 0.24 at 1e-6 (2CylinderEngine, the bitmask: z-fighting
  between its fins), and past far/near 1e8 the camera check refuses it with a clear error
  (before, near 1e-9 and far 1e9 rendered an empty frame reported as "fully occluded").
  Reversed-Z with a float depth buffer (the default, `--depth reversed`) stays within RMSE 0.003
  at every ratio up to 1e11 (exactly 0 at near 1e-5 and 1e-6) and with an infinite far plane:
  the robust choice is the default. A far plane of one diagonal clips CornellBox (its camera stands
  farther away) and changes its AO in either mapping, as it should.
- An orthographic camera (`--projection orthographic`) renders finite, in-range AO for every
  technique in both depth mappings, also with near at 1e-6 diagonals.
- Geometry: degenerate triangles (10 % more, zero area) and normals scaled by 1e-6 or 1e6 change
  nothing (RMSE 0.0000); every third normal zero falls back to the face's normal (RMSE 0.0026).
  A camera on a surface, inside the scene or grazing the floor renders finite AO.

MD
  cat docs/stress/stability.md
} > docs/stability.md
echo "wrote docs/stability.md (stress exit code $rc)"
