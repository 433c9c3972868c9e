"""Engine-level checks of the bonds each pass steps from the bond store
(docs/development.md, "Where a bond lives"), for LAMMPS (lmp-granbond) and
LIGGGHTS (liggghts-granbond). One claim per mode:

  index       with GRANBOND_CHECK_STORE set, every pass recounts the bond
              store against the atoms (each bond stored once over the
              ranks, between its owner and the partner it names; every
              listed pair flagged bonded exactly when it is; created =
              broken + intact + lost over the ranks). A mismatch ends the
              run. The deck
              index_<kind>.in (bonds across the periodic boundary, bonds
              that break, bonds that form mid-run, delete_atoms ... compress
              no, a restart file) runs on 1, 2 and 4 ranks; with neighbour
              lists rebuilt every step, every 100 steps, and with
              atom_modify sort; and is continued from its restart file on
              another rank count. Every run passes the check; at every
              thermo step created = broken + intact + lost; and the bond
              counts (LAMMPS: created, broken; LIGGGHTS: created, broken,
              intact, lost) equal those of the reference table
              data/index_counts_<kind>.txt, which the adapters that visited
              each bond in the neighbour loop printed for the same deck.
              LAMMPS also runs its agglomerate example under the check on
              1 and 2 ranks: bonds break in compression and shear between
              spheres that go on touching.
  under       LAMMPS contact_under_bond yes|no, LIGGGHTS model voigt's
              contactUnderBond on|off (deck under_<kind>.in): two touching
              spheres, bonded, slide past each other until the bond breaks
              beyond its distance limit. With yes/on the contact's
              tangential spring acts at the break with the history it built
              under the bond; with no/off it starts from zero: in the step
              of the break its force is one step's increment.
  observe     LIGGGHTS: output changes no result: the flagship deck's first
              1000 steps (bonds break under impact, fragments touch) with
              and without its dumps (compute pair/gran/local among them) end
              with the same state of every atom, to the last digit.
  callbacks   LIGGGHTS: where the engine's pair loop reads each pair's
              forces (here: the per-atom sum of normal forces, a fix
              property/atom named sum_normal_force_), the bonds act as
              without it. The flagship deck's first 300 steps
              (bonds loaded by the impact) with and without that fix end
              with the same state of every atom, to round-off (the loads
              join the atoms' sums in another order).
  reform      a bond that breaks between spheres still within the creation
              distance (create_always / createBondAlways) forms again in
              the next pass, not in the pass it broke in, as when each bond
              is stepped in its pair's turn (deck reform_<kind>.in: two
              spheres pushed together break their bond in compression every
              other step).
  beside      LAMMPS: a sphere bonded in a pass still feels the contact of
              a listed neighbour it is not bonded to, before the list is
              built again (deck beside_lammps.in: sphere 1 bonds with
              sphere 2 at step 1, sphere 3 runs into sphere 1 and bounces
              back).

usage: check_bond_index.py --mode MODE --engine BIN --kind lammps|liggghts
                           [--mpiexec MPIEXEC] --workdir DIR
"""

import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))
sys.path.insert(0, HERE)

import deck_runner  # noqa: E402
from deck_runner import Failure, main, mpi_launcher, read_table, run_deck  # noqa: E402

deck_runner.DECKS = os.path.join(HERE, "decks")
# both engines recount their bond store
CHECK = {"lammps": {"GRANBOND_CHECK_STORE": "1"}, "liggghts": {"GRANBOND_CHECK_STORE": "1"}}
ANNOUNCED = {"lammps": "recounting the bonds after every pass",
             "liggghts": "recounting the bonds after every pass"}


def launcher(a, n):
    return mpi_launcher(a.engine, a.mpiexec, n)


def thermo_rows(workdir):
    """The rows of every thermo block of the run's log, as numbers."""
    with open(os.path.join(workdir, "log.lammps"), encoding="utf-8", errors="replace") as f:
        return [row for _, rows in deck_runner.thermo_blocks(f.read()) for _, row in rows]


def counts(workdir):
    """The thermo rows as integers (step, atoms, then the bond counts)."""
    return [tuple(int(v) for v in row) for row in thermo_rows(workdir)]


