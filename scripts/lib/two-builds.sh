# shellcheck shell=bash
# Sourced by the scripts that set two builds of smp-parameterize side by side
# (compare-atlas-builds.sh, compare-solver-builds.sh): their options, the scratch directory and
# the runs in turns, so that both tools see the same load.
#   two_builds_init USAGE "$@"   reads [-r RUNS] [-l BUSY] [-a ARGS] TOOL_BEFORE TOOL_AFTER MESH...
#                                into runs, busy, args, before, after and meshes (an array); makes
#                                $work (removed on exit) and starts BUSY processes that keep a core
#                                busy until then
#   two_builds_run MESH OPTION...  runs each tool RUNS times in turns on MESH with OPTION... and
#                                ARGS into $work/before-R and $work/after-R; exits if a run fails

two_builds_init()
{
  local usage="$1"
  shift
  runs=3
  busy=0
  args=""
  while [ $# -gt 0 ]; do
    case "$1" in
      -r) runs="$2"; shift 2 ;;
      -l) busy="$2"; shift 2 ;;
      -a) args="$2"; shift 2 ;;
      *) break ;;
    esac
  done
  [ $# -ge 3 ] || { echo "usage: $usage" >&2; exit 2; }
  # shellcheck disable=SC2034 # read by name in two_builds_run
  before="$(realpath "$1")"
  # shellcheck disable=SC2034 # read by name in two_builds_run
  after="$(realpath "$2")"
  shift 2
  # shellcheck disable=SC2034 # read by the sourcing script
  meshes=("$@")
  work="$(mktemp -d)"
  busy_pids=()
  trap two_builds_cleanup EXIT
  for _ in $(seq "$busy"); do
    sh -c 'while :; do :; done' &
    busy_pids+=("$!")
  done
}

two_builds_cleanup()
{
  local p
  rm -rf "$work"
  for p in "${busy_pids[@]}"; do
    kill "$p" 2>/dev/null || true
  done
}

two_builds_run()
{
  local mesh="$1" r tool
  shift
  for r in $(seq "$runs"); do
    for tool in before after; do
      # shellcheck disable=SC2086 # ARGS is a list of options
      "${!tool}" "$mesh" "$@" $args --no-pictures -q -o "$work/$tool-$r" >/dev/null 2>&1 ||
        { echo "$tool failed on $mesh" >&2; exit 1; }
    done
  done
}
