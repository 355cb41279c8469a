#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fuzzes one of litkit's readers with libFuzzer under ASan and UBSan for a
# bounded time, starting from every file of its kind in the tree:
#   scene  the scene loader (fuzz/fuzz_scene.cpp), seeds: every .toml file
#   obj    the OBJ reader and the normals of what it reads
#          (fuzz/fuzz_obj.cpp), seeds: every .obj file
#   ply, stl, gltf  the PLY, STL and glTF readers (fuzz/fuzz_mesh.cpp, one
#          target each), seeds: the tree's files of that format
#
#   scripts/fuzz.sh [SECONDS] [scene|obj|ply|stl|gltf]      default 60 scene
#
# Prints how many inputs ran. Exits non-zero when the fuzzer found a crash,
# a sanitizer report, a leak, a timeout or an out-of-memory; the input that
# did it is kept in build-fuzz/artifacts-TARGET/ and printed. To replay one:
#   build-fuzz/fuzz/fuzz_scene build-fuzz/artifacts-scene/crash-…
# LITKIT_FUZZ_FLAGS adds libFuzzer options (docs/reliability.md: the
# campaign's -runs=10000000 beside the time); LITKIT_FUZZ_CORPUS keeps the
# corpus in a folder of one's own (below).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
target=${2:-scene}
case "$seconds" in
  '' | *[!0-9]*) echo "usage: $0 [SECONDS] [scene|obj|ply|stl|gltf]" >&2; exit 2 ;;
esac
case "$target" in
  scene | obj | ply | stl | gltf) ;;
  *) echo "usage: $0 [SECONDS] [scene|obj|ply|stl|gltf]" >&2; exit 2 ;;
esac
./scripts/install-deps.sh --fuzz

build=build-fuzz
# Tests are not built here: the instrumented tree exists for the fuzzer only.
# LITKIT_WERROR=ON in the environment (.ci/run sets it): warnings are errors.
werror=()
[ -z "${LITKIT_WERROR:-}" ] || werror=("-DLITKIT_WERROR=$LITKIT_WERROR")
CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLITKIT_FUZZ=ON -DLITKIT_BUILD_TESTS=OFF "${werror[@]}" > /dev/null
cmake --build "$build" -j "$(nproc)" --target "fuzz_$target"

# A scratch corpus, new each run: the seeds, then what the fuzzer adds. With
# LITKIT_FUZZ_CORPUS=FOLDER, that folder instead, kept and added to (so that a
# long campaign can go on where an earlier run stopped).
corpus="${LITKIT_FUZZ_CORPUS:-$build/corpus-$target}"
artifacts="$build/artifacts-$target"
[ -n "${LITKIT_FUZZ_CORPUS:-}" ] || rm -rf "$corpus"
rm -rf "$artifacts"
mkdir -p "$corpus" "$artifacts"
shopt -s globstar nullglob
seeds=0
case "$target" in
  scene) seed_files=(examples/**/*.toml tests/bad/**/*.toml tests/data/**/*.toml fuzz/seeds/*.toml) ;;
  obj) seed_files=(examples/**/*.obj tests/**/*.obj fuzz/seeds/*.obj) ;;
  ply) seed_files=(examples/**/*.ply tests/data/ply/* fuzz/seeds/ply/*) ;;
  stl) seed_files=(examples/**/*.stl tests/data/stl/* fuzz/seeds/stl/*) ;;
  gltf) seed_files=(examples/**/*.gltf tests/data/gltf/* fuzz/seeds/gltf/*) ;;
esac
dict=()
[ -f "fuzz/$target.dict" ] && dict=(-dict="fuzz/$target.dict")
for seed in "${seed_files[@]}"; do
  cp "$seed" "$corpus/${seed//\//_}"
  seeds=$((seeds + 1))
done
shopt -u globstar nullglob
echo "fuzz: $target: $seeds seed files; running for $seconds s"

log="$build/fuzz-$target.log"
export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
# shellcheck disable=SC2086 # LITKIT_FUZZ_FLAGS: several words
"$build/fuzz/fuzz_$target" -max_total_time="$seconds" -max_len=8192 -timeout=10 \
  -rss_limit_mb=4096 "${dict[@]}" -artifact_prefix="$artifacts/" \
  -print_final_stats=1 ${LITKIT_FUZZ_FLAGS:-} "$corpus" > "$log" 2>&1 || status=$?

# The full log is long (a line per new coverage); show the summary.
grep -E '^(INFO: Seed|INFO: Loaded|INFO: +[0-9]+ files found)|INITED|^Done [0-9]+ runs|^stat::' "$log" || true
# The coverage reached: the last status line ("#RUNS ... cov: EDGES ft: FEATURES corp: ...").
grep -E '^#[0-9]+.* cov: ' "$log" | tail -n 1 || true
if [ "$status" -ne 0 ]; then
  echo "fuzz: FAILED (libFuzzer exit $status); the end of $log:"
  tail -n 80 "$log"
  shopt -s nullglob
  for artifact in "$artifacts"/*; do
    echo "fuzz: input that failed, $artifact ($(wc -c < "$artifact") bytes), as hex:"
    od -A d -t x1z -v "$artifact" | head -n 64
  done
  exit 1
fi
runs=$(grep -oE '^Done [0-9]+ runs in [0-9]+ second\(s\)' "$log" | tail -n 1 || true)
echo "fuzz: $target: ok: ${runs:-?}, nothing found; corpus grew to $(find "$corpus" -type f | wc -l) files"
