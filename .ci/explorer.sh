#!/usr/bin/env bash
# `make explorer`: the explorer's still, drag and idle frame times through its real UI
# (tests/bench/bench_explorer.cpp) on the shared scenes, the start preset against the learnopengl
# baseline in the same run, in the grid it opens in and in the single view, and the
# half-resolution preset in the grid; writes
# docs/bench/explorer.md, then reassembles docs/benchmarks.md.
# Usage: .ci/explorer.sh BUILD_DIR [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SCENES=${2:-../shared/scenes}
OUT=docs/bench/explorer.md
cmake --build "$BUILD" --target bench_explorer -j 2 >/dev/null
{
  echo "Grid (the view the explorer opens in), the reference tracing in the background as when the app opens:"
  echo
  "$BUILD/tests/bench_explorer"
  echo
  echo "Single view (the composite enlarged), the reference off:"
  echo
  "$BUILD/tests/bench_explorer" --single --no-reference
  echo
  echo "Grid as above, the half-resolution preset vbao-half-medium in place of the start preset (a point"
  echo "of the front):"
  echo
  "$BUILD/tests/bench_explorer" --preset vbao-half-medium
} > "$OUT.tmp"
mv "$OUT.tmp" "$OUT"
echo "wrote $OUT"
BENCH_REPORT_ONLY=1 bash .ci/bench.sh "$BUILD" "$SCENES"
