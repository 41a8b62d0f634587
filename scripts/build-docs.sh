#!/usr/bin/env bash
# Builds the documentation (user manual and reference, Doxygen) in build/doc and fails on any
# Doxygen warning. Installs what is missing first: the build dependencies (install-deps.sh),
# then doxygen, and bibtex (texlive-binaries) and perl for the citations.
# Output: build/doc/doc/Stretch_minimizing_parameterization/html/index.html
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh

# Debian packages providing the commands the doc target runs
packages=(doxygen texlive-binaries perl)
missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  if [ "$status" != "installed" ]; then
    missing+=("$p")
  fi
done
if [ "${#missing[@]}" -gt 0 ]; then
  SUDO=()
  if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1; then
    SUDO=(sudo)
  fi
  echo "build-docs: installing ${missing[*]}" >&2
  "${SUDO[@]}" apt-get update
  "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build/doc -DSMP_BUILD_DOC=ON -DSMP_BUILD_TESTS=OFF -DSMP_BUILD_EXAMPLES=OFF
cmake --build build/doc --target doc
