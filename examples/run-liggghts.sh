#!/usr/bin/env bash
# Runs one LIGGGHTS example and its plotting script:
#   examples/run-liggghts.sh NAME [-var K V ...]
# runs examples/NAME/in.NAME with build/bin/liggghts-granbond in
# examples/NAME/out (emptied first), then examples/NAME/plot.py out.
# Needs the build (cmake -S . -B build && cmake --build build -j2).
# NP=2 runs on two MPI ranks.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
name=${1:?usage: examples/run-liggghts.sh NAME [liggghts args]}
shift
ex="$root/examples/$name"
engine=("$root/build/bin/liggghts-granbond")
[ -x "${engine[0]}" ] || { echo "build first: cmake -S . -B build && cmake --build build -j2" >&2; exit 1; }
if [ "${NP:-1}" -gt 1 ]; then
    mpi=(mpirun -np "$NP")
    [ "$(id -u)" = 0 ] && mpi+=(--allow-run-as-root)
    engine=("${mpi[@]}" --oversubscribe "${engine[@]}")
fi
rm -rf "$ex/out"
mkdir -p "$ex/out"
echo "== $name: ${engine[*]} -in $ex/in.$name $*"
(cd "$ex/out" && "${engine[@]}" -in "$ex/in.$name" -log log.liggghts "$@")
echo "== $name: plotting"
python3 "$ex/plot.py" "$ex/out"
