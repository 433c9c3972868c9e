#!/usr/bin/env bash
# Runs the oblique collision with pair_style granbond (voigt) and with
# pair_style granular, then plot.py: out/voigt_vs_granular.png.
#   examples/lammps_voigt_vs_granular/run.sh   (needs build/bin/lmp-granbond and Debian's /usr/bin/lmp)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$here/../.."
mkdir -p "$here/out"
cd "$here/out"
"${LMP_GRANBOND:-$root/build/bin/lmp-granbond}" -in ../in.lammps_voigt_vs_granular \
    -var model ../granbond.in -var out granbond.txt -log granbond.log >/dev/null
"${LMP:-/usr/bin/lmp}" -in ../in.lammps_voigt_vs_granular \
    -var model ../granular.in -var out granular.txt -log granular.log >/dev/null
python3 ../plot.py .
