#!/usr/bin/env bash
# Build the main example and parameterize the mannequin head; writes
# mannequin_uv.obj at the repo root.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh

cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_EXAMPLES=ON
cmake --build build/release -j2 --target stretch_minimizing_parameterization

build/release/examples/Stretch_minimizing_parameterization/stretch_minimizing_parameterization \
  examples/Stretch_minimizing_parameterization/data/mannequin-devil.off mannequin_uv.obj

echo "UV-mapped mesh written to $(pwd)/mannequin_uv.obj"
