#!/usr/bin/env bash
# Builds the tests with AddressSanitizer and UndefinedBehaviorSanitizer in build/asan and runs them.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh

# Without UMFPACK: the release tests cover the UMFPACK default, these Eigen's SparseLU.
cmake -S . -B build/asan -DCMAKE_BUILD_TYPE=Release -DSMP_SANITIZE=ON \
  -DSMP_BUILD_TESTS=ON -DSMP_BUILD_EXAMPLES=OFF -DSMP_WITH_UMFPACK=OFF
cmake --build build/asan -j2
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build/asan --output-on-failure -j2
