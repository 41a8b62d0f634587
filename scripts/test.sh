#!/usr/bin/env bash
# Build and run all tests and examples in build/release.
# With --sanitize (or SMP_SANITIZE=1) also build and run the tests with
# AddressSanitizer + UBSan in build/asan.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

sanitize=0
if [ "${SMP_SANITIZE:-0}" = "1" ] || [ "${1:-}" = "--sanitize" ]; then
  sanitize=1
fi

bash scripts/install-deps.sh

cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release \
  -DSMP_BUILD_TESTS=ON -DSMP_BUILD_EXAMPLES=ON
cmake --build build/release -j2
ctest --test-dir build/release --output-on-failure -j2

if [ "$sanitize" = "1" ]; then
  cmake -S . -B build/asan -DSMP_SANITIZE=ON -DCMAKE_BUILD_TYPE=Release \
    -DSMP_BUILD_TESTS=ON -DSMP_BUILD_EXAMPLES=OFF
  cmake --build build/asan -j2
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build/asan --output-on-failure -j2
fi
