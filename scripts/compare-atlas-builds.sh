#!/usr/bin/env bash
# Two builds of smp-parameterize side by side on the atlas (a change against the code before it):
# for every mesh, each tool runs RUNS times in turns (so that both see the same load), and the
# least atlas time of each (report.json's seconds.atlas) is kept with the atlas's charts, L2
# stretch, seam share and utilization (deterministic: the same in every run), and whether the
# two OBJ files are the same byte for byte (a change meant to keep every atlas). From the root of
# the repository:
#   bash scripts/compare-atlas-builds.sh [-r RUNS] [-l BUSY] [-a "ARGS"] TOOL_BEFORE TOOL_AFTER MESH...
# TOOL_*: smp-parameterize executables (e.g. build/release/tools/smp-parameterize of two
# checkouts); RUNS defaults to 3. BUSY (default 0): processes that keep a core busy beside the
# tools all along, as other work on a shared machine does; ARGS: options given to both tools
# beside --atlas (e.g. "--max-stretch 1.1"). Writes a markdown table and the
# totals to standard output.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=lib/two-builds.sh
. "$(dirname "$0")/lib/two-builds.sh"
two_builds_init "bash scripts/compare-atlas-builds.sh [-r RUNS] [-l BUSY] [-a ARGS] TOOL_BEFORE TOOL_AFTER MESH..." "$@"

echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average $(cut -d ' ' -f 1-3 /proc/loadavg), $runs runs each in turns, $busy busy processes beside"
echo
echo "| mesh | charts | L2 | seam % | utilization | atlas s (least) | same OBJ |"
echo "|---|---:|---:|---:|---:|---:|---|"
for mesh in "${meshes[@]}"; do
  two_builds_run "$mesh" --atlas
  obj="$(basename "${mesh%.*}").obj"
  same=no
  cmp -s "$work/before-1/$obj" "$work/after-1/$obj" && same=yes
  python3 - "$work" "$runs" "$(basename "$mesh")" "$same" <<'PY'
import json, sys
work, runs, name, same = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
def load(tool):
    reports = [json.load(open(f"{work}/{tool}-{r}/report.json")) for r in range(1, runs + 1)]
    a = reports[0]["atlas"]
    return a, min(x["seconds"]["atlas"] for x in reports)
(a, ta), (b, tb) = load("before"), load("after")
seam = lambda x: 100 * x["seam_length"] / x["edge_length"] if x["edge_length"] > 0 else 0.
print(f"| {name} | {a['charts']} / {b['charts']} | {a['l2_stretch']:.4f} / {b['l2_stretch']:.4f} | "
      f"{seam(a):.2f} / {seam(b):.2f} | {a['utilization']:.3f} / {b['utilization']:.3f} | {ta:.3f} / {tb:.3f} | {same} |")
PY
done | tee "$work/table.md"
python3 - "$work/table.md" <<'PY'
import sys
rows = [[c.strip() for c in l.strip().strip("|").split("|")] for l in open(sys.argv[1])]
pair = lambda c: [float(x) for x in c.split("/")]
t = [pair(r[5]) for r in rows]
s = [pair(r[3]) for r in rows]
u = [pair(r[4]) for r in rows]
n = len(rows)
same = sum(r[6] == "yes" for r in rows)
print()
print(f"Totals over {n} meshes (before / after): atlas time {sum(x[0] for x in t):.3f} / {sum(x[1] for x in t):.3f} s "
      f"({sum(x[1] for x in t) / sum(x[0] for x in t):.3f}); mean seam share {sum(x[0] for x in s) / n:.3f} / "
      f"{sum(x[1] for x in s) / n:.3f} %; mean utilization {sum(x[0] for x in u) / n:.4f} / {sum(x[1] for x in u) / n:.4f}; "
      f"OBJ files the same byte for byte on {same} of {n}")
PY
