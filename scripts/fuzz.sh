#!/usr/bin/env bash
# Builds the libFuzzer harness (clang-14, ASan + UBSan) in build/fuzz and runs it for SECONDS
# (default 120; developers run it for hours: `bash scripts/fuzz.sh 3600`), on JOBS processes
# (default 1), with the random seed SEED (default 0: a new one each run), for at most RUNS
# inputs (default 0: no bound). With RUNS, one job starts from an empty corpus of its own: CI
# runs `bash scripts/fuzz.sh 600 1 SEED RUNS`, the same amount of fuzzing on a slow machine as
# on a fast one. (Not the same inputs: the coverage that steers the mutations varies from run
# to run, so a finding is printed, below.) Inputs to
# start from: the small bundled meshes and test/.../fuzz/seeds, made into inputs of each target
# (fuzz_smp.cpp: the first byte chooses the target), and the inputs of earlier findings as they
# were (test/.../fuzz/regressions), run first every time. Without RUNS the corpus grows in
# build/fuzz/corpus across runs. A finding is written to build/fuzz/findings/ and fails the
# script, which prints it in base64: reproduce it with
# `build/fuzz/test/Stretch_minimizing_parameterization/fuzz/fuzz_smp FILE`, then make it a test.
# `bash scripts/fuzz.sh --build-only` builds the harness and stops (CI builds it while the
# sanitizer stage runs).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build_only=false
if [ "${1:-}" = --build-only ]; then build_only=true; shift; fi
seconds=${1:-120}
jobs=${2:-1}
seed=${3:-0} # 0: libFuzzer draws one
runs=${4:-0}

bash scripts/install-deps.sh clang-14 libclang-rt-14-dev

cmake -S . -B build/fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only" -DSMP_BUILD_FUZZERS=ON -DSMP_BUILD_TESTS=OFF -DSMP_BUILD_EXAMPLES=OFF
cmake --build build/fuzz -j2 --target fuzz_smp
$build_only && exit 0

seeds=build/fuzz/seeds
corpus=build/fuzz/corpus
if [ "$runs" -gt 0 ]; then
  corpus=build/fuzz/corpus-counted
  rm -rf "$corpus"
fi
mkdir -p "$seeds" "$corpus" build/fuzz/findings
prefix() { printf "\\x$(printf %02x "$1")\\x$(printf %02x "$2")"; }
for f in test/Stretch_minimizing_parameterization/fuzz/seeds/* \
         examples/Stretch_minimizing_parameterization/data/{nefertiti,pig}.off; do
  case "${f##*.}" in off) e=0 ;; obj) e=1 ;; ply) e=2 ;; stl) e=3 ;; *) continue ;; esac
  { prefix 0 $e; cat "$f"; } > "$seeds/reader-$(basename "$f")"
done
# soups: a few fixed byte strings for targets 1 (atlas), 2 (parameterizer) and 3 (remeshing)
for t in 1 2 3; do
  for s in 1 2 3; do
    { printf "\\x$(printf %02x $t)"; head -c 600 /dev/zero | tr '\0' "\\$(printf %03o $((s * 37)))"; } > "$seeds/soup-$t-$s"
  done
done

parallel=()
[ "$jobs" -gt 1 ] && parallel=(-jobs="$jobs" -workers="$jobs")
counted=()
[ "$runs" -gt 0 ] && counted=(-runs="$runs")
# allocator_may_return_null: an allocation too large throws std::bad_alloc, as without ASan
status=0
touch build/fuzz/run-started
ASAN_OPTIONS=allocator_may_return_null=1:detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  build/fuzz/test/Stretch_minimizing_parameterization/fuzz/fuzz_smp "$corpus" "$seeds" test/Stretch_minimizing_parameterization/fuzz/regressions -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 \
  -max_len=65536 -artifact_prefix=build/fuzz/findings/ -print_final_stats=1 -seed="$seed" "${parallel[@]}" "${counted[@]}" || status=$?
# a finding is printed last, so that a run on a machine that is gone (CI) can be reproduced:
# `base64 -d > FILE` of the line
if [ "$status" -ne 0 ]; then
  for f in $(find build/fuzz/findings -type f -newer build/fuzz/run-started); do
    echo "fuzz: finding $(basename "$f"), $(stat -c %s "$f") bytes, in base64:"
    base64 -w0 "$f"
    echo
  done
fi
exit "$status"
