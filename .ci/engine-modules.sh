#!/usr/bin/env bash
# `make engine-modules` (and so `make test`): the web engines' npm packages - three.js, N8AO,
# postprocessing, Babylon.js (babylonjs, babylonjs-loaders), PlayCanvas and playwright-core, at the versions tools/peers/package-lock.json pins - in
# BUILD/peers/node_modules, by `npm ci` from the lock, once per lock (the folder .ci/peers.sh uses).
# `ssaolab tune --engine` runs them; tests/cli/test_cli_engines.cpp checks their defaults and runs one.
# Usage: .ci/engine-modules.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
MODS="$BUILD/peers"
for tool in node npm; do
  command -v "$tool" >/dev/null || { echo "engine-modules: $tool not found (make deps installs Node.js with npm)" >&2; exit 1; }
done
if cmp -s tools/peers/package-lock.json "$MODS/package-lock.json" && [ -f "$MODS/node_modules/three/package.json" ] &&
   [ -f "$MODS/node_modules/n8ao/package.json" ] && [ -f "$MODS/node_modules/playwright-core/package.json" ] &&
   [ -f "$MODS/node_modules/babylonjs/package.json" ] && [ -f "$MODS/node_modules/playcanvas/package.json" ]; then
  exit 0
fi
rm -rf "$MODS" && mkdir -p "$MODS"
cp tools/peers/package.json tools/peers/package-lock.json "$MODS/"
(cd "$MODS" && npm ci --ignore-scripts --no-audit --no-fund >/dev/null) # no package needs its install scripts
echo "engine-modules: the pinned npm packages installed in $MODS/node_modules"
