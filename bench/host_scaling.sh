#!/usr/bin/env bash
# What this host gives a second process: each measurement of
# bench/host_scaling.c run alone, then two copies at once (as 2 MPI ranks
# on 2 cores), and the two copies' summed rate over the one copy's. The
# speed-up of 2 ranks over 1 (bench/scale.sh) cannot pass the ratio of the
# resource its work waits on:
#   compute   arithmetic in registers (the core's lanes in cache)
#   CACHE     an array that fits in the caches, read and written back
#   MEMORY    one that does not (the rows of a million bonds)
#
#   [REPS=5] bench/host_scaling.sh [CACHE_MIB (8)] [MEMORY_MIB (512)]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
reps="${REPS:-5}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cc -O2 -o "$work/probe" "$root/bench/host_scaling.c"
echo "host_scaling.sh: $(nproc) cores, $(awk -F: '/model name/ {print $2; exit}' /proc/cpuinfo | sed 's/^ *//'), load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u '+%Y-%m-%d %H:%M') UTC"
for what in compute "${1:-8}" "${2:-512}"; do
    one=$("$work/probe" "$what" "$reps" | cut -d' ' -f1)
    "$work/probe" "$what" "$reps" > "$work/a" &
    "$work/probe" "$what" "$reps" > "$work/b"
    wait
    a=$(cut -d' ' -f1 "$work/a")
    b=$(cut -d' ' -f1 "$work/b")
    label="$what MiB"
    unit="GB/s"
    [ "$what" = compute ] && { label="compute"; unit="G mult-adds/s"; }
    awk -v l="$label" -v u="$unit" -v one="$one" -v a="$a" -v b="$b" 'BEGIN {
        printf "  %-9s one copy %7.2f %s; two at once %7.2f + %7.2f = %.2fx one copy\n", l, one, u, a, b, (a + b) / one }'
done
