#!/bin/sh
# The measurements of docs/performance.md, in one run so that ratios are fair on a shared
# machine: for each scene (settled bed, gas) and each thread/rank count (1, 2), veridem (on 2, also
# on 2 MPI ranks: "veridem-mpi"), then LAMMPS, then LIGGGHTS (if installed: apt-get install -y lammps liggghts), on the same input; then
# the bed with Hertz-Mindlin contacts against LAMMPS `pair_style granular`, the 1e6-sphere bed and
# the one-ball turntable; then, if LIGGGHTS is installed, 20,000 spheres in a rotating meshed drum.
#
#   bench/run_reference.sh [BUILD_DIR] [STEPS]      (defaults: build/release, 10000)
#
# VERIDEM_DRUM_ONLY=1 runs the drum section alone (DRUM_WARMUP: its untimed steps, default STEPS).
#
# VERIDEM_BASELINE_BENCH=path/to/another/veridem_bench also runs that build (e.g. an older commit)
# on the bed (1 thread) and the turntable, for a before/after ratio in the same run.
#
# VERIDEM_ROUNDS=N runs, instead, N side-by-side rounds on the settled bed: veridem and LAMMPS back
# to back on 1 thread/rank, then on 2, each round printing the ratio of its two adjacent runs (and
# the baseline build against this one, if given). On a machine whose speed drifts by +-25 % within
# minutes, the spread of these ratios is the honest uncertainty of "veridem / LAMMPS". LAMMPS runs
# in 100-step runs here, so each round also prints the ratio of the two codes' best 100-step
# windows: what each code does in the quietest moments of the run (on a dedicated machine).
# Every veridem run prints a core probe before and after its timed loop (bench/core_probe.h: the
# integer adds per cycle this thread gets, ~3.7 on a whole Zen 3 core (~5 on Zen 5), 2.2-2.8 when
# another tenant's hardware thread shares it); `veridem_bench --core-probe` is run around each
# LAMMPS and LIGGGHTS run as well, so that each figure says which state of the machine it was
# measured in.
# veridem's threads wait by spinning a few microseconds, then blocking (src/exec/thread_pool.h):
# the program sets it, no environment variable changes it.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
build=${1:-$root/build/release}
steps=${2:-10000}
shared=${VERIDEM_SHARED_BENCH_DIR:-$root/../shared/bench}
bench="$build/bench/veridem_bench"
# scripts/test (CI) links the benchmarks without link-time optimisation (VERIDEM_LTO_BENCH=OFF):
# not the build these figures are for.
if grep -q '^VERIDEM_LTO_BENCH:BOOL=OFF' "$build/CMakeCache.txt" 2>/dev/null; then
  echo "bench/run_reference.sh: $build links the benchmarks without link-time optimisation" \
    "(VERIDEM_LTO_BENCH=OFF, as scripts/test builds it); run cmake --preset release &&" \
    "cmake --build --preset release first" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 "$here/lammps/xyz_to_data.py" "$shared/settled_bed_20k.xyz" "$work/bed.data" 0.05
python3 "$here/lammps/xyz_to_data.py" "$shared/random_gas_20k.xyz" "$work/gas.data" 0.32

# veridem on MPI ranks (distributed/rank_step.h): the same bench, distributed, one thread a rank.
mpi_bench() { # ranks, bench arguments...
  n=$1; shift
  mpirun --allow-run-as-root --oversubscribe --mca btl_vader_single_copy_mechanism none -np "$n" "$bench" "$@" --threads 1
}

rate_of_loop() {  # LAMMPS/LIGGGHTS log -> particle-steps/s
  # "Loop time of T on P procs for N steps with M atoms"
  awk '/^Loop time of/ {printf "%.4g", $12 * $9 / $4}' "$1"
}

