#!/usr/bin/env bash
# Two builds of smp-parameterize side by side on U^opt (a change of the linear solver against
# the code before it): for every mesh, each tool runs RUNS times in turns (so that both see the
# same load), and the least parameterization time of each (report.json's seconds.parameterize)
# is kept with the steps, the L2 stretch of U^opt, the largest relative difference of the two
# builds' L2 stretch over the steps, and the solver iterations summed over the steps
# (deterministic: the same in every run). From the root of the repository:
#   bash scripts/compare-solver-builds.sh [-r RUNS] [-l BUSY] [-a "ARGS"] TOOL_BEFORE TOOL_AFTER MESH...
# TOOL_*: smp-parameterize executables of two checkouts; RUNS defaults to 3; BUSY (default 0):
# processes that keep a core busy beside the tools; ARGS: options given to both tools (e.g.
# "--cut" for closed genus-0 meshes). The iterations are those of the
# multigrid solver, which serves from 30,000 interior vertices. Writes a markdown table and the
# totals to standard output.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=lib/two-builds.sh
. "$(dirname "$0")/lib/two-builds.sh"
two_builds_init "bash scripts/compare-solver-builds.sh [-r RUNS] [-l BUSY] [-a ARGS] TOOL_BEFORE TOOL_AFTER MESH..." "$@"

echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average $(cut -d ' ' -f 1-3 /proc/loadavg), $runs runs each in turns${args:+, options $args}"
echo
echo "| mesh | vertices | steps (kept) | L2 of U^opt | largest L2 difference | solver iterations | parameterization s (least) |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for mesh in "${meshes[@]}"; do
  two_builds_run "$mesh"
  python3 - "$work" "$runs" "$(basename "$mesh")" <<'PY'
import json, sys
work, runs, name = sys.argv[1], int(sys.argv[2]), sys.argv[3]
def load(tool):
    reports = [json.load(open(f"{work}/{tool}-{r}/report.json")) for r in range(1, runs + 1)]
    return reports[0], min(x["seconds"]["parameterize"] for x in reports)
(a, ta), (b, tb) = load("before"), load("after")
ha, hb = a["history"], b["history"]
diff = max((abs(x["l2_stretch"] - y["l2_stretch"]) / x["l2_stretch"] for x, y in zip(ha, hb)), default=0.)
its = lambda h: sum(x.get("solver_iterations", 0) for x in h)
l2 = lambda r: r["history"][r["kept_step"]]["l2_stretch"]
print(f"| {name} | {a['mesh']['vertices']} | {len(ha) - 1} ({a['kept_step']}) / {len(hb) - 1} ({b['kept_step']}) | "
      f"{l2(a):.6f} / {l2(b):.6f} | {diff:.1e} | {its(ha)} / {its(hb)} | {ta:.2f} / {tb:.2f} |")
PY
done | tee "$work/table.md"
python3 - "$work/table.md" <<'PY'
import sys
rows = [[c.strip() for c in l.strip().strip("|").split("|")] for l in open(sys.argv[1])]
pair = lambda c: [float(x) for x in c.split("/")]
i = [pair(r[5]) for r in rows]
t = [pair(r[6]) for r in rows]
print()
print(f"Totals over {len(rows)} meshes (before / after): solver iterations {sum(x[0] for x in i):.0f} / {sum(x[1] for x in i):.0f} "
      f"({sum(x[1] for x in i) / max(1., sum(x[0] for x in i)):.3f}); parameterization time {sum(x[0] for x in t):.2f} / "
      f"{sum(x[1] for x in t):.2f} s ({sum(x[1] for x in t) / sum(x[0] for x in t):.3f})")
PY
