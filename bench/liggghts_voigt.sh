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
#   bench/liggghts_voigt.sh --interleaved <launcher> [steps (300)] [rounds (10)]
#       wall clock on a shared machine: one process alternates voigt and stock
#       (pair style and walls replaced every `steps` steps, `rounds` times
#       each), so both meet the same load; best and median loop time of each,
#       ratio of the best and of the medians
#   bench/liggghts_voigt.sh --call
#       the core's per-contact call alone (bench/liggghts_voigt_call.c against
#       target/release/libgranbond.a): ns per contact, frame entry and fields
#       entry, best of 300 short passes (robust to machine load)
#   bench/liggghts_voigt.sh --callgrind <launcher>
#       instructions executed (valgrind --tool=callgrind, whole program) on a
#       smaller block (8 x 8 x 10 spheres, 500 + 200 steps): load-independent,
#       the fair measure on a shared machine
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
deck="$here/liggghts_voigt_heap.in"
VOIGT=("model voigt tangential voigt rolling_friction voigt" "noAttraction on")
STOCK=("model hooke/stiffness tangential history rolling_friction epsd2" "absolute_damping on")
# the launcher as a path that still holds after `cd` into a work directory
# (a bare command name is left to PATH)
absolute() { if [[ "$1" == */* ]]; then echo "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"; else echo "$1"; fi; }

if [[ "${1:-}" == "--call" ]]; then
    root="$(cd "$here/.." && pwd)"
    library="${CARGO_TARGET_DIR:-$root/target}/release/libgranbond.a"
    [ -f "$library" ] || { echo "build first: cmake --build build (or cargo build --release -p granbond)" >&2; exit 1; }
    work="$(mktemp -d)"
    trap 'rm -rf "$work"' EXIT
    cc -O2 -std=c99 -D_POSIX_C_SOURCE=199309L -I"$root/rust-core/include" "$here/liggghts_voigt_call.c" "$library" \
        -lpthread -ldl -lm -o "$work/call"
    "$work/call"
    exit 0
fi

if [[ "${1:-}" == "--interleaved" ]]; then
    engine="${2:?usage: $0 --interleaved <liggghts launcher with the granbond models> [steps] [rounds]}"
    engine="$(absolute "$engine")"
    steps="${3:-300}"
    rounds="${4:-10}"
    work="$(mktemp -d)"
    trap 'rm -rf "$work"' EXIT
    (cd "$work" && "$engine" -in "$deck" -log none -var nrun "$steps" -var alternate "$rounds" \
        -var models "${VOIGT[0]}" -var settings "${VOIGT[1]}" -var models2 "${STOCK[0]}" -var settings2 "${STOCK[1]}") |
        awk '/^Loop time/ { print $4 }' | tail -n +2 > "$work/times"
    [ "$(wc -l < "$work/times")" -eq $((2 * rounds)) ] || { echo "bench: the interleaved run failed" >&2; exit 1; }
    # odd lines voigt, even lines stock
    awk 'NR % 2 == 1' "$work/times" | sort -g > "$work/voigt"
    awk 'NR % 2 == 0' "$work/times" | sort -g > "$work/stock"
    stats() { awk -f "$here/best_and_median.awk" "$1"; }
    read -r vb vm <<< "$(stats "$work/voigt")"
    read -r sb sm <<< "$(stats "$work/stock")"
    echo "5120 spheres, $rounds x $steps steps each, alternating in one process"
    echo "voigt  loop time best $vb s, median $vm s"
    echo "stock  loop time best $sb s, median $sm s"
    awk -v vb="$vb" -v sb="$sb" -v vm="$vm" -v sm="$sm" 'BEGIN {
        printf "throughput ratio voigt/stock = %.3f (best), %.3f (median) (target >= 0.95)\n", sb / vb, sm / vm }'
    exit 0
fi

if [[ "${1:-}" == "--callgrind" ]]; then
    engine="${2:?usage: $0 --callgrind <liggghts launcher with the granbond models>}"
    engine="$(absolute "$engine")"
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
engine="$(absolute "$engine")"
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