# The meshed rotating drum (veridem_bench --scene drum; bench/lammps/drum_liggghts.in states the
# mapping), if LIGGGHTS is installed: one STL from scripts/make_meshes.py (a closed cylinder about +y,
# R 45 mm, L 50 mm, 96 segments: 3456 triangles) read by both codes; 20,000 of the bed's spheres
# (law, dt, skin, gravity) filled on a lattice and settled once by veridem in the drum at rest
# (40,000 steps; the same bits on any thread count), written as centres that both codes read
# (xyz_to_data.py --box). Then in each code, from that bed at rest, DRUM_WARMUP steps with the drum
# turning at 4 rad/s about +y (not timed: the bed starts turning), then STEPS timed ones; the
# kinetic energy and the bed's centre of mass at the end say whether both ran the same physics.
# LIGGGHTS crashes reading a mesh with `-screen none` (it prints to the absent screen), so its
# screen goes to a file.
drum_section() {
  command -v liggghts > /dev/null || return 0
  drum_warmup=${DRUM_WARMUP:-$steps}
  drum_steps=$((drum_warmup + steps))
  python3 "$root/scripts/make_meshes.py" drum "$work/drum.stl" --radius 0.045 --length 0.05 --segments 96 > /dev/null
  "$bench" --scene drum --mesh "$work/drum.stl" --fill 20000 --omega 0 --steps 40000 --threads 2 \
    --write-xyz "$work/drum.xyz" | sed -n 's/^ *kinetic/   veridem settled bed: kinetic/p'
  python3 "$here/lammps/xyz_to_data.py" "$work/drum.xyz" "$work/drum.data" --box -0.046 0.046 -0.001 0.051 -0.046 0.046
  for n in 1 2; do
    echo "== drum (mesh, 4 rad/s), $n thread(s)/rank(s), $drum_warmup untimed + $steps timed steps"
    "$bench" --scene drum --mesh "$work/drum.stl" --file "$work/drum.xyz" --warmup "$drum_warmup" \
      --steps "$steps" --threads "$n" | sed 's/^/   veridem /'
    echo "   LIGGGHTS before: $("$bench" --core-probe)"
    mpirun --allow-run-as-root --oversubscribe -np "$n" liggghts -in "$here/lammps/drum_liggghts.in" \
      -var data "$work/drum.data" -var mesh "$work/drum.stl" -var steps "$steps" -var warmup "$drum_warmup" \
      -log "$work/liggghts.log" -screen "$work/liggghts.screen" > /dev/null 2>&1
    echo "   LIGGGHTS $(grep '^Loop time' "$work/liggghts.log" | tail -n 1 | awk '{printf "%.4g", $12 * $9 / $4}')" \
      "particle-steps/s  ($(grep '^Loop time' "$work/liggghts.log" | tail -n 1 | cut -d, -f1))"
    echo "   LIGGGHTS kinetic energy (trans, rot) and centre of mass after $drum_steps steps:" \
      "$(awk -v s="$drum_steps" '$1 == s && NF == 7 {print $3, $4, "  ", $5, $6, $7}' "$work/liggghts.log")"
    echo "   LIGGGHTS after: $("$bench" --core-probe)"
  done
}

echo "date $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
if [ -n "${VERIDEM_DRUM_ONLY:-}" ]; then
  drum_section
  exit 0
fi

