#!/usr/bin/env bash
# Fuzzes the scene loader (fuzz/fuzz_scene.cpp), or one mesh reader
# (fuzz/fuzz_mesh.cpp), with libFuzzer under ASan and UBSan for a bounded
# time, starting from every file of its kind in the tree.
#
#   scripts/fuzz.sh [SECONDS] [TARGET]   default 60 s, fuzz_scene; TARGET one
#                                        of fuzz_scene, fuzz_ply, fuzz_stl,
#                                        fuzz_gltf
#
# Prints how many inputs ran. Exits non-zero when the fuzzer found a crash,
# a sanitizer report, a leak, a timeout or an out-of-memory; the input that
# did it is kept in build-fuzz/artifacts/ and printed. To replay one:
#   build-fuzz/fuzz/TARGET build-fuzz/artifacts/crash-…
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
target=${2:-fuzz_scene}
case "$seconds" in
  '' | *[!0-9]*) echo "usage: $0 [SECONDS] [TARGET]" >&2; exit 2 ;;
esac
case "$target" in
  fuzz_scene | fuzz_ply | fuzz_stl | fuzz_gltf) ;;
  *) echo "usage: $0 [SECONDS] [fuzz_scene|fuzz_ply|fuzz_stl|fuzz_gltf]" >&2; exit 2 ;;
esac
./scripts/install-deps.sh --fuzz

build=build-fuzz
# Tests are not built here: the instrumented tree exists for the fuzzer only.
CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLITKIT_FUZZ=ON -DLITKIT_BUILD_TESTS=OFF > /dev/null
cmake --build "$build" -j "$(nproc)" --target "$target"

# A scratch corpus, new each run: the seeds, then what the fuzzer adds.
corpus="$build/corpus"
artifacts="$build/artifacts"
rm -rf "$corpus" "$artifacts"
mkdir -p "$corpus" "$artifacts"
shopt -s globstar nullglob
seeds=0
case "$target" in
  fuzz_scene) seed_files=(examples/**/*.toml tests/bad/**/*.toml tests/data/**/*.toml fuzz/seeds/*.toml) ;;
  fuzz_ply) seed_files=(examples/**/*.ply tests/data/ply/* fuzz/seeds/ply/*) ;;
  fuzz_stl) seed_files=(examples/**/*.stl tests/data/stl/* fuzz/seeds/stl/*) ;;
  fuzz_gltf) seed_files=(examples/**/*.gltf tests/data/gltf/* fuzz/seeds/gltf/*) ;;
esac
dict=()
[ "$target" = fuzz_scene ] && dict=(-dict=fuzz/scene.dict)
for seed in "${seed_files[@]}"; do
  cp "$seed" "$corpus/${seed//\//_}"
  seeds=$((seeds + 1))
done
shopt -u globstar nullglob
echo "fuzz: $seeds seed files; running for $seconds s"

log="$build/fuzz.log"
export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
"$build/fuzz/$target" -max_total_time="$seconds" -max_len=8192 -timeout=10 \
  -rss_limit_mb=4096 "${dict[@]}" -artifact_prefix="$artifacts/" \
  -print_final_stats=1 "$corpus" > "$log" 2>&1 || status=$?

# The full log is long (a line per new coverage); show the summary.
grep -E '^(INFO: Seed|INFO: Loaded|INFO: +[0-9]+ files found)|INITED|^Done [0-9]+ runs|^stat::' "$log" || true
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
echo "fuzz: ok: ${runs:-?}, nothing found; corpus grew to $(find "$corpus" -type f | wc -l) files"
