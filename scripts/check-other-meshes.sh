#!/usr/bin/env bash
# The options beyond the paper on meshes that are not in this repository: CGAL's sample meshes
# (Debian package libcgal-demo), every one of them that is a triangulated disk, except the ones
# bundled here. From the root of the repository:
#   bash scripts/check-other-meshes.sh
# Writes benchmark/results/other_meshes.md (one row per mesh; times are medians of at least 5
# rounds calling each method once, 1 above 20k vertices, more until 0.3 s, at most 201). Builds in
# build/bench, extracts the meshes in build/other-meshes.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh libcgal-demo
cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_BENCHMARK=ON \
      -DSMP_BUILD_TESTS=OFF -DSMP_BUILD_EXAMPLES=OFF >/dev/null
cmake --build build/bench -j"$(nproc)" --target other_meshes

dir=build/other-meshes
rm -rf "$dir" && mkdir -p "$dir"
tar xzf /usr/share/doc/libcgal-demo/data.tar.gz -C "$dir" --wildcards 'data/meshes/*.off'
bundled=$(ls examples/Stretch_minimizing_parameterization/data)
meshes=()
for f in "$dir"/data/meshes/*.off; do
  grep -qxF "$(basename "$f")" <<<"$bundled" && continue
  [ "$(stat -c %s "$f")" -lt 5000000 ] && meshes+=("$(realpath "$f")")
done
program="$(realpath build/bench/benchmark/Stretch_minimizing_parameterization/other_meshes)"
out="$(pwd)/benchmark/results/other_meshes.md"
{
  echo "# Meshes not in the repository"
  echo
  echo "Made by \`bash scripts/check-other-meshes.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores:"
  echo "the disk-like meshes among CGAL's sample meshes (libcgal-demo's data.tar.gz), the bundled ones left out."
  echo "Normalized L2 stretch, unit-square arc-length border; times are ratios of medians measured side by side."
  echo
  (cd "$dir" && "$program" "${meshes[@]}")
} > "$out"
cat "$out"
