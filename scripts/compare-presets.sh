#!/usr/bin/env bash
# The paper's method and LOWEST_STRETCH side by side through smp-parameterize (each call a fresh
# process, as a user runs it; unit square border, all cores), in turns, ROUNDS times per mesh:
# L2 stretch, descent steps and the median times, written as a markdown table to standard output.
# From the root of the repository:
#   bash scripts/compare-presets.sh [-r ROUNDS] MESH...
# MESH is a file, or FILE@loopN: the file refined N times by CGAL's Loop subdivision (written
# to build/bench/refined/ once). ROUNDS defaults to 3.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

rounds=3
if [ "${1:-}" = "-r" ]; then rounds="$2"; shift 2; fi
[ $# -gt 0 ] || { echo "usage: bash scripts/compare-presets.sh [-r ROUNDS] MESH..." >&2; exit 2; }

bash scripts/install-deps.sh >&2
cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_BENCHMARK=ON -DSMP_BUILD_TOOLS=ON \
      -DSMP_BUILD_TESTS=OFF -DSMP_BUILD_EXAMPLES=OFF >/dev/null
cmake --build build/bench -j"$(nproc)" --target smp-parameterize refine_mesh >&2
tool=build/bench/tools/smp-parameterize
work=build/bench/compare-presets
mkdir -p build/bench/refined "$work"

echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average $(cut -d ' ' -f 1-3 /proc/loadavg), commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown), $rounds rounds"
echo
echo "| mesh | vertices | paper L2 | LOWEST L2 | descent steps | paper s | LOWEST s | LOWEST / paper time |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for spec in "$@"; do
  file="${spec%@loop*}"
  name="$(basename "${file%.*}")"
  if [ "$spec" != "$file" ]; then
    levels="${spec##*@loop}"
    name="$name-loop$levels"
    [ -f "build/bench/refined/$name.off" ] ||
      build/bench/benchmark/Stretch_minimizing_parameterization/refine_mesh "$file" "$levels" "build/bench/refined/$name.off"
    file="build/bench/refined/$name.off"
  fi
  for r in $(seq "$rounds"); do
    for preset in paper lowest; do
      "$tool" "$file" --preset "$preset" --no-pictures -q -o "$work/$preset-$r" >/dev/null
    done
  done
  python3 - "$work" "$rounds" "$name" <<'PY'
import json, statistics, sys
work, rounds, name = sys.argv[1], int(sys.argv[2]), sys.argv[3]
def load(preset):
    reports = [json.load(open(f"{work}/{preset}-{r}/report.json")) for r in range(1, rounds + 1)]
    return reports[0], statistics.median(x["seconds"]["parameterize"] for x in reports)
(paper, tp), (lowest, tl) = load("paper"), load("lowest")
print(f"| {name} | {paper['mesh']['vertices']} | {paper['measures']['l2_stretch']:.4f} | "
      f"{lowest['measures']['l2_stretch']:.4f} | {lowest['polish']['descent_iterations']} | "
      f"{tp:.3g} | {tl:.3g} | {tl / tp:.2f} |")
PY
done
