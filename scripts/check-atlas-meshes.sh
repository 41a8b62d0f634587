#!/usr/bin/env bash
# make_atlas() on meshes that are not in this repository: every polygon file of CGAL's sample
# data (Debian package libcgal-demo) under 6 MB. Each goes through test_atlas, which checks the
# atlas independently (uv in the unit square, no flipped or flat triangle, no overlap by exact
# constructions, L2 <= 1.05) and prints its figures. From the root of the repository:
#   bash scripts/check-atlas-meshes.sh
# Writes benchmark/results/atlas_other_meshes.txt. Builds in build/bench.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh libcgal-demo
cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_TESTS=ON -DSMP_BUILD_EXAMPLES=OFF >/dev/null
cmake --build build/bench -j"$(nproc)" --target smp_tests
program="$(realpath build/bench/test/Stretch_minimizing_parameterization/smp_tests)"
dir=build/other-meshes
rm -rf "$dir" && mkdir -p "$dir"
tar xzf /usr/share/doc/libcgal-demo/data.tar.gz -C "$dir" --wildcards 'data/meshes/*'
out="$(pwd)/benchmark/results/atlas_other_meshes.txt"
{
  echo "# make_atlas() on CGAL's sample meshes, $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores"
  for f in "$dir"/data/meshes/*.{off,obj,ply,stl}; do
    [ -f "$f" ] && [ "$(stat -c %s "$f")" -lt 6000000 ] || continue
    (cd "$dir/data/meshes" && timeout 300 "$program" test_atlas "$(basename "$f")" 2>&1) | grep -v " passed, 0 failed" || true
  done
} > "$out"
echo "failed checks: $(grep -c 'check failed' "$out" || true)"
echo "wrote $out"
