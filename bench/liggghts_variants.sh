#!/usr/bin/env bash
# Cost of each bond/nonlinear model variant inside LIGGGHTS, on the flagship
# agglomerate (examples/agglomerate_liggghts: 3,603 spheres, 9,946 bonds,
# impact at 3 m/s, dumps off), the variants chosen by the deck's `bondopts`
# variable (the switches of cohesion bond/nonlinear):
#   full 6-DOF; no twist (normalTorqueStress off); normal + shear (twist and
#   bend off); normal only (shear off too); damping off; smooth damping;
#   and no bonds at all (-var bonds 0: Hertz contacts only).
# Each figure is the minimum loop time ("Loop time" of LIGGGHTS) of `repeat`
# runs, the variants alternating (the machine is shared; the minimum is the
# least disturbed run).
#
#   bench/liggghts_variants.sh [repeat (3)] [steps (1000)]
#
# Columns: loop time (s); wall seconds per simulated second (loop / (steps dt),
# dt = 1e-6 s); bond-steps (intact bonds summed over the steps, from the
# thermo's bond counter every 100 steps, trapezoidal, the count at step 0
# taken as that of step 100 since bonds are created at step 1; bonds break after the
# impact, at a rate that depends on the variant); ns per bond-step relative
# to no bonds: (loop - loop without bonds) / bond-steps.
# Needs the build (cmake -S . -B build && cmake --build build -j2).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
repeat="${1:-3}"
steps="${2:-1000}"
every=100
launcher="$root/build/bin/liggghts-granbond"
agg="$root/examples/agglomerate_liggghts/in.agglomerate_liggghts"
[ -x "$launcher" ] || { echo "build first: cmake -S . -B build && cmake --build build -j2" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

names=(full notwist normalshear normal nodamping smooth nobonds)
declare -A label opts
label[full]="full 6-DOF";                      opts[full]="stressBreak on"
label[notwist]="no twist";                     opts[notwist]="stressBreak on normalTorqueStress off"
label[normalshear]="normal + shear (no twist/bend)"
opts[normalshear]="stressBreak on normalTorqueStress off shearTorqueStress off"
label[normal]="normal only";                   opts[normal]="stressBreak on normalTorqueStress off shearTorqueStress off shearStress off"
label[nodamping]="full, damping off";          opts[nodamping]="stressBreak on dampingBond off"
label[smooth]="full, smooth damping";          opts[smooth]="stressBreak on dampingBondSmooth on"
label[nobonds]="no bonds (Hertz only)";        opts[nobonds]="stressBreak on"

# run NAME: runs the variant once, appends its loop time (s) to $work/NAME.t
# and writes its bond-steps to $work/NAME.b
run() {
    local name=$1 bonds=1 out
    [ "$name" = nobonds ] && bonds=0
    out=$(cd "$work" && "$launcher" -in "$agg" -log none -var nrun "$steps" -var dumps 0 -var every "$every" \
        -var bonds "$bonds" -var bondopts "${opts[$name]}" 2>&1) || { echo "$out" >&2; echo "bench: $name failed" >&2; exit 1; }
    echo "$out" | awk '/^Loop time/ { print $4 }' >> "$work/$name.t"
    # thermo rows: step time atoms ke zmin intact broken cpu (bonds) / 6 columns (no bonds)
    echo "$out" | awk -v e="$every" '
        /^ *Step/ { on = 1; next } /^Loop time/ { on = 0 }
        on && $1 ~ /^[0-9]+$/ { n++; v[n] = (NF >= 8) ? $6 : 0 }
        END { if (n > 1 && v[1] == 0) v[1] = v[2]   # bonds are created at step 1
              s = 0; for (i = 2; i <= n; i++) s += (v[i - 1] + v[i]) / 2 * e; printf "%.0f\n", s }' > "$work/$name.b"
}
best() { sort -g "$work/$1.t" | head -1; }

echo "liggghts_variants: $repeat rounds, $steps steps per run, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for k in $(seq "$repeat"); do
    echo "  round $k/$repeat"
    for n in "${names[@]}"; do run "$n"; done
done
echo "  load at the end $(cut -d' ' -f1-3 /proc/loadavg)"

base=$(best nobonds)
echo
echo "minimum loop time of $repeat runs, $steps steps each (dt = 1e-6 s)"
printf "| %-32s | %8s | %12s | %11s | %13s |\n" "variant" "loop (s)" "wall s / s" "bond-steps" "ns/bond-step"
printf "|%s|%s|%s|%s|%s|\n" "----------------------------------" "----------" "--------------" "-------------" "---------------"
for n in "${names[@]}"; do
    awk -v l="${label[$n]}" -v t="$(best "$n")" -v b="$(cat "$work/$n.b")" -v t0="$base" -v s="$steps" 'BEGIN {
        ns = (b > 0) ? sprintf("%.0f", (t - t0) / b * 1e9) : "-"
        printf "| %-32s | %8.3f | %12.0f | %11.4g | %13s |\n", l, t, t / (s * 1e-6), b, ns }'
done
