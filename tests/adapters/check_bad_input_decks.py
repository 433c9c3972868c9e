"""Decks of bad input stop with an ERROR naming it; decks that are right run without a word.

decks/bad_input/ holds decks users wrote with bad input: a switch without a
value at the end of a LIGGGHTS line, a bond without compression
stiffness, a linear compression law beyond the bond radius, creation far
beyond contact, a break reach beyond the neighbour lists, repeated
keywords and phrases, coincident centres, a property in the wrong style,
`timestep 0`; and decks that are right: a strength of `inf` under
per-bond output, the intended values of the same decks, radii set after
an early init (`reset_atom_ids` before `set diameter`). Each case runs one
deck (in a copy of the folder) and expects either an ERROR line naming
every word listed, no signal, or a clean run with the property the case
states.

usage: check_bad_input_decks.py --liggghts EXE --lammps EXE --workdir DIR
"""

import argparse
import os
import re
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))
from deck_runner import Failure, main, run_deck, thermo_rows  # noqa: E402

FOLDER = os.path.join(HERE, "decks", "bad_input")
MUTATION = os.path.join(HERE, "decks", "mutation")


def apart(text):
    """The spheres never pass through each other: r = x2 - x1 stays > 0."""
    rows = thermo_rows(text)
    if not rows:
        return "no thermo rows"
    if any(r[1] <= 0.0 for r in rows):
        return f"the spheres passed through each other: r = {[r[1] for r in rows]}"
    return None


def quiet_and_bonded(text):
    """No warning, and the bond formed (created count 1 at the last row)."""
    warnings = [l for l in text.splitlines() if l.startswith("WARNING")]
    if warnings:
        return f"warned about a deck whose radii are set before its run: {warnings}"
    rows = thermo_rows(text)
    if not rows or rows[-1][1] != 1.0:
        return f"no bond formed: {rows}"
    return None


def dumped(workdir):
    def check(_text):
        with open(os.path.join(workdir, "bonds.dump"), encoding="utf-8") as f:
            text = f.read()
        if not re.search(r"^1 2\b", text, re.MULTILINE):
            return f"no row of the bond of atoms 1 and 2 in bonds.dump:\n{text[-500:]}"
        return None
    return check


def variant(source, name, old, new):
    """A copy of a base deck of decks/mutation with one line changed."""
    with open(os.path.join(MUTATION, source), encoding="utf-8") as f:
        text = f.read()
    assert old in text, (source, old)
    return name, text.replace(old, new)


# (engine, deck, variables, ERROR words or None for a clean run, check of a clean run)
CASES = [
    ("liggghts", "switch_no_value.in", {}, ["pair_style gran", "dampingBond"], None),
    ("liggghts", "switch_no_value_wall.in", {}, ["wall/gran", "historyReset"], None),
    ("lammps", "k_fn1_left_out.in", {}, ["k_fn1"], None),
    ("liggghts", "k_fn1_zero_liggghts.in", {}, ["stiffnessPerUnitAreaK_fn1"], None),
    ("lammps", "clb_huge.in", {}, ["compression_linear_below"], None),
    ("lammps", "clb_huge.in", {"clb": "1e-3"}, ["compression_linear_below"], None),
    ("lammps", "clb_huge.in", {"clb": "7e-7"}, None, apart),
    ("liggghts", "clb_huge_liggghts.in", {}, ["compressionLinearBelowBondnonlinear"], None),
    ("liggghts", "clb_huge_liggghts.in", {"clb": "1.0"}, ["compressionLinearBelowBondnonlinear"], None),
    ("liggghts", "clb_huge_liggghts.in", {"clb": "7e-7"}, None, apart),
    ("lammps", "create_distance_huge.in", {}, ["create_distance"], None),
    ("lammps", "tau_max_inf_local.in", {}, None, "dumped"),
    ("lammps", "repeated_keyword.in", {}, ["break stress", "break distance"], None),
    ("liggghts", "coincident_liggghts.in", {}, ["coincident centres", "atoms 1 and 2"], None),
    ("lammps", "in.pair_line", {"line": "two_breaks_distance_first.inc"}, ["break stress", "break distance"], None),
    ("lammps", "in.pair_line", {"line": "two_breaks_stress_first.inc"}, ["break stress", "break distance"], None),
    ("lammps", "in.pair_line", {"line": "create_always_then_step.inc"}, ["create_step", "create_always"], None),
    ("lammps", "in.pair_line", {"line": "create_step_then_always.inc"}, ["create_step", "create_always"], None),
    ("lammps", "in.pair_line", {"line": "k_ft_twice.inc"}, ["k_ft 3e10", "k_ft 2e10"], None),
    ("lammps", "in.pair_line", {"line": "valid.inc"}, None, None),
    ("liggghts", "in.linear_below", {"spec": "scalar 5e-7"}, ["compressionLinearBelowBondnonlinear", "scalar"],
     None),
    ("liggghts", "in.linear_below", {"spec": "peratomtypepair 1 5e-7"}, None, None),
    ("lammps", "early_init.in", {}, None, quiet_and_bonded),
    ("lammps", variant("lammps_stress.in", "timestep_zero.in", "timestep     2e-7", "timestep 0"), {},
     ["timestep"], None),
    ("liggghts", variant("liggghts_stress.in", "timestep_zero_liggghts.in", "timestep     2e-7", "timestep 0"), {},
     ["timestep"], None),
    ("lammps", variant("lammps_distance.in", "reach_25_diameters.in", "break distance 2.08e-3",
                       "break distance 0.05"), {}, ["max_distance"], None),
]


def check_all(engines, workdir):
    failures = []
    for index, (engine, deck, variables, words, clean) in enumerate(CASES):
        where = os.path.join(workdir, f"case{index}")
        shutil.rmtree(where, ignore_errors=True)
        shutil.copytree(FOLDER, where)
        if isinstance(deck, tuple):
            deck, text = deck
            with open(os.path.join(where, deck), "w", encoding="utf-8") as f:
                f.write(text)
        label = f"{engine} {deck} {variables}"
        # the decks are run in their folder's copy: -in takes the path as given
        try:
            rc, text = run_deck([engines[engine]], os.path.join(where, deck), where, variables)
        except Failure as e:   # a signal
            failures.append(f"{label}: {str(e).splitlines()[0]}")
            continue
        errors = [line for line in text.splitlines() if "ERROR" in line]
        if words is not None:
            if rc == 0:
                failures.append(f"{label}: the run succeeded; expected an ERROR naming {words}")
            elif not any(all(w in line for w in words) for line in errors):
                failures.append(f"{label}: no ERROR line names {words}; got {errors or text[-1500:]}")
            else:
                print(f"ok: {label}: {next(l for l in errors if all(w in l for w in words))}")
            continue
        if rc != 0:
            failures.append(f"{label}: exit {rc}: {errors or text[-1500:]}")
            continue
        if re.search(r"(?<![A-Za-z])-?nan\b", text, re.IGNORECASE):
            failures.append(f"{label}: nan in the output")
            continue
        check = dumped(where) if clean == "dumped" else clean
        problem = check(text) if check else None
        if problem:
            failures.append(f"{label}: {problem}")
        else:
            print(f"ok: {label}: runs")
    if failures:
        raise Failure("\n".join(failures))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", required=True)
    parser.add_argument("--lammps", required=True)
    parser.add_argument("--workdir", required=True)
    a = parser.parse_args()
    main(lambda: check_all({"liggghts": a.liggghts, "lammps": a.lammps}, a.workdir))
