#!/usr/bin/env bash
# Reruns the benchmark of the parameterizers from scratch, from the root of the repository:
#   bash scripts/benchmark.sh
# Installs what is missing (Debian 12 packages, gnuplot-nox), builds benchmark_parameterizers
# in build/bench, runs it on every bundled disk mesh and on mannequin-devil.off refined 1, 2 and
# 3 times by Loop subdivision (made at run time), and writes benchmark/results/: one markdown
# table per mesh (<mesh>.md, all in tables.md), summary.md (the ratios to quote), results.csv
# and history.csv (all figures), machine.md, run.log and the PNG plots.
#
# Environment (all optional):
#   SMP_BENCH_BUDGET=300       skip a method on a mesh when its predicted time exceeds this (s)
#   SMP_BENCH_HARD_LIMIT=900   kill a run that takes longer than this (s)
#   SMP_BENCH_MAX_LOOP=3       refine mannequin-devil up to this many times (4: 3.3M vertices,
#                              6.6M faces, about 6.5 GB and minutes per method)
#   SMP_BENCH_METHODS=a,b      only these methods (ids: benchmark_parameterizers --list)
#   SMP_BENCH_MESHES="A B"     these meshes instead (paths; FILE@loopN: refined N times at run
#                              time), e.g. examples/.../data/mech-holes-shark.off@loop5 (10.4M faces)
#   SMP_BENCH_BUILD_DIR=build/bench   SMP_BENCH_RESULTS=benchmark/results
#   SMP_BENCH_SUITESPARSE=ON   OFF: build without SuiteSparse (Eigen's solvers only, as a program
#                              that includes the headers and links nothing else gets them)
# Nothing is written outside the build directory and the results directory.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
build="${SMP_BENCH_BUILD_DIR:-build/bench}"
results="${SMP_BENCH_RESULTS:-benchmark/results}"
budget="${SMP_BENCH_BUDGET:-300}"
hard_limit="${SMP_BENCH_HARD_LIMIT:-900}"
max_loop="${SMP_BENCH_MAX_LOOP:-3}"
data="examples/Stretch_minimizing_parameterization/data"
start_seconds=$(date +%s)

# --- what is needed -----------------------------------------------------------------------
bash scripts/install-deps.sh gnuplot-nox

# --- build --------------------------------------------------------------------------------
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_BENCHMARK=ON \
      -DSMP_BUILD_TESTS=OFF -DSMP_BUILD_EXAMPLES=OFF -DSMP_WITH_UMFPACK="${SMP_BENCH_SUITESPARSE:-ON}" >/dev/null
cmake --build "$build" -j"$(nproc)" --target benchmark_parameterizers
program="$build/benchmark/Stretch_minimizing_parameterization/benchmark_parameterizers"

# --- results directory: only the files written here are replaced ---------------------------
mkdir -p "$results"
# (other_meshes.md is written by check-other-meshes.sh and kept)
find "$results" -maxdepth 1 -type f \( -name '*.md' -o -name '*.csv' -o -name '*.dat' -o -name '*.png' \
     -o -name run.log \) ! -name other_meshes.md -delete

