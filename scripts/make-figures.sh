#!/usr/bin/env bash
# Makes the pictures of the README and the manual with the project's own tool: the mannequin
# head at U^0, U^1 and U^opt (checkerboard, three-quarter view) and the uv layout of U^opt
# coloured by stretch, into doc/Stretch_minimizing_parameterization/fig/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_TOOLS=ON > /dev/null
cmake --build build/release -j2 --target smp-parameterize

fig=doc/Stretch_minimizing_parameterization/fig
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$fig"
mesh=examples/Stretch_minimizing_parameterization/data/mannequin-devil.off
for method in u0 u1 uopt; do
  build/release/tools/smp-parameterize "$mesh" -m "$method" -q --size 400 -o "$work/$method"
  name=$(echo "$method" | sed 's/^u/U/')
  cp "$work/$method/mannequin-devil_checker_three_quarter.png" "$fig/mannequin_${name}_checker.png"
  cp "$work/$method/mannequin-devil_stretch_three_quarter.png" "$fig/mannequin_${name}_stretch.png"
  cp "$work/$method/mannequin-devil_uv_stretch.png" "$fig/mannequin_${name}_uv_stretch.png"
done
echo "figures written to $fig"
