#!/bin/sh
# The DEM8 drum case in LIGGGHTS from the shared input: converts it (convert_drum.py), runs STEPS
# steps of 8e-7 s from the settled bed (the drum starting to turn at t = 0), and writes
# OUTDIR/drum-liggghts.csv in veridem's zones.csv columns (t [s], zone, material, count: M1 and M2
# centres in zone 1, x > 0 and z > 0, and zone 2, x < 0 and z < 0) every EVERY steps, and
# OUTDIR/drum-liggghts.log; prints the wall time, particle-steps/s per wall and per CPU-second,
# and the load (uptime) before and after. See README.md.
#
#   bench/dem8/peers/run_drum.sh [--ranks N] [--every N] [--nice N] STEPS OUTDIR
#     --ranks N   LIGGGHTS MPI ranks (default 1)
#     --every N   steps between zone counts (default 125000: 0.1 s)
#     --nice N    run under `nice -n N` (default 0)
# Environment: VERIDEM_SHARED_DEM8 (default <repo>/../shared/dem8).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
shared=${VERIDEM_SHARED_DEM8:-$root/../shared/dem8}
ranks=1 every=125000 niceness=0
while [ $# -gt 2 ]; do
  case $1 in
    --ranks) ranks=$2; shift 2 ;;
    --every) every=$2; shift 2 ;;
    --nice) niceness=$2; shift 2 ;;
    *) echo "run_drum.sh: unknown option '$1' (expected --ranks, --every, --nice)" >&2; exit 2 ;;
  esac
done
[ $# -eq 2 ] || { echo "usage: run_drum.sh [options] STEPS OUTDIR (STEPS: steps of 8e-7 s)" >&2; exit 2; }
steps=$1 out=$2
case $steps in ''|*[!0-9]*|0) echo "run_drum.sh: STEPS expects a positive whole number, found '$steps'" >&2; exit 2 ;; esac
mkdir -p "$out"
out=$(cd "$out" && pwd)
work="$out/input"
/usr/bin/python3 "$here/convert_drum.py" "$shared/drum/particles.txt" "$shared/drum/walls.txt" "$work"
particles=$(sed -n 's/^particles = //p' "$work/drum.txt")
echo "DEM8 drum: $particles particles, $steps steps of 8e-7 s, LIGGGHTS on $ranks rank(s); before: $(uptime)"
log="$out/drum-liggghts.log"
(cd "$work" && nice -n "$niceness" /usr/bin/time -f "%U %S" -o "$out/drum-liggghts.cpu" mpirun --allow-run-as-root --oversubscribe -np "$ranks" liggghts \
  -in "$here/drum_liggghts.in" -var data drum.data -var mesh walls.stl -var steps "$steps" -var every "$every" \
  -log "$log" -screen "$out/drum-liggghts.screen" > /dev/null 2>&1) ||
  { echo "run_drum.sh: LIGGGHTS failed, see $log and $out/drum-liggghts.screen" >&2; exit 1; }
echo "after: $(uptime)"
# thermo rows: step, t, M1 zone 1, M2 zone 1, M1 zone 2, M2 zone 2, atoms
awk 'BEGIN {print "t,zone,material,count"} /^ *Step/ {on = 1; next} /^Loop time/ {on = 0}
     on && NF == 7 {print $2 ",zone1,M1," $3; print $2 ",zone1,M2," $4; print $2 ",zone2,M1," $5; print $2 ",zone2,M2," $6}' \
  "$log" > "$out/drum-liggghts.csv"
wall=$(awk '/^Loop time of/ {print $4}' "$log" | tail -n 1)
cpu=$(awk 'NF == 2 {print $1 + $2}' "$out/drum-liggghts.cpu")
awk -v p="$particles" -v n="$steps" -v w="$wall" -v c="$cpu" -v r="$ranks" 'BEGIN {
  printf "LIGGGHTS-%s: loop %s s wall, %.4g particle-steps/s; cpu %s s (all ranks, with start-up), %.4g particle-steps per CPU-second\n",
    r, w, p * n / w, c, p * n / c }'
