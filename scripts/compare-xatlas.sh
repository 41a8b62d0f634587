#!/usr/bin/env bash
# smp-parameterize --atlas against xatlas (https://github.com/jpcy/xatlas), mesh by mesh, both
# atlases graded by the same independent grader (grade_atlas). From the root of the repository:
#   bash scripts/compare-xatlas.sh XATLAS_SRC_DIR OUT_DIR MESH...
# XATLAS_SRC_DIR: a checkout of xatlas (its xatlas.h and xatlas.cpp, in source/xatlas/ or at its
# top); nothing of it enters this repository: benchmark/peers/xatlas_driver.cpp is built with it
# into OUT_DIR. Our tool and grade_atlas are built in build/bench. For every mesh, ours then
# xatlas's run one right after the other (so that both see the same load), each timed as a
# whole process; OUT_DIR gets ours/NAME/, xatlas/NAME.obj, the grades, and compare.md.
#
# Environment (all optional):
#   SMP_COMPARE_BUILD_DIR=build/bench   where our tool and the grader are built
#   SMP_COMPARE_PADDING=0               xatlas's PackOptions::padding (see xatlas_driver.cpp)
#   SMP_COMPARE_TIMEOUT=1800            kill a run that takes longer than this (s)
#   SMP_COMPARE_RUNS=3                  runs of each program per mesh, in turns; the least time is kept
set -euo pipefail

