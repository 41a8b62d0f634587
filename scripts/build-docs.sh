#!/usr/bin/env bash
# Builds the documentation (user manual and reference, Doxygen) in build/doc and fails on any
# Doxygen warning. Installs what is missing first: the build dependencies (install-deps.sh),
# then doxygen, and bibtex (texlive-binaries) and perl for the citations.
# Output: build/doc/doc/Stretch_minimizing_parameterization/html/index.html
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# doxygen, and bibtex (texlive-binaries) and perl for the citations
bash scripts/install-deps.sh doxygen texlive-binaries perl

cmake -S . -B build/doc -DSMP_BUILD_DOC=ON -DSMP_BUILD_TESTS=OFF -DSMP_BUILD_EXAMPLES=OFF
cmake --build build/doc --target doc