# --- the machine --------------------------------------------------------------------------
cache="$build/CMakeCache.txt"
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$cache" | head -n 1; }
compiler="$(cache_value CMAKE_CXX_COMPILER)"
{
  echo "# Machine"
  echo
  echo "- date: $(date -u '+%Y-%m-%d %H:%M:%S UTC')"
  echo "- nproc: $(nproc)"
  echo "- CPU: $(lscpu | sed -n 's/^Model name: *//p' | head -n 1)"
  echo "- memory: $(awk '/^MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo)"
  echo "- kernel: $(uname -sr)"
  echo "- compiler: $compiler, $("$compiler" --version | head -n 1)"
  echo "- build type: $(cache_value CMAKE_BUILD_TYPE), flags: $(cache_value CMAKE_CXX_FLAGS_RELEASE)"
  echo "- CGAL: $(sed -n "s/^#define CGAL_VERSION  *//p" /usr/include/CGAL/version.h)" \
       "(Debian libcgal-dev $(dpkg-query -W -f='${Version}' libcgal-dev 2>/dev/null || echo '?'))"
  echo "- Eigen: $(awk '/#define EIGEN_(WORLD|MAJOR|MINOR)_VERSION/ {v = v (v ? "." : "") $3} END {print v}' \
       /usr/include/eigen3/Eigen/src/Core/util/Macros.h)" \
       "(Debian libeigen3-dev $(dpkg-query -W -f='${Version}' libeigen3-dev 2>/dev/null || echo '?'))"
  echo "- gnuplot: $(gnuplot --version)"
  echo "- source: git $(git rev-parse --short HEAD 2>/dev/null || echo '?')$(git diff --quiet HEAD -- include benchmark/Stretch_minimizing_parameterization scripts cmake CMakeLists.txt 2>/dev/null || echo ' (with uncommitted changes)')"
  echo "- load average at the start: $(cut -d ' ' -f 1-3 /proc/loadavg)"
} > "$results/machine.md"

# --- run ----------------------------------------------------------------------------------
meshes=(
  "$data/nefertiti.off"
  "$data/mesh_with_border.off"
  "$data/patch-01.off"
  "$data/three_peaks.off"
  "$data/mushroom.off"
  "$data/mannequin-devil.off"
)
for ((level = 1; level <= max_loop; ++level)); do
  meshes+=("$data/mannequin-devil.off@loop$level")
done
if [ -n "${SMP_BENCH_MESHES:-}" ]; then
  read -r -a meshes <<< "$SMP_BENCH_MESHES"
fi
options=(--out "$results" --budget "$budget" --hard-limit "$hard_limit" --scratch "$build/scratch")
if [ -n "${SMP_BENCH_METHODS:-}" ]; then
  options+=(--methods "$SMP_BENCH_METHODS")
fi

"$program" "${options[@]}" "${meshes[@]}" 2>&1 | tee "$results/run.log"
rm -rf "$build/scratch"

# --- plots --------------------------------------------------------------------------------
gnuplot -e "dir='$results'" benchmark/Stretch_minimizing_parameterization/plots.gp 2>>"$results/run.log"

elapsed=$(( $(date +%s) - start_seconds ))
{
  echo "- load average at the end: $(cut -d ' ' -f 1-3 /proc/loadavg)"
  echo "- the whole of scripts/benchmark.sh took $((elapsed / 60)) min $((elapsed % 60)) s"
  echo "- command: bash scripts/benchmark.sh (budget ${budget} s, hard limit ${hard_limit} s, ${SMP_BENCH_MESHES:-Loop levels up to ${max_loop}}, SuiteSparse ${SMP_BENCH_SUITESPARSE:-ON}${SMP_BENCH_METHODS:+, methods $SMP_BENCH_METHODS})"
} >> "$results/machine.md"

# an index
{
  echo "# Benchmark results"
  echo
  echo "Made by \`bash scripts/benchmark.sh\`. Files: [summary.md](summary.md) (ratios to quote),"
  echo "[tables.md](tables.md) (one table per mesh), [results.csv](results.csv) (every figure),"
  echo "[history.csv](history.csv) (L2 stretch of every step U^h), [machine.md](machine.md), run.log."
  echo
  cat "$results/machine.md" | sed '1s/^# /## /'
  echo
  echo "![time](time_vs_vertices.png)"
  echo "![memory](memory_vs_vertices.png)"
  echo "![stretch, eta = 1](stretch_vs_step_f_uopt.png)"
  echo "![stretch, eta = 0.5](stretch_vs_step_uopt_eta05.png)"
} > "$results/README.md"

echo "benchmark: results in $results ($((elapsed / 60)) min $((elapsed % 60)) s)" >&2
