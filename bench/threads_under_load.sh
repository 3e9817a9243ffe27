#!/bin/sh
# Two threads against one on the settled 20k bed, on a quiet machine and with one other CPU-bound
# process running (`yes > /dev/null`), in short interleaved runs (docs/performance.md, "Threads on
# a shared machine").
#
#   bench/threads_under_load.sh [BUILD_DIR] [ROUNDS] [STEPS]   (defaults: build/release, 4, 3000)
#
# Each round runs, in the quiet condition and then with the `yes` process, 1, 2, 2 and 1 threads
# (so that a drift of the machine's load within the round weighs on both counts alike), and
# prints each rate with the 1-minute load average read just before it, and the round's ratio of
# the two 2-thread rates' sum to the two 1-thread rates' sum. VERIDEM_BASELINE_BENCH=path/to/
# another/veridem_bench runs that build the same way, right after this one, in every slot.
# VERIDEM_QUIET_RT=1 runs the quiet condition's runs under `chrt -f 10` (real-time priority; needs
# root or CAP_SYS_NICE): on a machine that other users keep busy, the benchmark's threads then
# preempt everyone else's, which stands in for idle cores (the kernel still keeps 5 % of each
# second for other work: /proc/sys/kernel/sched_rt_runtime_us). The condition with `yes` never
# uses it (`yes` would not run).
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
build=${1:-$root/build/release}
rounds=${2:-4}
steps=${3:-3000}
input=${VERIDEM_SHARED_BENCH_DIR:-$root/../shared/bench}/settled_bed_20k.xyz
bench="$build/bench/veridem_bench"
baseline=${VERIDEM_BASELINE_BENCH:-}

rate() { # bench binary, threads -> whole-run particle-steps/s
  $rt "$1" --steps "$steps" --threads "$2" --file "$input" |
    awk '/wall time/ {for (i = 1; i < NF; ++i) if ($(i + 1) == "particle-steps/s") print $i}'
}
load() { cut -d' ' -f1 /proc/loadavg; }

hog=""
stop_hog() { if [ -n "$hog" ]; then kill "$hog" 2> /dev/null; wait "$hog" 2> /dev/null; hog=""; fi; }
trap stop_hog EXIT INT TERM

echo "date $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, $steps steps a run"
for r in $(seq "$rounds"); do
  for condition in quiet loaded; do
    rt=""
    [ "$condition" = quiet ] && [ -n "${VERIDEM_QUIET_RT:-}" ] && rt="chrt -f 10"
    if [ "$condition" = loaded ]; then
      yes > /dev/null &
      hog=$!
      sleep 1
    fi
    line="round $r, $condition${rt:+ (chrt -f 10)}:"
    for name in this baseline; do
      b=$bench
      if [ "$name" = baseline ]; then
        [ -n "$baseline" ] || continue
        b=$baseline
      fi
      l1=$(load); r1=$(rate "$b" 1)
      l2=$(load); r2=$(rate "$b" 2)
      l3=$(load); r3=$(rate "$b" 2)
      l4=$(load); r4=$(rate "$b" 1)
      line="$line  $name 1t $r1 (load $l1) 2t $r2 (load $l2) 2t $r3 (load $l3) 1t $r4 (load $l4)"
      line="$line ratio $(awk -v a="$r2" -v b="$r3" -v c="$r1" -v d="$r4" 'BEGIN {printf "%.2f", (a + b) / (c + d)}');"
    done
    stop_hog
    echo "$line"
  done
done
