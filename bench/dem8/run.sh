#!/bin/sh
# Runs one DEM8 benchmark scene of this folder (bench/dem8/README.md) with veridem:
#
#   bench/dem8/run.sh CASE [OUT_DIR] [veridem run options...]     e.g. bench/dem8/run.sh impact_25k
#
# CASE is a scene name (impact_25k, impact_50k, drum, silo_M1_small, silo_M1_large, silo_M2_small,
# silo_M2_large). The scenes name the organisers' data as ../../../shared/dem8/... (the shared
# folder beside the repository); with VERIDEM_SHARED_DEM8_DIR set, a copy of the scene naming
# that folder is written to OUT_DIR and run instead. VERIDEM (default build/release/src/app/veridem)
# is the program.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
case=${1:?usage: bench/dem8/run.sh CASE [OUT_DIR] [options...]}
out=${2:-$root/out/dem8/$case}
[ $# -ge 2 ] && shift 2 || shift 1
veridem=${VERIDEM:-$root/build/release/src/app/veridem}
scene="$here/$case.toml"
[ -f "$scene" ] || { echo "run.sh: no scene '$scene'" >&2; exit 2; }
mkdir -p "$out"
if [ -n "${VERIDEM_SHARED_DEM8_DIR:-}" ]; then
  shared=$(cd "$VERIDEM_SHARED_DEM8_DIR" && pwd)
  sed "s#\.\./\.\./\.\./shared/dem8#$shared#g" "$scene" > "$out/$case.toml"
  scene="$out/$case.toml"
fi
exec "$veridem" run "$scene" --out "$out" "$@"