if [ $# -lt 3 ]; then
  echo "usage: bash scripts/compare-xatlas.sh XATLAS_SRC_DIR OUT_DIR MESH..." >&2
  exit 2
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
xatlas_src="$(realpath "$1")"
mkdir -p "$2"
out="$(realpath "$2")"
shift 2
meshes=()
for m in "$@"; do meshes+=("$(realpath "$m")"); done
build="${SMP_COMPARE_BUILD_DIR:-build/bench}"
padding="${SMP_COMPARE_PADDING:-0}"
limit="${SMP_COMPARE_TIMEOUT:-1800}"
runs="${SMP_COMPARE_RUNS:-3}"
cd "$root"

# --- build: xatlas with the flags of its own Release configuration (-DNDEBUG, else its debug
# checks run), the driver, our tool and the grader (Release: -O2 -DNDEBUG)
xdir="$xatlas_src/source/xatlas"
[ -f "$xdir/xatlas.cpp" ] || xdir="$xatlas_src"
[ -f "$xdir/xatlas.cpp" ] && [ -f "$xdir/xatlas.h" ] || { echo "no xatlas.cpp and xatlas.h in $xatlas_src" >&2; exit 1; }
g++ -O2 -DNDEBUG -std=c++17 -pthread -c "$xdir/xatlas.cpp" -o "$out/xatlas.o"
g++ -O2 -DNDEBUG -std=c++17 -pthread -I"$xdir" benchmark/peers/xatlas_driver.cpp "$out/xatlas.o" -o "$out/xatlas_driver"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSMP_BUILD_BENCHMARK=ON -DSMP_BUILD_TOOLS=ON \
      -DSMP_BUILD_TESTS=OFF -DSMP_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target smp-parameterize grade_atlas
tool="$(realpath "$build/tools/smp-parameterize")"
grade="$(realpath "$build/benchmark/Stretch_minimizing_parameterization/grade_atlas")"

# value of KEY in a line of key=value pairs
get() { sed -n "s/.* $2=\([^ ]*\).*/\1/p" <<< " $1"; }
# value of "KEY": in report.json
json() { sed -n "s/.*\"$2\": \([^,}]*\).*/\1/p" "$1" | head -n 1; }
fmt() { [ -n "$2" ] && [ "$2" != null ] && LC_ALL=C printf "%.$1f" "$2" || printf '-'; }
pct() { [ -n "$1" ] && [ "$1" != null ] && LC_ALL=C awk -v x="$1" 'BEGIN { printf "%.2f", 100 * x }' || printf '-'; }
pair() { echo "$1 / $2"; }
# runs a command, its wall time in seconds (whole process) in $seconds; fails softly
run_timed() {
  local start end
  start=$(date +%s.%N)
  if timeout "$limit" "$@"; then status=ok; else status="failed ($?)"; fi
  end=$(date +%s.%N)
  seconds=$(LC_ALL=C awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
}

mkdir -p "$out/ours" "$out/xatlas"
table="$out/compare.md"
details="$out/details.md"
{
  echo "# smp-parameterize --atlas and xatlas"
  echo
  echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average at the start $(cut -d ' ' -f 1-3 /proc/loadavg)."
  echo "xatlas $(git -C "$xatlas_src" rev-parse --short HEAD 2>/dev/null || echo '(not a git checkout)'): default ChartOptions,"
  echo "PackOptions resolution 1024, padding $padding, bilinear on; ours: default options (gutter 2 texels, resolution 1024)."
  echo "Each cell: ours / xatlas. All figures by grade_atlas on the written OBJ files: L2 and Linf are Sander's"
  echo "normalized stretch, flipped counts triangles against the orientation of their chart, overlaps the pairs of"
  echo "uv triangles whose interiors meet (exact), seam % the share of the edge length cut, utilization the uv area"
  echo "over the square of the longer side of the uv bounding box. Seconds: wall time of the whole process (read,"
  echo "atlas, write; ours without pictures), the least of $runs runs of each, taken in turns; ratio: xatlas's time over ours."
  echo
  echo "| mesh | faces | charts | L2 | Linf | flipped | overlaps | seam % | utilization | seconds | ratio |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
} > "$table"
{
  echo "# Details"
  echo
  echo "ours: report.json against grade_atlas (L2, seam length, utilization; report.json's utilization is over the"
  echo "whole square, the grade's over the square of the uv bounding box). xatlas: its own utilization (texels of the"
  echo "charts with their bilinear and padding texels, over width x height), atlas size, xatlas's own seconds"
  echo "(ComputeCharts + PackCharts). degenerate: triangles of zero uv area and positive 3D area. mirrored: charts"
  echo "whose orientation is against the majority of the atlas (allowed, not counted as flipped)."
  echo
  echo "| mesh | ours L2 report / grade | ours seam report / grade | ours util. report / grade | ours atlas s | xatlas util. | xatlas size | xatlas s | degenerate | mirrored | split polygons (xatlas) |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
} > "$details"

for mesh in "${meshes[@]}"; do
  name="$(basename "${mesh%.*}")"
  while [ -e "$out/ours/$name" ]; do name="${name}_"; done
  echo "== $name" >&2
  # in turns, so that both see the same load; the outputs of the last runs are graded
  ours_status=ok xatlas_status=ok ours_seconds="" xatlas_seconds=""
  least() { [ -z "$1" ] && echo "$2" || LC_ALL=C awk -v a="$1" -v b="$2" 'BEGIN { print (b < a ? b : a) }'; }
  for ((k = 0; k < runs; ++k)); do
    run_timed "$tool" "$mesh" --atlas -o "$out/ours/$name" -q --no-pictures
    [ "$status" = ok ] && ours_seconds=$(least "$ours_seconds" "$seconds") || ours_status=$status
    run_timed "$out/xatlas_driver" "$mesh" "$out/xatlas/$name.obj" --padding "$padding" > "$out/xatlas/$name.txt"
    [ "$status" = ok ] && xatlas_seconds=$(least "$xatlas_seconds" "$seconds") || xatlas_status=$status
  done
  o="" x="" xa="$(cat "$out/xatlas/$name.txt")"
  # a grade that fails leaves its cells empty ('-')
  [ "$ours_status" = ok ] && o="$("$grade" "$out/ours/$name/$name.obj" | tee "$out/ours/$name/grade.txt" || true)"
  [ "$xatlas_status" = ok ] && x="$("$grade" "$out/xatlas/$name.obj" | tee "$out/xatlas/$name.grade.txt" || true)"
  [ "$ours_status" = ok ] || ours_seconds="$ours_status"
  [ "$xatlas_status" = ok ] || xatlas_seconds="$xatlas_status"
  ratio=$(LC_ALL=C awk -v a="$ours_seconds" -v b="$xatlas_seconds" 'BEGIN { if(a > 0 && b > 0) printf "%.2f", b / a; else printf "-" }')
  echo "| $name | $(get "$o" faces) | $(pair "$(get "$o" charts)" "$(get "$x" charts)")" \
       "| $(pair "$(fmt 4 "$(get "$o" l2)")" "$(fmt 4 "$(get "$x" l2)")") | $(pair "$(fmt 2 "$(get "$o" linf)")" "$(fmt 2 "$(get "$x" linf)")")" \
       "| $(pair "$(get "$o" flipped)" "$(get "$x" flipped)") | $(pair "$(get "$o" overlaps)" "$(get "$x" overlaps)")" \
       "| $(pair "$(pct "$(get "$o" seam_fraction)")" "$(pct "$(get "$x" seam_fraction)")")" \
       "| $(pair "$(fmt 3 "$(get "$o" utilization)")" "$(fmt 3 "$(get "$x" utilization)")")" \
       "| $(pair "$ours_seconds" "$xatlas_seconds") | $ratio |" >> "$table"
  report="$out/ours/$name/report.json"
  if [ -f "$report" ]; then
    r_l2="$(json "$report" l2_stretch)" r_seam="$(json "$report" seam_length)" r_util="$(json "$report" utilization)"
    r_s="$(sed -n 's/.*"seconds":.*"atlas": \([^,}]*\).*/\1/p' "$report")"
  else
    r_l2="" r_seam="" r_util="" r_s=""
  fi
  echo "| $name | $(pair "$(fmt 6 "$r_l2")" "$(fmt 6 "$(get "$o" l2)")") | $(pair "$(fmt 4 "$r_seam")" "$(fmt 4 "$(get "$o" seam_length)")")" \
       "| $(pair "$(fmt 4 "$r_util")" "$(fmt 4 "$(get "$o" utilization)")") | $(fmt 2 "$r_s")" \
       "| $(fmt 3 "$(get "$xa" utilization)") | $(get "$xa" width)x$(get "$xa" height) | $(fmt 2 "$(get "$xa" xatlas_seconds)")" \
       "| $(pair "$(get "$o" degenerate_uv)" "$(get "$x" degenerate_uv)") | $(pair "$(get "$o" mirrored_charts)" "$(get "$x" mirrored_charts)")" \
       "| $(get "$xa" split_polygons) |" >> "$details"
done
{ echo; echo "Load average at the end: $(cut -d ' ' -f 1-3 /proc/loadavg)."; echo; cat "$details"; } >> "$table"
rm -f "$details"
echo "wrote $table" >&2
