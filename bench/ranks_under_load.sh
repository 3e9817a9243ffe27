#!/bin/sh
# Two MPI ranks against one process (one thread) on the settled 20k bed and on a pour, on a quiet
# machine and with one other CPU-bound process running (`yes > /dev/null`), in interleaved runs
# (docs/performance.md, "Ranks on a shared machine"; bench/threads_under_load.sh does the same for
# threads).
#
#   bench/ranks_under_load.sh [BUILD_DIR] [ROUNDS] [BED_STEPS] [POUR_STEPS]
#   (defaults: build/release, 3, 3000, 15000)
#
# The bed is veridem_bench --file settled_bed_20k.xyz (particle-steps/s over the whole run); the
# pour is `veridem run examples/pour.toml --stop-at-step POUR_STEPS` (dt 2e-5 s: 15000 steps is
# the first 0.3 s, the bed filling through the inserter's events), timed from start to exit (the
# scene's preparation, the outputs every 0.01 s and the checkpoint at the stop included). Each round runs, in
# the quiet condition and then with the `yes` process, 1 process, 2 ranks, 2 ranks, 1 process per
# scene (so that a drift of the machine's load within the round weighs on both alike) and prints
# each figure with the 1-minute load average read just before it, and the round's ratio of the
# two 2-rank speeds' sum to the two 1-process speeds' sum (>= 0.8 is the goal under load).
# VERIDEM_BASELINE_BUILD=path/to/another/build runs that build the same way right after this one in
# every slot. Ranks are started by `mpirun -np 2` with OpenMPI's defaults (a rank bound to a core)
# plus the options a container needs (root, no single-copy shared memory); VERIDEM_MPIRUN_ARGS adds
# more to both builds' ranks, VERIDEM_BASELINE_MPIRUN_ARGS to the baseline's only (e.g.
# "--mca mpi_yield_when_idle 1", OpenMPI's own yielding wait).
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
build=${1:-$root/build/release}
rounds=${2:-3}
bedSteps=${3:-3000}
pourSteps=${4:-15000}
input=${VERIDEM_SHARED_BENCH_DIR:-$root/../shared/bench}/settled_bed_20k.xyz
baseline=${VERIDEM_BASELINE_BUILD:-}
work=$(mktemp -d /tmp/veridem-ranks-XXXXXX)
mpiBase="mpirun --allow-run-as-root --oversubscribe --mca btl_vader_single_copy_mechanism none ${VERIDEM_MPIRUN_ARGS:-}"

launch() { # ranks (1: one process, no launcher) then the command
  n=$1
  shift
  if [ "$n" = 1 ]; then "$@"; else $mpirun -np "$n" "$@"; fi
}
bed() { # build, ranks -> particle-steps/s
  launch "$2" "$1/bench/veridem_bench" --steps "$bedSteps" --threads 1 --file "$input" |
    awk '/wall time/ {for (i = 1; i < NF; ++i) if ($(i + 1) == "particle-steps/s") print $i}'
}
pour() { # build, ranks -> 1 / seconds of the whole run (a speed, so that the ratio reads as bed's)
  rm -rf "$work/out"
  t0=$(date +%s.%N)
  launch "$2" "$1/src/app/veridem" run "$root/examples/pour.toml" --threads 1 --out "$work/out" \
    --stop-at-step "$pourSteps" > "$work/pour.log" 2>&1 || { echo "pour failed:" >&2; cat "$work/pour.log" >&2; }
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.4f", 1 / (b - a)}'
}
load() { cut -d' ' -f1 /proc/loadavg; }

hog=""
stop_hog() { if [ -n "$hog" ]; then kill "$hog" 2> /dev/null; wait "$hog" 2> /dev/null; hog=""; fi; }
cleanup() { stop_hog; rm -rf "$work"; }
trap cleanup EXIT
trap 'cleanup; exit 130' INT TERM

echo "date $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, bed $bedSteps steps a run (particle-steps/s)," \
  "pour $pourSteps steps a run (1/s of the whole run)"
for r in $(seq "$rounds"); do
  for condition in quiet loaded; do
    if [ "$condition" = loaded ]; then
      yes > /dev/null &
      hog=$!
      sleep 1
    fi
    for scene in bed pour; do
      line="round $r, $condition, $scene:"
      for name in this baseline; do
        b=$build
        mpirun=$mpiBase
        if [ "$name" = baseline ]; then
          [ -n "$baseline" ] || continue
          b=$baseline
          mpirun="$mpiBase ${VERIDEM_BASELINE_MPIRUN_ARGS:-}"
        fi
        l1=$(load); r1=$($scene "$b" 1)
        l2=$(load); r2=$($scene "$b" 2)
        l3=$(load); r3=$($scene "$b" 2)
        l4=$(load); r4=$($scene "$b" 1)
        line="$line  $name 1p $r1 (load $l1) 2r $r2 (load $l2) 2r $r3 (load $l3) 1p $r4 (load $l4)"
        line="$line ratio $(awk -v a="$r2" -v b="$r3" -v c="$r1" -v d="$r4" 'BEGIN {printf "%.2f", (a + b) / (c + d)}');"
      done
      echo "$line"
    done
    stop_hog
  done
done
