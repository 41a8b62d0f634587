#!/usr/bin/env bash
# Installs what is missing, builds the command-line tool and parameterizes the bundled mannequin
# head: prints the stretch of every step and writes the OBJ (+ MTL, checkerboard), the JSON
# report and the pictures into mannequin-devil_uv/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh

cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_TOOLS=ON > /dev/null
cmake --build build/release -j2 --target smp-parameterize

build/release/tools/smp-parameterize examples/Stretch_minimizing_parameterization/data/mannequin-devil.off \
  -o mannequin-devil_uv
echo "Pictures: $(pwd)/mannequin-devil_uv/*.png (checkerboard and stretch views, uv layout)"