def index_run(a, n, workdir, variables):
    rc, text = run_deck(launcher(a, n), f"index_{a.kind}.in", workdir, variables, env=CHECK[a.kind])
    if rc != 0:
        raise Failure(f"{n} ranks, {variables}: exit {rc}:\n{text[-3000:]}")
    if ANNOUNCED[a.kind] not in text:
        raise Failure(f"{n} ranks, {variables}: the run did not check its index")
    return counts(workdir)


def check_index(a, workdir):
    table = os.path.join(HERE, "data", f"index_counts_{a.kind}.txt")
    # rows: phase (0: the first deck, 1: continued from its restart file), then the thermo columns
    want = [tuple(int(v) for v in row) for row in read_table(table)]
    first = [r[1:] for r in want if r[0] == 0]
    resumed = [r[1:] for r in want if r[0] == 1]
    d = lambda *p: os.path.join(workdir, *p)  # noqa: E731
    failures = []

    def judge(label, got, expected, balanced=True):
        # created = broken + intact + lost (vanished) at every output
        unbalanced = [r for r in got if balanced and r[2] != r[3] + r[4] + r[5]]
        if unbalanced:
            failures.append(f"{label}: created != broken + intact + lost at {unbalanced[:3]}")
        # the reference holds what the visiting adapters printed: LAMMPS's
        # created and broken, LIGGGHTS's four counts
        got = [r[:len(e)] for r, e in zip(got, expected)] + got[len(expected):]
        if got != expected:
            diff = [(g, e) for g, e in zip(got, expected) if g != e][:3]
            failures.append(f"{label}: counts differ from the reference (got, want): "
                            f"{diff or (len(got), len(expected))}")
        else:
            print(f"ok: {label}: {len(got)} rows equal, the last {got[-1]}")

    for n in (1, 2, 4):
        for every, sort in ((1, 0), (100, 0), (1, 10)):
            label = f"{n} ranks, lists every {every}, sort {sort}"
            judge(label, index_run(a, n, d(f"r{n}-e{every}-s{sort}"), {"every": every, "sort": sort}), first)
    for wrote, reads in ((1, 2), (2, 1), (4, 2)):
        w = d(f"r{wrote}-e1-s0")
        label = f"restart written on {wrote} ranks, read on {reads}"
        judge(label, index_run(a, reads, w, {"phase": 1}), resumed)
    if a.kind == "lammps":
        check_impact(a, workdir, failures)
    if failures:
        raise Failure("; ".join(failures))


def check_impact(a, workdir, failures):
    """The LAMMPS agglomerate example under the index check: the spheres of
    a bond broken in compression or shear mostly go on touching, so the
    contact loop reads the broken bond's record in the pass it broke in."""
    deck = os.path.join(HERE, "..", "..", "examples", "lammps_agglomerate", "in.lammps_agglomerate")
    for n in (1, 2):
        run_dir = os.path.join(workdir, f"impact-r{n}")
        rc, text = run_deck(launcher(a, n), deck, run_dir, {"nrun": 1500}, env=CHECK[a.kind])
        if rc != 0 or ANNOUNCED[a.kind] not in text:
            failures.append(f"agglomerate example, {n} ranks: exit {rc}:\n{text[-3000:]}")
            continue
        with open(os.path.join(run_dir, "counts.txt"), encoding="utf-8") as f:
            last = [int(float(v)) for v in f.read().split("\n")[-2].split()]
        # step created broken intact distance tension compression shear vanished
        if last[6] == 0 or last[7] == 0:
            failures.append(f"agglomerate example, {n} ranks: no bond broke in compression and in shear: {last}")
        else:
            print(f"ok: agglomerate example under the check, {n} ranks: {last[2]} bonds broke, "
                  f"{last[6]} in compression, {last[7]} in shear")


def tangential_force_after_break(a, workdir, under, create=1):
    deck_runner.run_ok([a.engine], f"under_{a.kind}.in", workdir, {"under": under, "create": create})
    rows = thermo_rows(workdir)
    broke = [k for k, r in enumerate(rows) if r[1] > 0]
    if not broke or broke[0] == 0:
        raise Failure(f"under {under}: the bond did not break within the run")
    k = broke[0]
    return rows[k - 1][2], rows[k][2], rows[k][0]


