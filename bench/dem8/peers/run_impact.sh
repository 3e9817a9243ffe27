#!/bin/sh
# The DEM8 impact case (25k or 50k bed) in LIGGGHTS and Yade, from the shared input: converts it
# (convert_impact.py), runs each code to the simulated time END [s], and writes for each code
# OUTDIR/impact-<code>.csv (t [s], z [m] of the ball every 0.5 ms) and OUTDIR/impact-<code>.log,
# and prints the wall time, particle-steps/s (per wall second and per CPU-second: the machine is
# shared), the load (uptime) before and after, and the ball's deepest point (penetration.py).
# See README.md.
#
#   bench/dem8/peers/run_impact.sh [options] END OUTDIR
#     --code liggghts|yade|both   (default both, one after the other)
#     --ranks N                   LIGGGHTS MPI ranks (default 1; Yade always 1 process, 1 thread)
#     --bed 25k|50k               (default 25k)
#     --skip-flight               start the ball 1 mm above the bed top on its free-flight
#                                 parabola (z(t) = 0.06 - 5 t - g t^2 / 2, exact for a ball that
#                                 touches nothing), at the time t_s it gets there: saves the ~20 ms
#                                 of flight (40,000 steps); the bed does not relax during them
#     --nice N                    run the codes under `nice -n N` (default 0)
# Environment: VERIDEM_SHARED_DEM8 (default <repo>/../shared/dem8).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
shared=${VERIDEM_SHARED_DEM8:-$root/../shared/dem8}
code=both ranks=1 bed=25k skip=0 niceness=0
while [ $# -gt 2 ]; do
  case $1 in
    --code) code=$2; shift 2 ;;
    --ranks) ranks=$2; shift 2 ;;
    --bed) bed=$2; shift 2 ;;
    --skip-flight) skip=1; shift ;;
    --nice) niceness=$2; shift 2 ;;
    *) echo "run_impact.sh: unknown option '$1' (expected --code, --ranks, --bed, --skip-flight, --nice)" >&2; exit 2 ;;
  esac
done
[ $# -eq 2 ] || { echo "usage: run_impact.sh [options] END OUTDIR (END: simulated end time [s])" >&2; exit 2; }
end=$1 out=$2
case $code in liggghts|yade|both) ;; *) echo "run_impact.sh: --code expects liggghts, yade or both, found '$code'" >&2; exit 2 ;; esac
mkdir -p "$out"
out=$(cd "$out" && pwd)
work="$out/input-$bed"
/usr/bin/python3 "$here/convert_impact.py" "$shared/impact/particles_$bed.txt" "$shared/impact/walls.txt" "$work"
key() { sed -n "s/^$1 = //p" "$work/bed.txt"; }
particles=$(key particles) bed_top=$(key bed_top)

# Start of the run: t0 = 0 with the ball at 0.06 m and -5 m/s, or (--skip-flight) t_s, z_s, v_s on
# the parabola, with z_s = bed top + radius + 1 mm; g = 9.8 m/s^2 as in both decks.
read -r t0 zball vz steps <<EOF
$(/usr/bin/python3 - "$bed_top" "$end" "$skip" <<'PY'
import math, sys
bed_top, end, skip = float(sys.argv[1]), float(sys.argv[2]), sys.argv[3] == "1"
g, z0, v0, radius, dt, every = 9.8, 0.06, 5.0, 0.01, 5e-7, 1000
t0 = 0.0
if skip:
    drop = z0 - (bed_top + radius + 1e-3)  # m the ball falls freely
    t0 = (-v0 + math.sqrt(v0 * v0 + 2 * g * drop)) / g
    t0 = math.floor(t0 / (every * dt)) * every * dt  # on the 0.5 ms output grid
zball = z0 - v0 * t0 - 0.5 * g * t0 * t0
vz = -(v0 + g * t0)
steps = int(round((end - t0) / dt))
if steps <= 0:
    sys.exit(f"run_impact.sh: END {end} s is not after the start {t0} s")
print(f"{t0:.6g} {zball:.12g} {vz:.12g} {steps}")
PY
)
EOF
echo "DEM8 impact $bed: $particles particles, bed top $bed_top m; start t $t0 s, ball z $zball m, vz $vz m/s; $steps steps of 5e-7 s to t $end s"

summary() { # code, csv, wall seconds
  rate=$(awk -v p="$particles" -v n="$steps" -v w="$3" 'BEGIN {printf "%.4g", p * n / w}')
  echo "$1: wall $3 s for $steps steps x $particles particles = $rate particle-steps/s"
  echo "$1: $(/usr/bin/python3 "$here/penetration.py" "$2" "$bed_top")"
}

if [ "$code" != yade ]; then
  echo "LIGGGHTS ($ranks rank(s)) before: $(uptime)"
  log="$out/impact-liggghts.log"
  (cd "$work" && nice -n "$niceness" /usr/bin/time -f "%U %S" -o "$out/impact-liggghts.cpu" mpirun --allow-run-as-root --oversubscribe -np "$ranks" liggghts \
    -in "$here/impact_liggghts.in" -var data impact.data -var mesh walls.stl -var steps "$steps" \
    -var zball "$zball" -var vz "$vz" -var t0 "$t0" -var ballid "$particles" \
    -log "$log" -screen "$out/impact-liggghts.screen" > /dev/null 2>&1) ||
    { echo "run_impact.sh: LIGGGHTS failed, see $log and $out/impact-liggghts.screen" >&2; exit 1; }
  echo "LIGGGHTS after: $(uptime)"
  # thermo rows: step, t, z, vz, atoms
  awk 'BEGIN {print "t,z"} /^ *Step/ {on = 1; next} /^Loop time/ {on = 0} on && NF == 5 {print $2 "," $3}' \
    "$log" > "$out/impact-liggghts.csv"
  wall=$(awk '/^Loop time of/ {print $4}' "$log" | tail -n 1)
  echo "LIGGGHTS atoms at the end: $(awk '/^ *Step/ {on = 1; next} /^Loop time/ {on = 0} on && NF == 5 {a = $5} END {print a}' "$log")"
  summary "LIGGGHTS-$ranks" "$out/impact-liggghts.csv" "$wall"
  cpu=$(awk 'NF == 2 {print $1 + $2}' "$out/impact-liggghts.cpu")
  echo "LIGGGHTS-$ranks: cpu $cpu s (all ranks, with start-up): $(awk -v p="$particles" -v n="$steps" -v c="$cpu" 'BEGIN {printf "%.4g", p * n / c}') particle-steps per CPU-second"
fi
if [ "$code" != liggghts ]; then
  echo "Yade (1 process, 1 thread) before: $(uptime)"
  (cd "$work" && nice -n "$niceness" yade -j 1 -n -x "$here/impact_yade.py" "$work" "$steps" "$out/impact-yade.csv" \
    "$zball" "$vz" "$t0" 2e-4 > "$out/impact-yade.log" 2>&1) ||
    { echo "run_impact.sh: Yade failed, see $out/impact-yade.log" >&2; exit 1; }
  echo "Yade after: $(uptime)"
  wall=$(awk '/^yade wall/ {print $3}' "$out/impact-yade.log")
  summary "Yade-1" "$out/impact-yade.csv" "$wall"
  echo "Yade-1: $(awk '/^yade wall/ {print "cpu " $5 " s: " $13 " particle-steps per CPU-second"}' "$out/impact-yade.log")"
fi
