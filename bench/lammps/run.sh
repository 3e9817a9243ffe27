#!/bin/sh
# Runs LAMMPS (Debian package `lammps`, binary lmp) on the reference bed and gas with 1 and 2 MPI
# ranks. Prints each run's loop time; particle-steps/s = 20000 * steps / loop time.
#   bench/lammps/run.sh [steps]
set -e
here=$(cd "$(dirname "$0")" && pwd)
shared=${VERIDEM_SHARED_BENCH_DIR:-$here/../../../shared/bench}
steps=${1:-10000}
work=$(mktemp -d)
python3 "$here/xyz_to_data.py" "$shared/settled_bed_20k.xyz" "$work/bed.data" 0.05
python3 "$here/xyz_to_data.py" "$shared/random_gas_20k.xyz" "$work/gas.data" 0.32
for scene in bed gas; do
  for ranks in 1 2; do
    echo "== LAMMPS $scene, $ranks rank(s), $steps steps"
    mpirun --allow-run-as-root --oversubscribe -np $ranks lmp -in "$here/bed.in" -var data "$work/$scene.data" \
      -var steps "$steps" -log "$work/$scene.$ranks.log" -nocite | grep -E "Loop time|^ +$steps +" || true
  done
done
rm -rf "$work"
