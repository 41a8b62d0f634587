#!/usr/bin/env bash
# Installs what is missing, builds the tests, examples and tool in build/release and runs them.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh

cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release \
  -DSMP_BUILD_TESTS=ON -DSMP_BUILD_EXAMPLES=ON -DSMP_BUILD_TOOLS=ON
cmake --build build/release -j2
ctest --test-dir build/release --output-on-failure -j2