if [ -n "${VERIDEM_ROUNDS:-}" ]; then
  veridem_rate() { # bench binary, threads -> particle-steps/s of the whole run
    "$1" --steps "$steps" --threads "$2" --file "$shared/settled_bed_20k.xyz" |
      awk '/wall time/ {for (i = 1; i < NF; ++i) if ($(i + 1) == "particle-steps/s") print $i}'
  }
  veridem_rates() { # bench binary, threads -> "whole-run best-window probe-before probe-after"
    "$1" --steps "$steps" --threads "$2" --file "$shared/settled_bed_20k.xyz" |
      awk '/wall time/ {for (i = 1; i < NF; ++i) if ($(i + 1) == "particle-steps/s") w = $i}
           /best window/ {b = $6} /core probe/ {p = $8; q = $13} END {print w, b, p, q}'
  }
  probe() { "$bench" --core-probe | awk '{print $5}'; } # adds per cycle now
  lammps_rates() { # LAMMPS log of 100-step runs -> "whole-run best-window" particle-steps/s
    awk '/^Loop time of/ {t += $4; s += $9; if ($12 * $9 / $4 > b) b = $12 * $9 / $4; a = $12}
         END {printf "%.4g %.4g\n", a * s / t, b}' "$1"
  }
  ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }
  for r in $(seq "$VERIDEM_ROUNDS"); do
    for n in 1 2; do
      set -- $(veridem_rates "$bench" "$n")
      v=$1 vb=$2 vp="$3/$4"
      lp=$(probe)
      # LAMMPS in runs of 100 steps (the same trajectory: `run pre no`), so that it too has a
      # best 100-step window, the rate of a quiet moment of this shared machine.
      mpirun --allow-run-as-root --oversubscribe -np "$n" lmp -in "$here/lammps/bed.in" -var data "$work/bed.data" \
        -var steps "$steps" -var window 100 -log "$work/lammps.log" -screen none -nocite > /dev/null 2>&1
      lp="$lp/$(probe)"
      set -- $(lammps_rates "$work/lammps.log")
      l=$1 lb=$2
      echo "round $r, bed, $n thread(s)/rank(s): veridem $v  LAMMPS $l  ratio $(ratio "$v" "$l");" \
        "best 100-step windows: veridem $vb  LAMMPS $lb  ratio $(ratio "$vb" "$lb");" \
        "core probe before/after, adds/cycle: veridem $vp  LAMMPS $lp"
      if [ "$n" = 2 ]; then # veridem on 2 MPI ranks, against LAMMPS on 2 ranks and veridem on 2 threads
        m=$(mpi_bench 2 --steps "$steps" --file "$shared/settled_bed_20k.xyz" |
          awk '/wall time/ {for (i = 1; i < NF; ++i) if ($(i + 1) == "particle-steps/s") print $i}')
        echo "round $r, bed, 2 MPI ranks: veridem $m  ratio to LAMMPS $(ratio "$m" "$l")  ratio to veridem on 2 threads $(ratio "$m" "$v")"
      fi
    done
    if [ -n "${VERIDEM_BASELINE_BENCH:-}" ]; then
      b=$(veridem_rate "$VERIDEM_BASELINE_BENCH" 1)
      v=$(veridem_rate "$bench" 1)
      echo "round $r, bed, 1 thread: baseline $b  this build $v  ratio $(ratio "$v" "$b")"
    fi
  done
  exit 0
fi
for scene in bed gas; do
  for n in 1 2; do
    echo "== $scene, $n thread(s)/rank(s), $steps steps"
    "$bench" --scene "$scene" --steps "$steps" --threads "$n" --file "$shared/$( [ $scene = bed ] && echo settled_bed_20k || echo random_gas_20k ).xyz" \
      | sed 's/^/   veridem /'
    if [ "$n" = 2 ]; then
      mpi_bench 2 --scene "$scene" --steps "$steps" --file "$shared/$( [ $scene = bed ] && echo settled_bed_20k || echo random_gas_20k ).xyz" \
        | sed 's/^/   veridem-mpi /'
    fi
    if command -v lmp > /dev/null; then
      echo "   LAMMPS   before: $("$bench" --core-probe)"
      mpirun --allow-run-as-root --oversubscribe -np "$n" lmp -in "$here/lammps/bed.in" -var data "$work/$scene.data" \
        -var steps "$steps" -log "$work/lammps.log" -screen none -nocite > /dev/null 2>&1
      echo "   LAMMPS   $(rate_of_loop "$work/lammps.log") particle-steps/s  ($(grep '^Loop time' "$work/lammps.log"))"
      echo "   LAMMPS   kinetic energy (trans, rot, total) after $steps steps: $(awk -v s="$steps" '$1 == s && NF == 5 {print $3, $4, $5}' "$work/lammps.log")"
      echo "   LAMMPS   after: $("$bench" --core-probe)"
    fi
    if command -v liggghts > /dev/null; then
      echo "   LIGGGHTS before: $("$bench" --core-probe)"
      mpirun --allow-run-as-root --oversubscribe -np "$n" liggghts -in "$here/lammps/bed_liggghts.in" \
        -var data "$work/$scene.data" -var steps "$steps" -log "$work/liggghts.log" -screen none > /dev/null 2>&1
      echo "   LIGGGHTS $(rate_of_loop "$work/liggghts.log") particle-steps/s  ($(grep '^Loop time' "$work/liggghts.log" | cut -d, -f1))"
      echo "   LIGGGHTS kinetic energy (trans, rot) after $steps steps: $(awk -v s="$steps" '$1 == s && NF == 4 {print $3, $4}' "$work/liggghts.log")"
      echo "   LIGGGHTS after: $("$bench" --core-probe)"
    fi
  done
