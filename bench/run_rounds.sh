#!/bin/sh
# Repeated side-by-side rounds on the settled bed, for a shared machine whose speed drifts by
# +-25 % within minutes: each round runs veridem and LAMMPS back to back on 1 thread/rank, then on
# 2, and prints the ratio of the two adjacent runs. The spread of the ratios over the rounds is
# the honest uncertainty of "veridem / LAMMPS" on that machine.
#
#   bench/run_rounds.sh [BUILD_DIR] [STEPS] [ROUNDS]      (defaults: build/release, 10000, 3)
#
# Needs lmp (apt-get install -y lammps). VERIDEM_BASELINE_BENCH=path also runs another build of
# veridem_bench each round (1 thread), for a before/after ratio.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
build=${1:-$root/build/release}
steps=${2:-10000}
rounds=${3:-3}
shared=${VERIDEM_SHARED_BENCH_DIR:-$root/../shared/bench}
export GOMP_SPINCOUNT=${GOMP_SPINCOUNT:-20000}
bench="$build/bench/veridem_bench"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/lammps/xyz_to_data.py" "$shared/settled_bed_20k.xyz" "$work/bed.data" 0.05

veridem_rate() { # bench binary, threads -> particle-steps/s of the whole run
  "$1" --steps "$steps" --threads "$2" --file "$shared/settled_bed_20k.xyz" |
    awk '/wall time/ {for (i = 1; i < NF; ++i) if ($(i + 1) == "particle-steps/s") print $i}'
}
lammps_rate() { # ranks -> particle-steps/s
  mpirun --allow-run-as-root --oversubscribe -np "$1" lmp -in "$here/lammps/bed.in" -var data "$work/bed.data" \
    -var steps "$steps" -log "$work/lammps.log" -screen none -nocite > /dev/null 2>&1
  awk '/^Loop time of/ {printf "%.4g", $12 * $9 / $4}' "$work/lammps.log"
}

echo "date $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), settled bed, $steps steps"
for r in $(seq "$rounds"); do
  for n in 1 2; do
    v=$(veridem_rate "$bench" "$n")
    l=$(lammps_rate "$n")
    echo "round $r, $n thread(s)/rank(s): veridem $v  LAMMPS $l  ratio $(awk -v a="$v" -v b="$l" 'BEGIN {printf "%.2f", a / b}')"
  done
  if [ -n "${VERIDEM_BASELINE_BENCH:-}" ]; then
    b=$(veridem_rate "$VERIDEM_BASELINE_BENCH" 1)
    v=$(veridem_rate "$bench" 1)
    echo "round $r, baseline: $b  this build: $v  ratio $(awk -v a="$v" -v b="$b" 'BEGIN {printf "%.2f", a / b}')"
  fi
done
