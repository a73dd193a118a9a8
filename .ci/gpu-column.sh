#!/usr/bin/env bash
# `make gpu-column GPU_RUN=DIR [GPU_NOTE="..."]`: the GPU column of docs/benchmarks.md from the
# folder `.ci/gpu-run.sh` filled on a GPU machine (check.json, scaling.tgz, bench1..3.tgz, skips.tgz): merges
# the bench shards (`ssaolab bench merge`), writes docs/bench/gpu.md beside this page's llvmpipe run
# (.ci/gpu-column.py), then reassembles docs/benchmarks.md. No GPU needed here.
# Usage: .ci/gpu-column.sh BUILD_DIR GPU_RUN_DIR [NOTE] [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=$1 RUN=$2 NOTE=${3:-} SCENES=${4:-../shared/scenes}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$TMP/scaling"
tar xzf "$RUN/scaling.tgz" -C "$TMP/scaling"
mkdir -p "$TMP/skips"
[ -f "$RUN/skips.tgz" ] && tar xzf "$RUN/skips.tgz" -C "$TMP/skips"
shards=()
for f in "$RUN"/bench*.tgz; do tar xzf "$f" -C "$TMP"; done
for d in "$TMP"/shard-*; do shards+=("$d"); done
"$BUILD/app/ssaolab" bench merge "${shards[@]}" --out "$TMP/merged" >/dev/null
/usr/bin/python3 .ci/gpu-column.py "$TMP/merged" "$TMP/scaling" "$RUN/check.json" "$NOTE" docs/bench "$TMP/skips"
BENCH_REPORT_ONLY=1 bash .ci/bench.sh "$BUILD" "$SCENES"