def check_under(a, workdir):
    # the switch in each engine's spelling: pair_coeff ... contact_under_bond
    # yes|no, pair_style gran model voigt ... contactUnderBond on|off
    keep, fresh = ("yes", "no") if a.kind == "lammps" else ("on", "off")
    _, after_yes, step_yes = tangential_force_after_break(a, os.path.join(workdir, keep), keep)
    before, after_no, step_no = tangential_force_after_break(a, os.path.join(workdir, fresh), fresh)
    print(f"the bond breaks at step {step_yes:.0f} ({keep}) and {step_no:.0f} ({fresh}); "
          f"tangential contact force after it: {keep} {after_yes:.6g} N, {fresh} {after_no:.6g} N")
    # from zero, one step of the spring: kt * slip velocity * dt (deck: kt
    # 1e4 N/m, 0.1 m/s, 1e-6 s), the slip velocity nearly all tangential
    one_step = 1e4 * 0.1 * 1e-6
    if abs(after_no - one_step) > 0.01 * one_step:
        raise Failure(f"{fresh}: the contact force after the break {after_no} N is not one step's spring "
                      f"increment {one_step} N: the contact did not start from zero")
    if a.kind == "lammps":
        # a bond formed over a contact that had built its spring: with no,
        # the contact after the break starts from zero too, not from the
        # spring it had when the bond formed
        _, after_late, _ = tangential_force_after_break(a, os.path.join(workdir, "late"), fresh, create=100)
        print(f"bond formed at step 100 over a sliding contact, {fresh}: {after_late:.6g} N after the break")
        if abs(after_late - one_step) > 0.01 * one_step:
            raise Failure(f"{fresh}, the bond formed at step 100: the contact force after the break {after_late} N "
                          f"is not one step's spring increment {one_step} N: the contact resumed the spring it "
                          "had before the bond")
    if step_yes != step_no:
        raise Failure(f"the bond broke at step {step_yes} with {keep} and {step_no} with {fresh}: "
                      "the switch changed the bond")
    if not after_yes > 20 * after_no > 0:
        raise Failure(f"the contact force after the break: {keep} {after_yes} N should keep the history built "
                      f"under the bond, far above {fresh}'s one-step increment {after_no} N")


def check_reform(a, workdir):
    deck_runner.run_ok([a.engine], f"reform_{a.kind}.in", workdir, {})
    rows = thermo_rows(workdir)
    created = {int(r[0]): r[1] for r in rows}
    broken = {int(r[0]): r[2] for r in rows}
    steps = sorted(created)
    breaks = [n for n in steps[1:] if broken[n] > broken[n - 1]]
    if len(breaks) < 3:
        raise Failure(f"the bond broke {len(breaks)} times; the deck should break it every other step")
    for n in breaks:
        if created[n] > created[n - 1]:
            raise Failure(f"step {n}: the bond broke and formed again in the same pass "
                          f"(created {created[n - 1]:.0f} -> {created[n]:.0f}, broken {broken[n - 1]:.0f} -> "
                          f"{broken[n]:.0f})")
        if n + 1 in created and not created[n + 1] > created[n]:
            raise Failure(f"step {n}: the bond broke and did not form again at step {n + 1}, "
                          "though the spheres stay within the creation distance")
    print(f"{len(breaks)} breaks, each followed by a new bond one step later")


def check_beside(a, workdir):
    deck_runner.run_ok([a.engine], f"beside_{a.kind}.in", workdir, {})
    rows = thermo_rows(workdir)
    created, vx = rows[-1][1], rows[-1][2]
    if created != 1:
        raise Failure(f"{created:.0f} bonds created; the deck bonds spheres 1 and 2 only")
    if not vx < 0.0:
        raise Failure(f"sphere 3 ends at vx {vx} m/s (started at 1): it did not bounce off sphere 1, "
                      "whose contact with it was not computed")
    print(f"sphere 3 bounced off the bonded sphere 1: vx 1 -> {vx} m/s")


