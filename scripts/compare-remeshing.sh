#!/usr/bin/env bash
# The paper's remeshing comparison: {U0}, {U0, U1} and {U0, Uopt} (remesh_with_parameterizations)
# and CGAL's isotropic_remeshing at the same vertex count, on the bundled disk meshes, written
# to benchmark/results/remeshing.md (the new meshes to build/bench/remeshing/):
#   bash scripts/compare-remeshing.sh [VERTICES]   (default 5000)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
vertices=${1:-5000}
bash scripts/install-deps.sh
cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_BENCHMARK=ON -DSMP_BUILD_TESTS=OFF \
      -DSMP_BUILD_EXAMPLES=OFF > /dev/null
cmake --build build/bench -j2 --target remeshing_comparison
data=examples/Stretch_minimizing_parameterization/data
mkdir -p build/bench/remeshing benchmark/results
{
  echo "# Remeshing with two parameterizations, and CGAL's isotropic remeshing ($vertices vertices)"
  echo
  echo "\`bash scripts/compare-remeshing.sh $vertices\` on $(date -u +%Y-%m-%d), $(nproc) cores."
  echo "Area variation: coefficient of variation of the 3D triangle areas (lower: more even sampling)."
  echo "Hausdorff and mean distance: symmetric, over the input's bounding box diagonal (the Hausdorff"
  echo "distance is one point's, where a part thinner than the edges is decided by where a vertex falls)."
  echo "Times in seconds, wall clock (the parameterizations use one thread per core); CGAL's isotropic"
  echo "remeshing: the last of its calls (its edge length is corrected from the count it gives)."
  echo
  build/bench/benchmark/Stretch_minimizing_parameterization/remeshing_comparison "$vertices" \
    $data/mannequin-devil.off $data/nefertiti.off $data/three_peaks.off $data/mushroom.off $data/holes.off \
    $data/head.off $data/patch-01.off --out build/bench/remeshing
} > benchmark/results/remeshing.md.part
mv benchmark/results/remeshing.md.part benchmark/results/remeshing.md
cat benchmark/results/remeshing.md
