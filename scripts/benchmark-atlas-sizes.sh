#!/usr/bin/env bash
# make_atlas() on the bundled meshes and their Loop refinements up to about a million faces:
# time per stage, charts, L2, seams, utilization and peak memory, one row per size, written to
# benchmark/results/atlas_sizes.md. From the root of the repository:
#   bash scripts/benchmark-atlas-sizes.sh [MAX_FACES (default 1100000)]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

max="${1:-1100000}"
bash scripts/install-deps.sh
cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_BENCHMARK=ON -DSMP_BUILD_TESTS=OFF \
      -DSMP_BUILD_EXAMPLES=OFF >/dev/null
cmake --build build/bench -j"$(nproc)" --target atlas_sizes
data=examples/Stretch_minimizing_parameterization/data
out=benchmark/results/atlas_sizes.md
{
  echo "# make_atlas() on the bundled meshes and their Loop refinements"
  echo
  echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average at the start $(cut -d ' ' -f 1-3 /proc/loadavg);"
  echo "default options (all cores); peak MiB: the process's peak resident memory so far."
  echo "\`bash scripts/benchmark-atlas-sizes.sh $max\` on commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)."
  echo
  echo "| mesh | faces | charts | L2 | seams % | utilization | cut s | flatten s | pack s | total s | peak MiB |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  for mesh in three_peaks holes mannequin-devil bear; do # one process each: its own peak memory
    build/bench/benchmark/Stretch_minimizing_parameterization/atlas_sizes "$max" "$data/$mesh.off"
  done
} > "$out.part"
mv "$out.part" "$out"
echo "wrote $out"