done
# The bed with Hertz-Mindlin contacts (veridem_bench --model hertz; LAMMPS `pair_style granular`
# with the same law, bench/lammps/bed_hertz.in states the mapping). LAMMPS's granular style runs
# ~10x slower than gran/hooke/history, so this comparison takes HERTZ_STEPS (default steps / 5).
hertz_steps=${HERTZ_STEPS:-$((steps / 5))}
for n in 1 2; do
  echo "== bed, Hertz-Mindlin, $n thread(s)/rank(s), $hertz_steps steps"
  "$bench" --scene bed --model hertz --steps "$hertz_steps" --threads "$n" --file "$shared/settled_bed_20k.xyz" \
    | sed 's/^/   veridem /'
  if command -v lmp > /dev/null; then
    echo "   LAMMPS   before: $("$bench" --core-probe)"
    mpirun --allow-run-as-root --oversubscribe -np "$n" lmp -in "$here/lammps/bed_hertz.in" -var data "$work/bed.data" \
      -var steps "$hertz_steps" -log "$work/lammps.log" -screen none -nocite > /dev/null 2>&1
    echo "   LAMMPS   $(rate_of_loop "$work/lammps.log") particle-steps/s  ($(grep '^Loop time' "$work/lammps.log"))"
    echo "   LAMMPS   kinetic energy (trans, rot, total) after $hertz_steps steps: $(awk -v s="$hertz_steps" '$1 == s && NF == 5 {print $3, $4, $5}' "$work/lammps.log")"
    echo "   LAMMPS   after: $("$bench" --core-probe)"
  fi
done
echo "== 1e6-sphere bed (the 20k bed tiled 7 x 7 = 980,000 spheres), 200 steps, 1 and 2 threads, 2 MPI ranks"
for n in 1 2; do "$bench" --tile 7 --steps 200 --threads "$n" | sed 's/^/   veridem /'; done
mpi_bench 2 --tile 7 --steps 200 | sed 's/^/   veridem-mpi /'
if command -v lmp > /dev/null; then
  python3 "$here/lammps/xyz_to_data.py" "$shared/settled_bed_20k.xyz" "$work/bed_1e6.data" 0.05 --tile 7 &&
    for n in 1 2; do
      mpirun --allow-run-as-root --oversubscribe -np "$n" lmp -in "$here/lammps/bed.in" -var data "$work/bed_1e6.data" \
        -var side 0.7 -var steps 200 -log "$work/lammps.log" -screen none -nocite > /dev/null 2>&1
      echo "   LAMMPS   $n rank(s): $(rate_of_loop "$work/lammps.log") particle-steps/s  ($(grep '^Loop time' "$work/lammps.log"))"
    done
fi
echo "== one ball on a turntable, 3,000,000 steps"
"$bench" --scene turntable --steps 3000000 | sed 's/^/   veridem /'
drum_section
if [ -n "${VERIDEM_BASELINE_BENCH:-}" ]; then
  echo "== baseline build $VERIDEM_BASELINE_BENCH: bed 1 thread, then turntable; this build again"
  "$VERIDEM_BASELINE_BENCH" --steps "$steps" --file "$shared/settled_bed_20k.xyz" | sed 's/^/   baseline /'
  "$bench" --steps "$steps" --threads 1 --file "$shared/settled_bed_20k.xyz" | sed 's/^/   veridem /'
  "$VERIDEM_BASELINE_BENCH" --scene turntable --steps 3000000 | sed 's/^/   baseline /'
  "$bench" --scene turntable --steps 3000000 | sed 's/^/   veridem /'
fi
