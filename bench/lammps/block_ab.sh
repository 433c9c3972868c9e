#!/usr/bin/env bash
# Two builds of lmp-granbond on the bonded block of bench/scale.sh
# (bench/lammps/block.in, n^3 touching spheres at rest, 3 n^2 (n - 1)
# bonds, 1 rank), alternating in one window: for each size and round, each
# build's ns per bond-step = (loop time with bonds - without) / (bonds x
# steps), steps = 5e7 / bonds within 100-20000.
#
#   [ROUNDS=2] [SIZES="22 47 70"] bench/lammps/block_ab.sh LMP_A LMP_B
#       LMP_A, LMP_B: lmp-granbond binaries (e.g. build/bin/lmp-granbond of
#       two worktrees)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
[ $# -eq 2 ] || { sed -n 2,11p "$0"; exit 2; }
a="$(realpath "$1")"
b="$(realpath "$2")"
rounds="${ROUNDS:-2}"
sizes="${SIZES:-22 47 70}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
loop() {  # binary n steps bonds -> loop time
    local t
    t=$( (cd "$work" && "$1" -in "$root/bench/lammps/block.in" -var n "$2" -var nrun "$3" -var bonds "$4" \
          -log none) 2>&1 | awk '/^Loop time of/ {print $4}')
    [ -n "$t" ] || { echo "block_ab.sh: no loop time from $1 (n $2, bonds $4)" >&2; exit 1; }
    echo "$t"
}
for round in $(seq "$rounds"); do
    for n in $sizes; do
        bonds=$((3 * n * n * (n - 1)))
        steps=$(awk -v b="$bonds" 'BEGIN {s = int(5e7 / b + 0.5); if (s < 100) s = 100; if (s > 20000) s = 20000; print s}')
        for name in A B; do
            if [ "$name" = A ]; then bin="$a"; else bin="$b"; fi
            with=$(loop "$bin" "$n" "$steps" 1)
            without=$(loop "$bin" "$n" "$steps" 0)
            awk -v r="$round" -v v="$name" -v b="$bonds" -v s="$steps" -v w="$with" -v o="$without" \
                -v load="$(cut -d' ' -f1 /proc/loadavg)" 'BEGIN {
                printf "round %d  %s  %9d bonds  %5d steps  loop %.3f s (no bonds %.3f s)  %6.1f ns/bond-step  load %s\n",
                       r, v, b, s, w, o, (w - o) / (b * s) * 1e9, load }'
        done
    done
done
