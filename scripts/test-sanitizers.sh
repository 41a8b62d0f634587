#!/usr/bin/env bash
# Builds the tests with AddressSanitizer and UndefinedBehaviorSanitizer in build/asan and runs
# them, against CGAL 6.1.1 when ../shared/cgal holds its headers (CI: the release build of
# scripts/test.sh uses Debian's CGAL 5.5.1 and g++, so one CI run builds and tests both CGALs
# and both compilers), else against Debian's CGAL; meanwhile, against the same CGAL, compiles the
# examples, the tools and the benchmark without code generation (-fsyntax-only: every template
# they use instantiated and checked, in a fraction of a build's time; scripts/test.sh builds and
# runs them). The compiler is clang++-14: these translation units, with the sanitizers, take
# g++ about one and a half times as long. The tests leave their longest runs on the largest
# meshes to the release build (SMP_TEST_SANITIZED, see smp_test_util.h).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh jq clang-14 libclang-rt-14-dev

cgal=()
archive=../shared/cgal/CGAL-6.1.1-headers.tar.xz
if [ -f "$archive" ]; then
  if [ ! -f build/cgal-6.1.1/CGALConfig.cmake ]; then
    mkdir -p build/cgal-6.1.1
    tar xJf "$archive" -C build/cgal-6.1.1
  fi
  cgal=(-DCGAL_DIR="$PWD/build/cgal-6.1.1")
fi

# -O1: the sanitizers' usual level, faster to compile than -O2. Without UMFPACK: the
# release tests cover the UMFPACK default, these Eigen's SparseLU.
cmake -S . -B build/asan -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
  -DSMP_SANITIZE=ON "${cgal[@]}" -DSMP_BUILD_TESTS=ON -DSMP_BUILD_EXAMPLES=OFF -DSMP_WITH_UMFPACK=OFF
cmake --build build/asan -j2

# The examples, tools and benchmark are compiled while the tests run: the longest tests end
# alone on one core, and sharing the cores with the compilers ends the stage sooner than
# compiling after the tests, though each test takes longer.
cmake -S . -B build/syntax -DCMAKE_CXX_COMPILER=clang++-14 "${cgal[@]}" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
  -DSMP_BUILD_TESTS=OFF -DSMP_BUILD_EXAMPLES=ON -DSMP_BUILD_TOOLS=ON -DSMP_BUILD_BENCHMARK=ON
# each file once (the tools compile some files into two targets)
jq -r 'unique_by(.file) | .[] | "cd \(.directory | @sh) && \(.command) -fsyntax-only"' build/syntax/compile_commands.json |
  xargs -d '\n' -P 2 -I '{}' bash -c '{}' &
syntax=$!
trap 'kill "$syntax" 2>/dev/null || true' EXIT
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build/asan --output-on-failure -j2
wait "$syntax"
echo "test-sanitizers: examples, tools and benchmark compile"
