#!/usr/bin/env bash
# libFuzzer with ASan+UBSan (clang) on the glTF loader, on every settings parser (preset and
# sweep JSON, --set, --camera, --size), on bench merge's shard reader (results.json) and on a user
# technique's file (NAME.ao.glsl: its header and its body's limits), and on the web engines' tuned
# settings reader and snippet writer. Builds build-fuzz/ and runs each target
# FUZZ_SECONDS (default 60: the test command's short run; for a long one, FUZZ_SECONDS=3600).
# Seeds: the committed corpus (tests/fuzz/seeds), the shared scenes' .gltf files and the shipped
# presets.
# A crash stops with the reproducer saved as build-fuzz/crash-*; it becomes a regression test.
# Usage: .ci/fuzz.sh [BUILD_DIR] [SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build-fuzz}
SCENES=${2:-../shared/scenes}
SECONDS_EACH=${FUZZ_SECONDS:-60}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DSSAOLAB_FUZZ=ON -DSSAOLAB_BUILD_TESTS=OFF >/dev/null
cmake --build "$BUILD" -j "$(nproc)" --target fuzz_gltf fuzz_settings fuzz_shard fuzz_user_header fuzz_engine

CORPUS="$BUILD/corpus"
mkdir -p "$CORPUS/gltf" "$CORPUS/settings" "$CORPUS/shard" "$CORPUS/user_header" "$CORPUS/engine"
rm -f "$BUILD"/crash-* "$BUILD"/leak-* "$BUILD"/timeout-* "$BUILD"/oom-*
cp tests/fuzz/seeds/gltf/* "$CORPUS/gltf/"
find "$SCENES" -name '*.gltf' -size -2M -exec cp {} "$CORPUS/gltf/" \; 2>/dev/null || true
cp tests/fuzz/seeds/settings/* "$CORPUS/settings/"
cp tests/fuzz/seeds/shard/* "$CORPUS/shard/"
cp tests/fuzz/seeds/user_header/* "$CORPUS/user_header/"
cp tests/fuzz/seeds/engine/* "$CORPUS/engine/"
for p in assets/presets/*.json; do
  { printf '\0'; cat "$p"; } > "$CORPUS/settings/preset_$(basename "$p" .json)"
done

export ASAN_OPTIONS=abort_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for target in fuzz_gltf fuzz_settings fuzz_shard fuzz_user_header fuzz_engine; do
  dir=$CORPUS/${target#fuzz_}
  echo "fuzz: $target for ${SECONDS_EACH}s on $(ls "$dir" | wc -l) seeds"
  (cd "$BUILD" && "./tests/fuzz/$target" -max_total_time="$SECONDS_EACH" -timeout=20 -rss_limit_mb=3072 \
     -print_final_stats=1 "corpus/${target#fuzz_}" 2>&1 | grep -E "stat::number_of_executed_units|stat::peak_rss|ERROR|SUMMARY|crash-|Done|what\(\)|terminate called| in ssao::" || true)
  found=$(find "$BUILD" -maxdepth 1 \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \))
  if [ -n "$found" ]; then
    echo "fuzz: $target found a failing input (reproduce: $BUILD/tests/fuzz/$target FILE):"
    echo "$found"
    exit 1
  fi
done
echo "fuzz: no crash, leak, timeout or out-of-memory"
