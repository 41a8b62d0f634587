#!/usr/bin/env bash
# The remeshing's curvature adaptation: smp-remesh ({U0, Uopt}) with --curvature 0 (the surface
# sampled evenly), 1 and 4 at the same vertex count, and how close each new mesh stays to the
# input (mean and Hausdorff distance), with its angles. From the root of the repository:
#   bash scripts/compare-curvature-adaptation.sh [-n VERTICES] [-o RESULT.md] [MESH...]
# VERTICES defaults to 3000; the meshes to the bundled disk meshes of the remeshing comparison;
# RESULT.md to standard output only (with -o, also written there, whole or not at all).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
vertices=3000
result=
while getopts "n:o:" option; do
  case $option in
    n) vertices=$OPTARG ;;
    o) result=$OPTARG ;;
    *) echo "usage: bash scripts/compare-curvature-adaptation.sh [-n VERTICES] [-o RESULT.md] [MESH...]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
data=examples/Stretch_minimizing_parameterization/data
meshes=("$@")
[ ${#meshes[@]} -gt 0 ] || meshes=("$data/mannequin-devil.off" "$data/nefertiti.off" "$data/three_peaks.off"
  "$data/mushroom.off" "$data/holes.off" "$data/head.off" "$data/patch-01.off")
bash scripts/install-deps.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_TOOLS=ON > /dev/null
cmake --build build/release -j2 --target smp-remesh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
{
  echo "# Remeshing with the curvature adaptation ($vertices vertices, {U0, Uopt})"
  echo
  echo "\`bash scripts/compare-curvature-adaptation.sh -n $vertices\` on $(date -u +%Y-%m-%d), $(nproc) cores:"
  echo "\`smp-remesh MESH -n $vertices --curvature A\` for A = 0 (the surface sampled evenly), 1 and 4."
  echo "Distances: symmetric, over the input's bounding box diagonal (the mean: over both surfaces;"
  echo "the Hausdorff distance: one point's). Ratios: to A = 0's. Seconds: the remeshing's, wall clock."
  echo
  echo "| mesh | A | vertices | mean distance | ratio | Hausdorff | ratio | angles >= 30 (%) | smallest angle | wrong faces | seconds |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  for mesh in "${meshes[@]}"; do
    for a in 0 1 4; do
      build/release/tools/smp-remesh "$mesh" -n "$vertices" --curvature "$a" -q -o "$work/a$a.off" 2> /dev/null
    done
    python3 - "$work" "$(basename "$mesh")" <<'PY'
import json, sys
work, name = sys.argv[1], sys.argv[2]
runs = {a: json.load(open(f"{work}/a{a}.json")) for a in (0, 1, 4)}
base = runs[0]
for a, r in runs.items():
    mean, hausdorff = r["mean_distance_over_diagonal"], r["hausdorff_distance_over_diagonal"]
    print(f"| {name} | {a} | {r['vertices']} | {mean:.6f} | {mean / base['mean_distance_over_diagonal']:.3f} | "
          f"{hausdorff:.5f} | {hausdorff / base['hausdorff_distance_over_diagonal']:.3f} | "
          f"{100 * r['angles_at_least_30_degrees']:.2f} | {r['min_angle_degrees']:.1f} | {r['wrong_faces']} | "
          f"{r['seconds']['remeshing']:.2f} |")
PY
  done
} > "$work/result.md"
cat "$work/result.md"
if [ -n "$result" ]; then
  cp "$work/result.md" "$result.part"
  mv "$result.part" "$result"
fi
