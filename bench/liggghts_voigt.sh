#!/usr/bin/env bash
# Throughput of the voigt contact in LIGGGHTS against the stock model it is
# meant to replace, on the same collapsing packing (bench/liggghts_voigt_heap.in):
#   voigt:  model voigt tangential voigt rolling_friction voigt
#   stock:  model hooke/stiffness tangential history rolling_friction epsd2 (absolute damping)
# Both runs see the same contacts (same pair/wall contact calls, within 0.3%).
#
#   bench/liggghts_voigt.sh <launcher> [steps] [repeat]
#       wall clock: loop time of the timed run, best of `repeat` (alternating),
#       and the ratio stock/voigt (1.0 = as fast as stock; target >= 0.95)
#   bench/liggghts_voigt.sh --callgrind <launcher>
#       instructions executed (valgrind --tool=callgrind, whole program) on a
#       smaller block (8 x 8 x 10 spheres, 500 + 200 steps): load-independent,
#       the fair measure on a shared machine
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
deck="$here/liggghts_voigt_heap.in"
VOIGT=("model voigt tangential voigt rolling_friction voigt" "noAttraction on")
STOCK=("model hooke/stiffness tangential history rolling_friction epsd2" "absolute_damping on")

if [[ "${1:-}" == "--callgrind" ]]; then
    engine="${2:?usage: $0 --callgrind <liggghts launcher with the granbond models>}"
    work="$(mktemp -d)"
    trap 'rm -rf "$work"' EXIT
    instructions() {  # models settings -> instructions executed
        (cd "$work" && valgrind --tool=callgrind --callgrind-out-file=cg.out "$engine" -in "$deck" -log none \
            -var n 8 -var nz 10 -var nrun 200 -var models "$1" -var settings "$2" 2>&1 >/dev/null) |
            awk '/Collected :/ { print $NF }'
    }
    v=$(instructions "${VOIGT[@]}")
    s=$(instructions "${STOCK[@]}")
    echo "640 spheres, 700 steps, instructions executed (callgrind Ir)"
    echo "voigt  $v"
    echo "stock  $s"
    awk -v v="$v" -v s="$s" 'BEGIN { printf "throughput ratio voigt/stock = %.3f (target >= 0.95)\n", s / v }'
    exit 0
fi

engine="${1:?usage: $0 <liggghts launcher with the granbond models> [steps] [repeat]}"
steps="${2:-3000}"
repeat="${3:-3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

loop_time() {  # models settings -> seconds of the timed run
    (cd "$work" && "$engine" -in "$deck" -log none -var nrun "$steps" -var models "$1" -var settings "$2") |
        awk '/^Loop time/ { t = $4 } END { print t }'
}

best_voigt=""; best_stock=""
for _ in $(seq "$repeat"); do
    v=$(loop_time "${VOIGT[@]}")
    s=$(loop_time "${STOCK[@]}")
    best_voigt=$(awk -v a="$v" -v b="$best_voigt" 'BEGIN { print (b == "" || a < b) ? a : b }')
    best_stock=$(awk -v a="$s" -v b="$best_stock" 'BEGIN { print (b == "" || a < b) ? a : b }')
done
echo "steps $steps (5120 spheres, best of $repeat)"
echo "voigt  loop time ${best_voigt} s"
echo "stock  loop time ${best_stock} s"
awk -v v="$best_voigt" -v s="$best_stock" 'BEGIN { printf "throughput ratio voigt/stock = %.3f (target >= 0.95)\n", s / v }'
