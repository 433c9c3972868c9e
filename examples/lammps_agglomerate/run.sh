#!/usr/bin/env bash
# The LAMMPS agglomerate impact (in.lammps_agglomerate) with
# build/bin/lmp-granbond, then the bond network as VTK (out/vtk/bonds.pvd,
# breaks.pvd: tools/bonds_to_vtk.py) and its picture (network.png:
# tools/plot_bond_network.py), and the bonds' energy budget over time
# (budget.png: plot_budget.py). Needs the build.
#   examples/lammps_agglomerate/run.sh [-var nrun 5000 ...]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
lmp="$root/build/bin/lmp-granbond"
[ -x "$lmp" ] || { echo "build first: cmake -S . -B build && cmake --build build -j2" >&2; exit 1; }
rm -rf "$here/out"
mkdir -p "$here/out"
cd "$here/out"
"$lmp" -in "$here/in.lammps_agglomerate" -log log.lammps "$@" >/dev/null
cols="id pos status stretch normal_force shear_force sigma_ratio tau_ratio"
python3 "$root/tools/bonds_to_vtk.py" bonds.dump --columns "$cols" --breaklog breaks.txt --out vtk
last=$(awk '!/^#/ {s=$1} END {print s}' counts.txt)
python3 "$root/tools/plot_bond_network.py" vtk --steps 250 1000 "$last" --field sigma_ratio --view xz \
    --title "LAMMPS pair granbond: intact bonds coloured by sigma/sigma_max, broken bonds by mode" \
    --out "$here/network.png"
python3 "$here/plot_budget.py" energy.txt "$here/budget.png"
tail -n 1 counts.txt
