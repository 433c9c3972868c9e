#!/usr/bin/env bash
# LIGGGHTS throughput figures of granbond, measured in one run on the same decks:
#   1. voigt vs the built-in hooke/stiffness + tangential history +
#      rolling_friction epsd2 (bench/liggghts_voigt_heap.in, 5120 spheres)
#   2. bond/nonlinear on vs off on the flagship agglomerate
#      (examples/agglomerate_liggghts, 3603 spheres, 9946 bonds, dumps off)
#   3. launcher (build/bin/liggghts-granbond) vs LD_PRELOAD into the stock
#      liggghts, on the agglomerate with bonds
#   4. 1 vs 2 MPI ranks, on the agglomerate with bonds
#   5. the bond's cost in ns per bond-step: a 20x20x20 bonded block hitting a
#      wall (bench/liggghts_block.in, 22,800 bonds, none breaks):
#      (loop time with bonds - loop time without) / (bonds x steps)
# Every figure is the minimum loop time ("Loop time" of LIGGGHTS) of `repeat`
# runs, the variants alternating: the machine is shared, the minimum is the
# least disturbed run.
#
#   bench/liggghts_bench.sh [repeat (3)] [steps (1000)]
#   bench/liggghts_bench.sh --callgrind
#       load-independent: instructions executed (valgrind callgrind) per
#       bond-step on a 10x10x10 block (2,700 bonds, 300 steps), with minus
#       without bonds
# Needs the build (cmake -S . -B build && cmake --build build -j2).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
repeat="${1:-3}"
steps="${2:-1000}"
launcher="$root/build/bin/liggghts-granbond"
library="$root/build/lib/libgranbond_liggghts.so"
stock="$(command -v liggghts || true)"
agg="$root/examples/agglomerate_liggghts/in.agglomerate_liggghts"
block="$root/bench/liggghts_block.in"
heap="$root/bench/liggghts_voigt_heap.in"
[ -x "$launcher" ] || { echo "build first: cmake -S . -B build && cmake --build build -j2" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

if [[ "$repeat" == "--callgrind" ]]; then
    instructions() {  # bonds -> instructions executed
        (cd "$work" && valgrind --tool=callgrind --callgrind-out-file=cg.out "$launcher" -in "$block" -log none \
            -var n 10 -var nrun 300 -var bonds "$1" 2>&1 >/dev/null) | awk '/Collected :/ { print $NF }'
    }
    with=$(instructions 1)
    without=$(instructions 0)
    echo "10x10x10 block, 300 steps, instructions executed (callgrind Ir): bonds $with, Hertz only $without"
    awk -v a="$with" -v b="$without" 'BEGIN {
        printf "bond cost: %.0f instructions per bond-step ((with - without) / (2700 bonds x 300 steps))\n",
               (a - b) / (2700 * 300) }'
    exit 0
fi
mpi=(mpirun -np 2 --oversubscribe)
[ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)

# loop NAME COMMAND... : runs once, appends the loop time (s) to $work/NAME
loop() {
    local name=$1; shift
    local t
    t=$(cd "$work" && "$@" -log none 2>&1 | awk '/^Loop time/ { t = $4 } END { print t }')
    [ -n "$t" ] || { echo "bench: $name failed: $*" >&2; exit 1; }
    echo "$t" >> "$work/$name"
}
best() { sort -g "$work/$1" | head -1; }

V="model voigt tangential voigt rolling_friction voigt"
S="model hooke/stiffness tangential history rolling_friction epsd2"
echo "liggghts_bench: $repeat rounds, $steps steps per run, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for k in $(seq "$repeat"); do
    echo "  round $k/$repeat"
    loop voigt "$launcher" -in "$heap" -var nrun "$steps" -var models "$V" -var settings "noAttraction on"
    loop stock "$launcher" -in "$heap" -var nrun "$steps" -var models "$S" -var settings "absolute_damping on"
    loop agg_bonds "$launcher" -in "$agg" -var nrun "$steps" -var dumps 0
    loop agg_nobonds "$launcher" -in "$agg" -var nrun "$steps" -var dumps 0 -var bonds 0
    if [ -n "$stock" ]; then
        loop agg_preload env LD_PRELOAD="$library" "$stock" -in "$agg" -var nrun "$steps" -var dumps 0
    fi
    loop agg_np2 "${mpi[@]}" "$launcher" -in "$agg" -var nrun "$steps" -var dumps 0
    loop block_bonds "$launcher" -in "$block" -var nrun "$steps"
    loop block_nobonds "$launcher" -in "$block" -var nrun "$steps" -var bonds 0
done

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", a / b }'; }
echo
echo "minimum loop time of $repeat runs, $steps steps each (s)"
printf "  %-58s %8s\n" "heap, voigt (5120 spheres)" "$(best voigt)"
printf "  %-58s %8s\n" "heap, hooke/stiffness + history + epsd2" "$(best stock)"
printf "  %-58s %8s\n" "agglomerate, bond/nonlinear, launcher" "$(best agg_bonds)"
printf "  %-58s %8s\n" "agglomerate, Hertz only (bonds off)" "$(best agg_nobonds)"
[ -n "$stock" ] && printf "  %-58s %8s\n" "agglomerate, bond/nonlinear, LD_PRELOAD into $stock" "$(best agg_preload)"
printf "  %-58s %8s\n" "agglomerate, bond/nonlinear, launcher, 2 MPI ranks" "$(best agg_np2)"
printf "  %-58s %8s\n" "block 20^3, bond/nonlinear (22,800 bonds)" "$(best block_bonds)"
printf "  %-58s %8s\n" "block 20^3, Hertz only" "$(best block_nobonds)"
echo
echo "ratios"
echo "  voigt throughput / built-in (stock time / voigt time; target >= 0.95):  $(ratio "$(best stock)" "$(best voigt)")"
echo "  agglomerate time, bonds on / off:                                       $(ratio "$(best agg_bonds)" "$(best agg_nobonds)")"
[ -n "$stock" ] && echo "  agglomerate time, LD_PRELOAD / launcher:                                $(ratio "$(best agg_preload)" "$(best agg_bonds)")"
echo "  agglomerate speed-up, 2 MPI ranks vs 1:                                $(ratio "$(best agg_bonds)" "$(best agg_np2)")"
awk -v a="$(best block_bonds)" -v b="$(best block_nobonds)" -v s="$steps" 'BEGIN {
    printf "  bond cost in LIGGGHTS: (%.3f - %.3f) s / (22800 bonds x %d steps) = %.1f ns per bond-step (target <= 60)\n",
           a, b, s, (a - b) / (22800 * s) * 1e9 }'
