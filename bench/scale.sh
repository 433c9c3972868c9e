#!/usr/bin/env bash
# Scale study: bonded blocks from 882 to 1,014,300 bonds in LIGGGHTS
# (build/bin/liggghts-granbond, bench/liggghts_block.in) and in LAMMPS
# (Debian LAMMPS through build/bin/lmp-granbond, bench/lammps/block.in, the
# same block with pair_style granbond), on 1 and 2 MPI ranks.
#
# The block: n x n x n touching spheres of 2 mm on a simple-cubic lattice,
# 3 n^2 (n - 1) bonds (bond/nonlinear, full 6 DOF, percentage damping 0.1,
# the LIGGGHTS block's parameters), made in step 1, none breaks; at rest
# (-var speed 0), so every size and run length sees the same state. The
# baseline is the same block without bonds (Hertz in LIGGGHTS, Voigt in
# LAMMPS; the spheres only touch, so the baseline computes almost no
# contact forces). For every size, every engine and rank count: the bonded
# run and the baseline, alternating, ROUNDS times (default 1; the minimum
# loop time is kept), steps = BOND_STEPS / bonds (default 5e7) within
# 100 .. 20000.
#
#   ns per bond-step  (loop time with bonds - without) / (bonds x steps)
#   bytes per bond    (maximum resident set size with bonds - without)
#                     / bonds, 1 rank (/usr/bin/time -v); bench/plot_scale.py
#                     also fits the slope of the bonded RSS against bonds
#   speed-up          loop time with bonds, 1 rank / 2 ranks
#                     (mpirun -np 2 --oversubscribe, OpenMPI)
#
#   [ROUNDS=1] [BOND_STEPS=5e7] [SIZES="7 10 15 22 32 47 70"] bench/scale.sh [CSV]
#       CSV defaults to docs/figures/data/perf_scale.csv; then
#       python3 bench/plot_scale.py draws docs/figures/perf_scale.png.
#   ENGINES="liggghts lammps" RANKS="1 2": a part of the study only (its
#       rows alone in CSV; the speed-up needs rank 1)
#   CPU=1: also each run's twin with `nrun 0` (setup alone; the bonds form
#       in step 1 of the loop), and ns per bond-step from CPU time: (CPU
#       time of the run less its twin's, bonded - without) / (bonds x
#       steps), 1 rank (user + system, /usr/bin/time), minimum over the
#       rounds; on a shared host this moves less than the wall clock
# Takes minutes per round on 2 cores, and the 1e6-bond runs hold over 1 GiB
# each (docs/performance.md gives the measured figures).
# Needs the build (cmake -S . -B build && cmake --build build -j2), mpirun
# and /usr/bin/time.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
csv="${1:-$root/docs/figures/data/perf_scale.csv}"
rounds="${ROUNDS:-1}"
bond_steps="${BOND_STEPS:-5e7}"
sizes="${SIZES:-7 10 15 22 32 47 70}"
liggghts="$root/build/bin/liggghts-granbond"
lammps="$root/build/bin/lmp-granbond"
for e in "$liggghts" "$lammps"; do
    [ -x "$e" ] || { echo "scale.sh: $e missing (cmake -S . -B build && cmake --build build -j2)" >&2; exit 1; }
