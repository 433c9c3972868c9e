#!/usr/bin/env bash
# Instructions per bond-step of the AVX2 lane step for each set of switches
# (rust-core/examples/scattered_cost.rs under valgrind callgrind): the
# difference of 11 sweeps and 1 sweep over 10,000 bonds, per bond-step.
#
#   cargo build --release -p granbond --example scattered_cost
#   bench/scattered_cost.sh [binary] [path] [switched]
#
# binary defaults to target/release/examples/scattered_cost, path to avx2
# (single | scalar | avx2); `switched` measures the steps that read the
# switches at run time instead of the ones compiled for each set.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
binary="${1:-${CARGO_TARGET_DIR:-$root/target}/release/examples/scattered_cost}"
path="${2:-avx2}"
mode="${3:-}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
ir() {
    valgrind --tool=callgrind --callgrind-out-file="$work/cg" "$binary" "$path" "$1" "$2" $mode \
        >/dev/null 2>"$work/log"
    awk '/^summary:/ { print $2 }' "$work/cg"
}
for variant in full_6dof no_twist no_bend normal_shear normal_only tension_only; do
    one="$(ir 1 "$variant")"
    eleven="$(ir 11 "$variant")"
    awk -v a="$one" -v b="$eleven" -v v="$variant" -v p="$path" -v m="$mode" \
        'BEGIN { printf "%-13s %s %s %8.1f instructions per bond-step\n", v, p, m, (b - a) / 100000 }'
done
