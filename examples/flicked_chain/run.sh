#!/usr/bin/env bash
# The flicked chain in both history modes, in LIGGGHTS (build/bin/liggghts-granbond)
# and in LAMMPS (build/bin/lmp-granbond), then plot.py: out/flicked_chain.png.
# About 10 s. Needs the build (cmake -S . -B build && cmake --build build -j2).
#   examples/flicked_chain/run.sh [-var nrun 100000 ...]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
liggghts="$root/build/bin/liggghts-granbond"
lammps="$root/build/bin/lmp-granbond"
[ -x "$liggghts" ] || { echo "build first: cmake -S . -B build && cmake --build build -j2" >&2; exit 1; }
rm -rf "$here/out"
mkdir -p "$here/out"
cd "$here/out"
for reset in off on; do
    echo "== LIGGGHTS, historyReset $reset"
    mkdir -p "liggghts_$reset"
    (cd "liggghts_$reset" && "$liggghts" -in "$here/in.flicked_chain" -var params "$here/params.in" -var here "$here" \
        -var reset "$reset" -log log.liggghts "$@" >/dev/null)
    if [ -x "$lammps" ]; then
        echo "== LAMMPS, history_reset $reset"
        mkdir -p "lammps_$reset"
        (cd "lammps_$reset" && "$lammps" -in "$here/in.flicked_chain_lammps" -var params "$here/params.in" -var here "$here" \
            -var reset "$reset" -log log.lammps "$@" >/dev/null)
    fi
done
python3 "$here/plot.py" .
