#!/usr/bin/env bash
# `make stress`: docs/stability.md, every technique under the stress cases (app/stress/) on the
# built-in showcase and two shared scenes at 320x180. Usage: .ci/stress.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
rc=0
"$BUILD/app/ssaolab" stress --quiet --out docs/stress \
  --scene builtin:showcase --scene "$SCENES/CornellBox/cornellBox.gltf" \
  --scene "$SCENES/2CylinderEngine/2CylinderEngine.gltf" || rc=$?
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
- Scale is invariant to RMSE ≤ 0.0035 from 1e-3 to 1e3 (the radius follows the scene).
- Translation holds to 1e5 units (RMSE ≤ 0.009); at 1e6 it reaches 0.02-0.03 for SAO, GTAO and the
  bitmask on the showcase: positions are stored as 32-bit floats, which at 1e6 are 1/16 unit apart
  (the showcase's radius is 0.86). Not yet fixed: it needs positions relative to a double-precision
  scene origin through the loader, the G-buffer and the reference.
- Fixed planes (in units of the scene's diagonal) from near 1e-6 to far 1e5 render finite AO. From
  near 1e-5 up the mean AO moves by under 0.002; at near 1e-6 (far/near 1e7) the 24/32-bit depth
  test loses surfaces and the mean AO drops by 0.01-0.04 (z-fighting). Reversed-Z with a float depth
  buffer is the known cure and not yet in. Planes with far/near above 1e8 are refused with a clear error (before, near 1e-9 and far 1e9
  rendered an empty frame reported as "fully occluded").

MD
  cat docs/stress/stability.md
} > docs/stability.md
echo "wrote docs/stability.md (stress exit code $rc)"
