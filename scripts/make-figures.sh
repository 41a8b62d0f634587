#!/usr/bin/env bash
# Makes the pictures of the README and the manual with the project's own tools: the mannequin
# head at U^0, U^1 and U^opt (checkerboard, three-quarter view) and the uv layout of U^opt
# coloured by stretch, and the head remeshed with {U^0}, {U^0, U^1} and {U^0, U^opt} (the
# paper's figure 10) and with its curvature adaptation, into doc/Stretch_minimizing_parameterization/fig/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_TOOLS=ON > /dev/null
cmake --build build/release -j2 --target smp-parameterize smp-remesh

fig=doc/Stretch_minimizing_parameterization/fig
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$fig"
mesh=examples/Stretch_minimizing_parameterization/data/mannequin-devil.off
# name, then the tool's options: the paper's U^0, U^1, U^opt, and U^opt polished with a free border
while read -r name options; do
  build/release/tools/smp-parameterize "$mesh" $options -q --size 400 -o "$work/$name"
  cp "$work/$name/mannequin-devil_checker_three_quarter.png" "$fig/mannequin_${name}_checker.png"
  cp "$work/$name/mannequin-devil_stretch_three_quarter.png" "$fig/mannequin_${name}_stretch.png"
  cp "$work/$name/mannequin-devil_uv_stretch.png" "$fig/mannequin_${name}_uv_stretch.png"
done <<'EOF_RUNS'
U0 -m u0
U1 -m u1
Uopt -m uopt
Ufree -m uopt --polish 100 --free-border
EOF_RUNS
# remeshed with 1500 vertices, few enough to see the triangles
for pair in U0:u0 U0_U1:u0-u1 U0_Uopt:u0-uopt; do
  build/release/tools/smp-remesh "$mesh" -n 1500 --pair "${pair#*:}" --size 400 -o "$work/remesh.off" \
    --picture "$fig/remesh_mannequin_${pair%%:*}.png"
done
# and with more vertices where the surface curves
build/release/tools/smp-remesh "$mesh" -n 1500 --curvature 1 --size 400 -o "$work/remesh.off" \
  --picture "$fig/remesh_mannequin_curvature.png"
echo "figures written to $fig"