def check_observe(a, workdir):
    """The flagship deck (bonds breaking under impact, contacts between the
    fragments), its first 1000 steps with and without its dumps, among them
    compute pair/gran/local: the same state of every atom to the last digit."""
    if a.kind != "liggghts":
        raise Failure("observe: liggghts only")
    finals = [flagship_final(a, workdir, f"dumps{dumps}", 1000, "", dumps) for dumps in (0, 1)]
    if not os.path.isdir(os.path.join(workdir, "dumps1", "post")):
        raise Failure("dumps 1 wrote no dumps")
    if finals[0] != finals[1]:
        diff = next((x, y) for x, y in zip(finals[0], finals[1]) if x != y)
        raise Failure(f"the dumps changed the run: without them {diff[0]}, with them {diff[1]}")
    print(f"the same final state of {len(finals[0])} atoms with and without the dumps "
          "(compute pair/gran/local among them)")


def flagship_final(a, workdir, name, nrun, extra, dumps=0):
    """The flagship LIGGGHTS deck with its dumps or without, `extra`
    commands added before its run, run for `nrun` steps: the final state,
    one row of numbers per atom (id, x, v, omega), to the last digit."""
    example = os.path.join(HERE, "..", "..", "examples", "agglomerate_liggghts")
    with open(os.path.join(example, "in.agglomerate_liggghts"), encoding="utf-8") as f:
        deck = f.read()
    final = ("dump final all custom ${nrun} final.txt id x y z vx vy vz omegax omegay omegaz\n"
             'dump_modify final sort id format "%d' + " %.17g" * 9 + '"\n')
    if deck.count("\nrun ${nrun}") != 1:
        raise Failure("the flagship deck no longer ends with one 'run ${nrun}'")
    deck = deck.replace("\nrun ${nrun}", "\n" + extra + final + "run ${nrun}")
    run_dir = os.path.join(workdir, name)
    os.makedirs(run_dir, exist_ok=True)
    with open(os.path.join(run_dir, "in.deck"), "w", encoding="utf-8") as f:
        f.write(deck)
    p = subprocess.run([a.engine, "-in", "in.deck", "-var", "dumps", str(dumps), "-var", "nrun", str(nrun),
                        "-log", "log.lammps"], cwd=run_dir, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, universal_newlines=True, timeout=600)
    if p.returncode != 0:
        raise Failure(f"{name}: exit {p.returncode}:\n{p.stdout[-3000:]}")
    with open(os.path.join(run_dir, "final.txt"), encoding="utf-8") as f:
        rows = f.read().split("ITEM: ATOMS")[-1].splitlines()[1:]
    return [[float(w) for w in r.split()] for r in rows if r.strip()]


def check_callbacks(a, workdir):
    if a.kind != "liggghts":
        raise Failure("callbacks: liggghts only")
    nrun = 300
    swept = flagship_final(a, workdir, "swept", nrun, "")
    summed = flagship_final(a, workdir, "callbacks", nrun,
                            "fix sumnf all property/atom sum_normal_force_ scalar no no no 0.\n")
    if len(swept) != len(summed) or not swept:
        raise Failure(f"{len(swept)} and {len(summed)} atoms")
    worst, where = 0.0, None
    for c in range(1, 10):   # x, v, omega: each against its column's scale
        scale = max(abs(r[c]) for r in swept) or 1.0
        for r, q in zip(swept, summed):
            d = abs(r[c] - q[c]) / scale
            if d > worst:
                worst, where = d, (int(r[0]), c)
    print(f"{len(swept)} atoms after {nrun} steps: largest difference {worst:.3g} of its column's scale")
    if worst > 1e-9:
        raise Failure(f"with the pairs' callbacks applying the bonds' loads the run differs: atom {where[0]}, "
                      f"column {where[1]}, {worst:.3g} of the column's scale")


def parse():
    p = argparse.ArgumentParser()
    p.add_argument("--mode", required=True, choices=["index", "under", "reform", "beside", "observe", "callbacks"])
    p.add_argument("--engine", required=True)
    p.add_argument("--kind", required=True, choices=["lammps", "liggghts"])
    p.add_argument("--mpiexec")
    p.add_argument("--workdir", required=True)
    return p.parse_args()


if __name__ == "__main__":
    args = parse()
    checks = {"index": check_index, "under": check_under, "reform": check_reform, "beside": check_beside, "observe": check_observe,
              "callbacks": check_callbacks}
    main(lambda: checks[args.mode](args, args.workdir))
