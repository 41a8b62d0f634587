#!/usr/bin/env bash
# Row (d) of the paper's tables, Sander et al. 2001's stretch minimization (re-implemented in
# benchmark/Stretch_minimizing_parameterization/Sander_line_search.h, capped at 300 s), beside
# U^0, the paper's U^opt, the package's lowest-stretch polish (the same energy, Newton steps) and
# CGAL's MVC, on the bundled disk meshes (up to 13k vertices), one run each (row (d) takes up to
# its cap per run): tables in benchmark/results/row_d/. scripts/benchmark.sh runs row (d) too,
# with the other methods, where its budget allows.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh
cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_BENCHMARK=ON -DSMP_BUILD_TESTS=OFF \
      -DSMP_BUILD_EXAMPLES=OFF > /dev/null
cmake --build build/bench -j2 --target benchmark_parameterizers
data=examples/Stretch_minimizing_parameterization/data
results=benchmark/results/row_d
rm -rf "$results"
mkdir -p "$results" build/bench/scratch
build/bench/benchmark/Stretch_minimizing_parameterization/benchmark_parameterizers --out "$results" --runs 1 \
  --budget 400 --hard-limit 900 --scratch build/bench/scratch \
  --methods d_sander,b_floater,f_uopt,lowest_polish,cgal_mvc \
  $data/nefertiti.off $data/mesh_with_border.off $data/patch-01.off $data/three_peaks.off $data/mushroom.off \
  $data/mannequin-devil.off 2>&1 | tee "$results/run.log"
echo "- load average at the end: $(cut -d ' ' -f 1-3 /proc/loadavg); git $(git rev-parse --short HEAD)" >> "$results/run.log"
