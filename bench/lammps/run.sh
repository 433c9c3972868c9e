#!/usr/bin/env bash
# Throughput of pair_style granbond (voigt) against pair_style granular with
# the matching sub-models (hooke + damping velocity + limit_damping +
# tangential linear_history) on the same deck: a periodic simple-cubic
# packing of 8000 spheres, 6 overlapping neighbours each. REPEAT alternating
# runs of each (default 1); the minimum loop and Pair times are kept.
# Prints both and the ratios granular/granbond (> 1: granbond faster).
#
#   [REPEAT=5] bench/lammps/run.sh [NRUN]
#   [REPEAT=3] bench/lammps/run.sh --bonds [NRUN (1000)]
#       the bond's cost in LAMMPS: the same packing with every touching pair
#       bonded (bond/nonlinear, full 6 DOF, damping, none breaks) against
#       voigt alone, both pair granbond; (Pair time with bonds - without) /
#       (bond computations x steps), ns per bond-step
#   bench/lammps/run.sh --interleaved [NRUN (300)] [ROUNDS (10)]
#       both styles taking turns in one lmp-granbond process (interleaved.in),
#       so that both meet the same machine load: best and median Pair time of
#       each, and the ratios of the best and of the medians
#
# Needs build/bin/lmp-granbond and Debian's /usr/bin/lmp (LMP overrides;
# the PyPI wheel's `lmp` may come first on PATH).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$here/../.."
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "pair_style granbond
pair_coeff * * voigt 1e4 1e-3 6e3 1e-3 0.5" > "$out/granbond.in"
echo "pair_style granular
pair_coeff * * hooke 1e4 1e-3 damping velocity limit_damping tangential linear_history 6e3 1 0.5" > "$out/granular.in"
granbond_lmp="${LMP_GRANBOND:-$root/build/bin/lmp-granbond}"
min() { awk -v a="$1" -v b="$2" 'BEGIN {print (b == "" || a + 0 < b + 0) ? a : b}'; }

if [[ "${1:-}" == "--interleaved" ]]; then
    nrun="${2:-300}"
    rounds="${3:-10}"
    (cd "$out" && "$granbond_lmp" -in "$here/interleaved.in" -var dir "$here" -var work "$out" \
        -var model "$out/granular.in" -var model2 "$out/granbond.in" -var nrun "$nrun" -var rounds "$rounds" \
        -log "$out/interleaved.log" >/dev/null)
    # Pair times of the runs in order: odd granular, even granbond
    awk '/^Pair +\|/ { print $3 }' "$out/interleaved.log" > "$out/pair"
    [ "$(wc -l < "$out/pair")" -eq $((2 * rounds)) ] || { echo "bench: the interleaved run failed" >&2; exit 1; }
    awk 'NR % 2 == 1' "$out/pair" | sort -g > "$out/granular"
    awk 'NR % 2 == 0' "$out/pair" | sort -g > "$out/granbond"
    stats() { awk -f "$here/../best_and_median.awk" "$1"; }
    read -r gb gm <<< "$(stats "$out/granular")"
    read -r bb bm <<< "$(stats "$out/granbond")"
    echo "8000 spheres, $rounds x $nrun steps each, alternating in one process"
    echo "pair granular          Pair time best $gb s, median $gm s"
    echo "pair granbond (voigt)  Pair time best $bb s, median $bm s"
    awk -v gb="$gb" -v bb="$bb" -v gm="$gm" -v bm="$bm" 'BEGIN {
        printf "throughput ratio granbond/granular = %.3f (best), %.3f (median) (target >= 1.0)\n", gb / bb, gm / bm }'
    exit 0
fi

if [[ "${1:-}" == "--bonds" ]]; then
    nrun="${2:-1000}"
    repeat="${REPEAT:-3}"
    echo "pair_style granbond
pair_coeff * * voigt 1e4 1e-3 6e3 1e-3 0.5 bond/nonlinear lambda 1.0 k_fn1 1.58e8 ku_fn1 3.16e8 kc_fn1 1.58e7 \
  k_fn2 5e10 ku_fn2 1e11 kc_fn2 5e9 k_ft 2e10 k_tn 2e10 ku_tn 4e10 kc_tn 2e9 k_tt 2e10 ku_tt 4e10 kc_tt 2e9 \
  eta_fn 0.1 eta_ft 0.1 eta_tn 0.1 eta_tt 0.1 create_distance 2.05e-3 create_step 1 break distance 2.5e-3" \
        > "$out/bonded.in"
    pair_time() {  # model -> Pair time (s); the bond computations of a step go to $out/$1.bonds
        (cd "$out" && "$granbond_lmp" -in "$here/packing.in" -var dir "$here" -var model "$out/$1.in" \
            -var nrun "$nrun" -log "$1.log" >/dev/null)
        awk '/^Pair +\|/ {pair = $3} END {print pair}' "$out/$1.log"
    }
    with="" without=""
    for _ in $(seq "$repeat"); do
        with=$(min "$(pair_time bonded)" "$with")
        without=$(min "$(pair_time granbond)" "$without")
    done
    # periodic simple-cubic packing, newton off: 3 bonds per sphere, and the
    # 3 x 20^2 pairs across the periodic boundary are computed from both
    # sides (local-ghost), as every contact is
    bonds=$((3 * 8000 + 3 * 400))
    echo "packing, 8000 spheres, $nrun steps, minimum Pair time of $repeat runs: bonded $with s, voigt only $without s"
    awk -v a="$with" -v b="$without" -v n="$bonds" -v s="$nrun" 'BEGIN {
        printf "bond cost in LAMMPS: (%.3f - %.3f) s / (%d bond computations x %d steps) = %.1f ns per bond-step\n",
               a, b, n, s, (a - b) / (n * s) * 1e9 }'
    exit 0
fi

nrun="${1:-3000}"
repeat="${REPEAT:-1}"
# prints "loop pair" (seconds) of one run
times() {
    (cd "$out" && "$1" -in "$here/packing.in" -var dir "$here" -var model "$out/$2.in" -var nrun "$nrun" \
        -log "$2.log" >/dev/null)
    awk '/^Loop time of/ {loop = $4} /^Pair +\|/ {pair = $3} END {print loop, pair}' "$out/$2.log"
}
gl="" gp="" bl="" bp=""
for _ in $(seq "$repeat"); do
    read -r l p < <(times "${LMP:-/usr/bin/lmp}" granular)
    gl=$(min "$l" "$gl"); gp=$(min "$p" "$gp")
    read -r l p < <(times "$granbond_lmp" granbond)
    bl=$(min "$l" "$bl"); bp=$(min "$p" "$bp")
done
echo "pair granular: loop ${gl} s (Pair ${gp} s), pair granbond (voigt): loop ${bl} s (Pair ${bp} s)"
echo "  for $nrun steps, 8000 spheres, minimum of $repeat run(s) each"
awk -v a="$gl" -v b="$bl" -v c="$gp" -v d="$bp" \
    'BEGIN {printf "throughput ratio granbond/granular = %.2fx (loop), %.2fx (Pair)\n", a / b, c / d}'