done
[ -x /usr/bin/time ] || { echo "scale.sh: /usr/bin/time missing (apt install time)" >&2; exit 1; }
mpi=(mpirun -np 2 --oversubscribe)
[ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# one ENGINE RANKS BONDS N STEPS: one run; prints "loop pair maxrss_kb last_bond_count cpu_s"
one() {
    local engine=$1 ranks=$2 bonds=$3 n=$4 steps=$5
    local cmd=() deck
    [ "$ranks" = 2 ] && cmd=("${mpi[@]}")
    if [ "$engine" = liggghts ]; then
        cmd+=("$liggghts" -in "$root/bench/liggghts_block.in"
              -var L "$(awk -v n="$n" 'BEGIN {print 0.002 * n + 0.004}')"
              -var Lz "$(awk -v n="$n" 'BEGIN {print 0.002 * n + 0.01}')" -var speed 0)
    else
        cmd+=("$lammps" -in "$root/bench/lammps/block.in")
    fi
    cmd+=(-var n "$n" -var nrun "$steps" -var bonds "$bonds" -log none)
    if ! (cd "$work" && /usr/bin/time -v -o time.txt "${cmd[@]}" > run.out 2>&1); then
        echo "scale.sh: failed: ${cmd[*]}" >&2; tail -20 "$work/run.out" >&2; exit 1
    fi
    local rss
    rss=$(awk -F: '/Maximum resident set size/ {gsub(/ /, "", $2); print $2}' "$work/time.txt")
    local cpu
    cpu=$(awk -F: '/User time|System time/ {t += $2} END {print t}' "$work/time.txt")
    awk -v rss="$rss" -v cpu="$cpu" -v steps="$steps" -v bonded="$bonds" -v engine="$engine" '
        /^Loop time of/ {loop = $4}
        /^Pair +\|/ {split($0, f, "|"); gsub(/ /, "", f[3]); pair = f[3]}        # LAMMPS
        /^Pair +time \(%\) =/ {pair = $5}                                        # LIGGGHTS
        engine == "liggghts" && bonded == 1 && $1 == steps {count = $4}         # thermo: c_bc[3]
        END {if (loop == "") exit 1; print loop, (pair == "" ? "nan" : pair), rss, (count == "" ? "-" : count), cpu}
    ' "$work/run.out" || { echo "scale.sh: no loop time: ${cmd[*]}" >&2; tail -20 "$work/run.out" >&2; exit 1; }
}
minimum() { awk -v a="$1" -v b="$2" 'BEGIN {print (b == "" || a + 0 < b + 0) ? a : b}'; }

mkdir -p "$(dirname "$csv")"
start=$(date +%s)
echo "scale.sh: sizes n = $sizes, $rounds round(s), $bond_steps bond-steps per run, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
{
    echo "# bench/scale.sh, $(date -u +%Y-%m-%d), ROUNDS=$rounds BOND_STEPS=$bond_steps, $(nproc) cores, load before $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "engine,ranks,n,bonds,atoms,steps,loop_bonds_s,loop_nobonds_s,pair_bonds_s,pair_nobonds_s,ns_per_bond_step,maxrss_bonds_kb,maxrss_nobonds_kb,bytes_per_bond,speedup_vs_1rank,cpu_ns_per_bond_step"
} > "$work/csv"
for n in $sizes; do
    bonds=$((3 * n * n * (n - 1)))
    atoms=$((n * n * n))
    steps=$(awk -v b="$bonds" -v t="$bond_steps" 'BEGIN {s = int(t / b + 0.5); if (s < 100) s = 100; if (s > 20000) s = 20000; print s}')
    declare -A loop=() pair=() rss=() cpu=()
    for _ in $(seq "$rounds"); do
        for ranks in ${RANKS:-1 2}; do
            for engine in ${ENGINES:-liggghts lammps}; do
                for b in 1 0; do
                    res=$(one "$engine" "$ranks" "$b" "$n" "$steps")
                    read -r l p r c u <<< "$res"
                    if [ "$engine" = liggghts ] && [ "$b" = 1 ] && [ "$c" != "$bonds" ]; then
                        echo "scale.sh: LIGGGHTS n = $n: $c bonds at the end, expected $bonds" >&2; exit 1
                    fi
                    k="$engine.$ranks.$b"
                    if [ -z "${loop[$k]:-}" ] || awk -v a="$l" -v b="${loop[$k]}" 'BEGIN {exit !(a + 0 < b + 0)}'; then
                        loop[$k]=$l; pair[$k]=$p
                    fi
                    rss[$k]=$r
                    if [ -n "${CPU:-}" ] && [ "$ranks" = 1 ]; then
                        read -r _ _ _ _ u0 <<< "$(one "$engine" "$ranks" "$b" "$n" 0)"
                        u=$(awk -v a="$u" -v b="$u0" 'BEGIN {print a - b}')
                        cpu[$k]=$(minimum "$u" "${cpu[$k]:-}")
                    fi
                done
            done
        done
    done
    for engine in ${ENGINES:-liggghts lammps}; do
        for ranks in ${RANKS:-1 2}; do
            awk -v OFS=, -v e="$engine" -v r="$ranks" -v n="$n" -v b="$bonds" -v a="$atoms" -v s="$steps" \
                -v lb="${loop[$engine.$ranks.1]}" -v ln="${loop[$engine.$ranks.0]}" \
                -v pb="${pair[$engine.$ranks.1]}" -v pn="${pair[$engine.$ranks.0]}" \
                -v rb="${rss[$engine.$ranks.1]}" -v rn="${rss[$engine.$ranks.0]}" \
                -v l1="${loop[$engine.1.1]}" -v cb="${cpu[$engine.$ranks.1]:-}" -v cn="${cpu[$engine.$ranks.0]:-}" 'BEGIN {
                ns = (lb - ln) / (b * s) * 1e9
                bpb = (r == 1) ? sprintf("%.1f", (rb - rn) * 1024 / b) : ""
                cns = (cb == "") ? "" : sprintf("%.2f", (cb - cn) / (b * s) * 1e9)
                print e, r, n, b, a, s, lb, ln, pb, pn, sprintf("%.2f", ns), rb, rn, bpb, sprintf("%.3f", l1 / lb), cns }' \
                >> "$work/csv"
        done
    done
    rows=0; for _ in ${ENGINES:-liggghts lammps}; do for _ in ${RANKS:-1 2}; do rows=$((rows + 1)); done; done
    tail -"$rows" "$work/csv" | awk -F, '{printf "  %-8s %d rank(s) %9d bonds %6d steps: loop %8.3f s (no bonds %7.3f s), %6.1f ns/bond-step%s, %s bytes/bond, speed-up %s\n",
        $1, $2, $4, $6, $7, $8, $11, ($16 == "" ? "" : " (CPU " $16 ")"), ($14 == "" ? "-" : $14), $15}'
    unset loop pair rss cpu
done
echo "# load after $(cut -d' ' -f1-3 /proc/loadavg), $(( $(date +%s) - start )) s" >> "$work/csv"
cp "$work/csv" "$csv"
echo "scale.sh: $(( $(date +%s) - start )) s; wrote $csv"
