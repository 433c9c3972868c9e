"""Engine-level checks that a bond lives with its atoms, in the bond store
(docs/development.md, "Where a bond lives"), whatever the deck does around
it. The decks in decks/bond_home/ are the testers' (written for the
defects they found when bonds lived in the contact history). One claim
per mode (LAMMPS unless said):

  newton     the bonded block in free motion under LAMMPS's default
             `newton on` on 3 ranks, and under `newton off`: at every
             output the intact bonds equal created - broken, none is lost,
             nothing is warned, and both settings end with the same
             counts.
  switch     `pair_style granular` (or `zero`) for 10 steps, then
             `pair_style granbond` again: the 267 bonds are kept (the run
             that only re-issues granbond keeps them too), and the run
             under the other style is told that they wait.
  settype    atoms set to a type pair without bonds: the bonds dropped
             are warned with that cause, not as vanished atoms.
  data       `write_data` says that the bonds are not in the data file
             and names the restart route.
  rerun      `rerun` of a bonded trajectory says that the bonds cannot be
             rebuilt from a dump.
  energy     an elastic, undamped bond between two spheres in free
             flight, pulled, sheared, twisted and bent: kinetic energy
             (translation and rotation) plus `pe` (the bonds' stored
             energy) stays constant to 1e-5 of itself on 1 and 2 ranks,
             while `pe` takes up a good part of it.
  budget     a bonded block in free flight, spinning and spreading, its
             bonds damped, hysteretic, some breaking (`pair_style granbond
             energy yes`): kinetic energy (translation and rotation) + `pe`
             + the energy dissipated by damping and by hysteresis +
             released by breaks (compute pair granbond's values 9-11)
             stays constant on 1 and 2 ranks within twice what kinetic +
             stored energy does for the same block with elastic, undamped
             bonds as stiff as the others unload, that do not break (the
             integrator's error, itself below 1e-5), while each
             of the three terms takes a share of it. The intact bonds'
             own energies (compute granbond/local) add up to `pe`, and to
             the dissipated terms until the first break (after it, to less).
             The same through a restart file half way. LIGGGHTS: the same
             block (cohesion bond/nonlinear, compute granbond/energy), on 1
             and 2 ranks, the intact bonds' own energies (compute
             pair/gran/local/bond) adding up likewise (the stored energy
             exactly); with bonds that do not break, they add up to the
             budget's at every output before and after a restart file half
             way; and each elastic bond stores its loading curves' energy
             for its state (dumped every 500 steps).
  momentum   a bonded block in free flight, spinning, its bonds breaking, a
             sphere inserted far away between two runs (LIGGGHTS: by fix
             insert/rate/region during the run, frictionless Hertz
             contacts, the store recounted after every pass), on 1 and 3
             ranks under `newton on` and `off` (LIGGGHTS: `newton off`):
             the total linear momentum and
             the angular momentum about the origin (orbital and spin) stay
             what they were to round-off (1e-12 of their size), and
             created = broken + intact + lost at every output.
  insert     LIGGGHTS: two spheres bonded across a periodic boundary (1
             and 3 ranks) or a rank boundary (2 ranks, the sphere inserted
             on either rank), a sphere inserted far away at step 100: at
             every output the bond acts on both spheres (f1 = -f2 to
             round-off), the pair's momentum stays what it was to
             round-off,
             created = broken + intact + lost and the bond is intact at
             the end, nothing is warned; the store recounted after every
             pass (GRANBOND_CHECK_STORE).
  edge       LIGGGHTS: one sphere bonded to a mesh wall on the edge
             shared by two triangles, the restart file written on 1 and
             on 2 ranks and read on 1, 2 and 3 while the mesh is pulled
             down (decks/bond_home/mesh_edge_restart.in): in every
             combination one wall bond (created 1, intact 1, nothing
             broken or lost at every output) and the same force on the
             sphere, -8.19e-3 N at step 150 and the same table as the
             restart written and read on one rank, to 1e-12 of the
             largest force. Read on 1-3 ranks with the mesh pulled
             fast, the bond breaks: created 1, broken 1, intact 0. The
             bond dragging the sphere across the boundaries of 2 and 3
             ranks stays one bond, with the same force on 1, 2 and 3
             ranks. created = broken + intact + lost at every output;
             the store recounted after every pass, the wall bonds' store at
             every output (GRANBOND_CHECK_STORE).
             With a second mesh (out of reach) listed after the bonded one
             when the file is written and before it when it is read (1-3
             ranks), the bond stays on its mesh: the same counts and table;
             the bonded mesh left out of the wall fix is an ERROR naming
             the meshes of the file and of the deck.
  wallinsert LIGGGHTS: a layer of four spheres bonded to a mesh plane at
             step 1, the plane sliding and sinking so that the bonds carry
             shear and tension and drag one sphere across the boundary of 2
             ranks, while fix insert/rate/region throws 24 spheres at the
             plane elsewhere (decks/bond_home/wall_bonds_insert.in), on 1
             and 2 ranks: at every output the wall bonds number created 4,
             intact 4, nothing broken or lost, created = broken + intact +
             lost; every inserted sphere that touches the plane does so
             unbonded (its contacts' bond flag 0, compute wall/gran/local)
             while the layer's contacts hold theirs; 2 ranks give the 1-rank
             counts and the layer's force to 1e-12 of its largest value;
             the store recounted after every pass, the wall bonds' store at
             every output (GRANBOND_CHECK_STORE).

usage: check_bond_home.py --mode MODE --kind lammps|liggghts --engine BIN
                          [--mpiexec MPIEXEC] --workdir DIR
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))
sys.path.insert(0, HERE)

import deck_runner  # noqa: E402
from check_bond_index import launcher  # noqa: E402
from check_runtime import warnings_in_log  # noqa: E402
from deck_runner import Failure, run_modes, run_ok, thermo_column  # noqa: E402

DECKS = os.path.join(HERE, "decks", "bond_home")
BASE = {"base": os.path.join(DECKS, "base")}


def run(a, n, deck, workdir, variables=None, env=None):
    deck_runner.DECKS = DECKS
    return run_ok(launcher(a, n), deck, workdir, dict(BASE, **(variables or {})), env)


def check_newton(a, workdir):
    n = 3 if a.mpiexec else 1
    finals = {}
    for newton in ("default", "off"):
        d = os.path.join(workdir, newton)
        text = run(a, n, "newton_default_counts.in", d, {"newton": newton})
        intact, lost, expect = thermo_column(text, "c_pg[3]"), thermo_column(text, "c_pg[8]"), thermo_column(text, "v_expect")
        if not intact or intact != expect or any(v != 0 for v in lost):
            raise Failure(f"newton {newton}, {n} ranks: intact {intact} against created - broken {expect}, lost {lost}")
        warned = warnings_in_log(d)
        if warned:
            raise Failure(f"newton {newton}: a correct deck warned: {warned}")
        finals[newton] = intact[-1]
        print(f"ok: newton {newton}, {n} ranks: intact = created - broken at every output ({intact[-1]:g} at the end)")
    if finals["default"] != finals["off"]:
        raise Failure(f"newton on and off end with {finals['default']} and {finals['off']} intact bonds")


def check_switch(a, workdir):
    kept = run(a, 1, "pair_style_switch.in", os.path.join(workdir, "style"), {"mode": "style"})
    want = thermo_column(kept, "c_pg[3]")[-1]
    if want <= 0:
        raise Failure("no bond in the reference run: the deck does not test them")
    for mode, style in (("switch", "granular"), ("zero", "zero")):
        d = os.path.join(workdir, mode)
        text = run(a, 1, "pair_style_switch.in", d, {"mode": mode})
        got = thermo_column(text, "c_pg[3]")[-1]
        told = [w for w in warnings_in_log(d) if f"{want:g} bonds of pair_style granbond are kept" in w and style in w]
        if got != want or not told:
            raise Failure(f"pair_style {style} and back: {got:g} intact bonds (want {want:g}); warnings "
                          f"{warnings_in_log(d)}")
        print(f"ok: pair_style {style} and back: the {got:g} bonds kept, and told: {told[0][:100]}")


def check_settype(a, workdir):
    d = os.path.join(workdir, "settype")
    run(a, 1, "set_type.in", d)
    told = [w for w in warnings_in_log(d) if "bonds lost" in w]
    if len(told) != 1 or "no bond model" not in told[0] or "left the system" in told[0]:
        raise Failure(f"set type: want one warning with the types' cause: {warnings_in_log(d)}")
    print(f"ok: set type: {told[0][:140]}")


def check_data(a, workdir):
    d = os.path.join(workdir, "data")
    run(a, 1, "write_read_data_a.in", d)
    told = [w for w in warnings_in_log(d) if w.startswith("WARNING: write_data") and "not in the data file" in w
            and "write_restart" in w]
    if not told:
        raise Failure(f"write_data: no warning that the bonds are not in the data file: {warnings_in_log(d)}")
    print(f"ok: {told[0][:140]}")


def check_rerun(a, workdir):
    d = os.path.join(workdir, "rerun")
    run(a, 1, "rerun.in", d)
    told = [w for w in warnings_in_log(d) if w.startswith("WARNING: rerun") and "not in dump files" in w]
    if not told:
        raise Failure(f"rerun: no warning that the bonds cannot come from a dump: {warnings_in_log(d)}")
    print(f"ok: {told[0][:140]}")


def check_momentum(a, workdir):
    counts = [1, 3] if a.mpiexec else [1]
    liggghts = a.kind == "liggghts"
    # LIGGGHTS: its granular decks run newton off, its counter is compute bond/counter
    settings = ("off",) if liggghts else ("default", "off")
    deck = "free_body_momentum_liggghts.in" if liggghts else "free_body_momentum.in"
    counters = ("c_bc[1]", "c_bc[2]", "c_bc[3]", "c_bc[7]") if liggghts else ("c_pg[1]", "c_pg[2]", "c_pg[3]", "c_pg[8]")
    for n in counts:
        for newton in settings:
            d = os.path.join(workdir, f"np{n}-{newton}")
            env = {"GRANBOND_CHECK_STORE": "1"} if liggghts else None
            text = run(a, n, deck, d, {} if liggghts else {"newton": newton}, env)
            cols = [thermo_column(text, c) for c in counters]
            unbalanced = [r for r in zip(*cols) if r[0] != r[1] + r[2] + r[3]]
            broken = cols[1][-1] if cols[1] else 0
            if not cols[0] or unbalanced or broken == 0:
                raise Failure(f"{n} ranks, newton {newton}: created != broken + intact + lost at {unbalanced[:3]}, "
                              f"or no bond broke ({broken})")
            moments = [thermo_column(text, f"c_L[{k}]") for k in range(1, 7)]
            worst = 0.0
            for group in (moments[:3], moments[3:]):
                size = max(sum(v * v for v in row) ** 0.5 for row in zip(*group))
                for values in group:
                    worst = max(worst, (max(values) - min(values)) / size)
            if worst > 1e-12:
                raise Failure(f"{n} ranks, newton {newton}: momentum or angular momentum moved by {worst:.3g} of its size")
            print(f"ok: {n} ranks, newton {newton}: {broken:g} bonds broke, momentum and angular momentum "
                  f"within {worst:.2g} of their size")


def check_energy(a, workdir):
    for n in [1, 2] if a.mpiexec else [1]:
        d = os.path.join(workdir, f"np{n}")
        text = run(a, n, "elastic_pair_energy.in", d)
        total, pe, intact = thermo_column(text, "v_total"), thermo_column(text, "PotEng"), thermo_column(text, "c_pg[3]")
        if not total or intact[-1] != 1:
            raise Failure(f"{n} ranks: the bond did not hold ({intact[-1:]} intact)")
        drift = (max(total) - min(total)) / max(total)
        share = max(pe) / max(total)
        if drift > 1e-5 or share < 0.3:
            raise Failure(f"{n} ranks: kinetic + stored energy moved by {drift:.3g} of itself; pe reached "
                          f"{share:.3g} of it")
        print(f"ok: {n} ranks: kinetic + stored energy within {drift:.2g} of itself, pe up to {share:.2f} of it")


def check_insert(a, workdir):
    cases = [(1, "insert_periodic_1rank.in")]
    if a.mpiexec:
        cases += [(2, "insert_2ranks_warned.in"), (2, "insert_2ranks_silent.in"), (3, "insert_periodic_1rank.in")]
    for n, deck in cases:
        d = os.path.join(workdir, f"{deck[:-3]}-np{n}")
        text = run(a, n, deck, d, env={"GRANBOND_CHECK_STORE": "1"})
        if "recounting the bonds after every pass" not in text:
            raise Failure(f"{deck}: the store check did not run")
        atoms = thermo_column(text, "Atoms")
        created, broken, intact, lost = (thermo_column(text, f"c_bc[{k}]") for k in (1, 2, 3, 7))
        # LIGGGHTS heads variable columns without the `v_`
        pz, f1, f2 = (thermo_column(text, c) for c in ("pz", "f1", "f2"))
        if not atoms or atoms[-1] != 3:
            raise Failure(f"{deck}, {n} ranks: no sphere was inserted ({atoms[-1:]} atoms at the end)")
        unbalanced = [r for r in zip(created, broken, intact, lost) if r[0] != r[1] + r[2] + r[3]]
        if unbalanced or intact[-1] != 1 or created[-1] != 1:
            raise Failure(f"{deck}, {n} ranks: created, broken, intact, lost {unbalanced[:3] or (created[-1], broken[-1], intact[-1], lost[-1])}")
        # from the bond's first step on (before it, the touching spheres'
        # contact acts, on one sphere per listing under newton off)
        bonded = [(x, y) for x, y, b in zip(f1, f2, intact) if b == 1]
        scale = max(abs(x) for x, _ in bonded) if bonded else 0.0
        one_sided = [(x, y) for x, y in bonded if abs(x + y) > 1e-12 * scale]
        if scale == 0.0 or one_sided:
            raise Failure(f"{deck}, {n} ranks: the bond acts on one sphere only: f1, f2 = {one_sided[:3]}")
        # each sphere carries 1.05e-5 kg at 0.05 m/s; the pair's momentum,
        # from the bond's first step on, is what the touching spheres'
        # contact left it
        held = [p for p, b in zip(pz, intact) if b == 1]
        drift = (max(held) - min(held)) / (1.05e-5 * 0.05)
        if drift > 1e-12:
            raise Failure(f"{deck}, {n} ranks: the free pair's momentum moved by {drift:.3g} of a sphere's")
        warned = warnings_in_log(d)
        if warned:
            raise Failure(f"{deck}, {n} ranks: a correct deck warned: {warned}")
        print(f"ok: {deck}, {n} ranks: the bond two-sided at every output (f1 = {f1[-1]:.4g} N), momentum within "
              f"{drift:.2g} of a sphere's, created {created[-1]:g} = intact {intact[-1]:g}")
def check_edge(a, workdir):
    writers = [1, 2] if a.mpiexec else [1]
    readers = [1, 2, 3] if a.mpiexec else [1]
    env = {"GRANBOND_CHECK_STORE": "1"}
    reference = None
    for w in writers:
        restart = os.path.join(workdir, f"edge-np{w}.restart")
        text = run(a, w, "mesh_edge_restart.in", os.path.join(workdir, f"write-np{w}"),
                   {"px": w, "restart": restart}, env)
        if "recounting the bonds after every pass" not in text or "recounting the wall bonds" not in text:
            raise Failure("mesh_edge_restart.in: the store check (pairs and walls) did not run")
        if thermo_column(text, "c_bc[6]")[-1:] != [1]:
            raise Failure(f"written on {w} ranks: {thermo_column(text, 'c_bc[6]')} intact wall bonds, want 1")
        for r in readers:
            d = os.path.join(workdir, f"write-np{w}-read-np{r}")
            text = run(a, r, "mesh_edge_restart.in", d, {"phase": 2, "v": -0.2, "restart": restart}, env)
            steps = thermo_column(text, "Step")
            counts = [thermo_column(text, f"c_bc[{k}]") for k in (4, 5, 6, 8)]
            fz = thermo_column(text, "fz")
            label = f"written on {w} ranks, read on {r}"
            if not steps or any(row != (1, 0, 1, 0) for row in zip(*counts)):
                raise Failure(f"{label}: wall bonds created, broken, intact, lost {list(zip(*counts))[:4]}, "
                              "want one bond (1, 0, 1, 0) at every output")
            at150 = fz[steps.index(150)]
            if abs(at150 - (-8.19e-3)) > 5e-6:
                raise Failure(f"{label}: fz at step 150 is {at150:.6g} N, want -8.19e-3 N (one bond)")
            table = list(zip(steps, fz))
            if reference is None:
                reference = table
            scale = max(abs(f) for _, f in reference)
            worst = max(abs(f - g) for (_, f), (_, g) in zip(table, reference))
            if [s for s, _ in table] != [s for s, _ in reference] or worst > 1e-12 * scale:
                raise Failure(f"{label}: fz differs from the run written and read on 1 rank by {worst:.3g} N")
            warned = [w_ for w_ in warnings_in_log(d) if "different # of processors" not in w_
                      and "is not after step" not in w_]
            if warned:
                raise Failure(f"{label}: a correct deck warned: {warned}")
            print(f"ok: {label}: one wall bond at every output, fz {at150:.6g} N at step 150, "
                  f"within {worst:.2g} N of the 1-rank table")
    # two meshes, the bonded one listed first; read back with the other first
    restart = os.path.join(workdir, "two-meshes.restart")
    two = {"second": 1, "nmeshes": 2}
    run(a, 1, "mesh_edge_restart.in", os.path.join(workdir, "two-write"),
        dict(two, meshes="plane plane2", restart=restart), env)
    for r in readers:
        d = os.path.join(workdir, f"two-swapped-read-np{r}")
        text = run(a, r, "mesh_edge_restart.in", d,
                   dict(two, meshes="plane2 plane", phase=2, v=-0.2, restart=restart), env)
        rows = list(zip(*[thermo_column(text, f"c_bc[{k}]") for k in (4, 5, 6, 8)]))
        table = list(zip(thermo_column(text, "Step"), thermo_column(text, "fz")))
        scale = max(abs(f) for _, f in reference)
        worst = max((abs(f - g) for (_, f), (_, g) in zip(table, reference)), default=math.inf)
        if not rows or any(row != (1, 0, 1, 0) for row in rows) or len(table) != len(reference) \
                or worst > 1e-12 * scale:
            raise Failure(f"meshes listed the other way round, read on {r} ranks: wall bonds created, broken, "
                          f"intact, lost {rows[:4]}, fz off the one-mesh table by {worst:.3g} N: want the bond on "
                          "its mesh, (1, 0, 1, 0) at every output and the one-mesh table")
        print(f"ok: meshes listed the other way round, read on {r} ranks: the bond stays on its mesh, "
              f"the one-mesh table within {worst:.2g} N")
    d = os.path.join(workdir, "two-gone")
    rc, text = deck_runner.run_deck(launcher(a, 1), "mesh_edge_restart.in", d,
                                    dict(BASE, second=1, nmeshes=1, meshes="plane2", phase=2, v=-0.2,
                                         restart=restart), env)
    said = [line for line in text.splitlines() if line.startswith("ERROR")]
    if rc == 0 or not said or "0 plane, 1 plane2" not in said[0] or "now lists 0 plane2" not in said[0]:
        raise Failure(f"the bonded mesh left out of the wall fix: exit {rc}, {said[:1]}: want an ERROR naming "
                      "the meshes of the file and of the deck")
    print(f"ok: the bonded mesh left out of the wall fix: {said[0][:160]}")
    for r in readers:
        d = os.path.join(workdir, f"break-read-np{r}")
        text = run(a, r, "mesh_edge_restart.in", d, {"phase": 2, "v": -2.0, "restart": restart}, env)
        rows = list(zip(*[thermo_column(text, f"c_bc[{k}]") for k in (4, 5, 6, 8)]))
        if not rows or rows[-1] != (1, 1, 0, 0) or any(c != b + i + l for c, b, i, l in rows):
            raise Failure(f"mesh pulled fast, read on {r} ranks: created, broken, intact, lost {rows}, "
                          "want the bond broken (1, 1, 0, 0) and created = broken + intact + lost")
        print(f"ok: mesh pulled fast, read on {r} ranks: the bond broke once, counts {rows[-1]}")
    tables = {}
    for n in readers:
        d = os.path.join(workdir, f"drag-np{n}")
        text = run(a, n, "mesh_edge_restart.in", d,
                   {"px": n, "x0": 0.004, "vx": -1.0, "run1": 5000, "restart": os.path.join(d, "unused.restart")},
                   env)
        # from the bond's first output on (step 0 comes before it)
        steps = thermo_column(text, "Step")
        rows = [r for t, *r in zip(steps, *[thermo_column(text, f"c_bc[{k}]") for k in (4, 5, 6, 8)]) if t > 0]
        x = thermo_column(text, "x")
        if not rows or any(tuple(row) != (1, 0, 1, 0) for row in rows) or not x or x[-1] > -5e-4:
            raise Failure(f"dragged on {n} ranks: counts {rows[:3]}..., x {x[-1:]}: want one bond at every "
                          "output and the sphere dragged past x = 0")
        tables[n] = list(zip(thermo_column(text, "Step"), thermo_column(text, "fz"), x))
        if tables[n] != tables[readers[0]]:
            raise Failure(f"dragged on {n} ranks: the table differs from 1 rank's")
        print(f"ok: dragged across the ranks' boundaries on {n} ranks: one bond, x from 4 mm to "
              f"{x[-1] * 1e3:.3g} mm, the same table as on 1 rank")


def wall_contacts(path):
    """The rows (step, atom id, bond flag) of a dump of compute
    wall/gran/local id history (columns: mesh, triangle, atom id, flag)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    rows, step = [], None
    for k, line in enumerate(lines):
        if line.startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
        elif not line.startswith("ITEM") and step is not None and len(line.split()) == 4:
            _, _, atom, flag = (float(v) for v in line.split())
            rows.append((step, int(atom), flag))
    return rows


def check_wall_insert(a, workdir):
    ranks = [1, 2] if a.mpiexec else [1]
    env = {"GRANBOND_CHECK_STORE": "1"}
    layer = 4
    reference = None
    for n in ranks:
        d = os.path.join(workdir, f"np{n}")
        text = run(a, n, "wall_bonds_insert.in", d, {"px": n}, env)
        if "recounting the bonds after every pass" not in text or "recounting the wall bonds" not in text:
            raise Failure("wall_bonds_insert.in: the store check (pairs and walls) did not run")
        steps, atoms = thermo_column(text, "Step"), thermo_column(text, "Atoms")
        rows = list(zip(*[thermo_column(text, f"c_bc[{k}]") for k in (4, 5, 6, 8)]))
        # LIGGGHTS heads variable columns without the `v_`
        fx, fz, x3 = (thermo_column(text, c) for c in ("fx", "fz", "x3"))
        label = f"{n} rank{'s' if n > 1 else ''}"
        if not atoms or atoms[-1] != layer + 24:
            raise Failure(f"{label}: {atoms[-1:]} atoms at the end, want the layer and 24 inserted spheres")
        bad = [(t, r) for t, r in zip(steps, rows) if t > 0 and r != (layer, 0, layer, 0)
               or r[0] != r[1] + r[2] + r[3]]
        if not rows or bad:
            raise Failure(f"{label}: wall bonds (step, (created, broken, intact, lost)) {bad[:4]}: want the "
                          f"layer's {layer} bonds, (4, 0, 4, 0), at every output after step 0")
        # the third sphere starts at x = 1 mm, on rank 1 of 2: dragged past
        # x = 0, its bond migrated
        if x3[-1] > -5e-4:
            raise Failure(f"{label}: the dragged sphere ends at x = {x3[-1]:.3g} m, want it past x = 0")
        scale = max(abs(f) for f in fx + fz)
        if scale < 1e-3:
            raise Failure(f"{label}: the layer's force is at most {scale:.3g} N: the bonds carry no load")
        contacts = wall_contacts(os.path.join(d, "wall.dump"))
        inserted = [(t, i, f) for t, i, f in contacts if i > layer]
        held = [(t, i, f) for t, i, f in inserted if f != 0]
        loose = [(t, i, f) for t, i, f in contacts if i <= layer and t > 0 and f != 1]
        if not inserted or held or loose:
            raise Failure(f"{label}: {len(inserted)} contacts of inserted spheres with the plane, bonded ones "
                          f"(step, id, flag) {held[:4]}; layer contacts without their bond {loose[:4]}: want "
                          "inserted spheres on the plane unbonded and the layer bonded")
        warned = warnings_in_log(d)
        if warned:
            raise Failure(f"{label}: a correct deck warned: {warned}")
        table = list(zip(steps, rows, fx, fz))
        if reference is None:
            reference = table
        # LIGGGHTS places and numbers inserted spheres by rank, so only the
        # layer is compared: its spheres touch nothing but the plane, so 2
        # ranks step the same bonds; only fcm's sum over ranks is taken in
        # another order (round-off of the sum)
        ref_scale = max(max(abs(x), abs(z)) for _, _, x, z in reference)
        worst = max((max(abs(x - u), abs(z - w)) for (_, _, x, z), (_, _, u, w) in zip(table, reference)),
                    default=math.inf)
        if [t[:2] for t in table] != [t[:2] for t in reference] or worst > 1e-12 * ref_scale:
            raise Failure(f"{label}: the counts or the layer's force differ from 1 rank's (force by {worst:.3g} N)")
        print(f"ok: {label}: wall bonds (4, 0, 4, 0) at every output with {atoms[-1]:g} atoms, "
              f"{len(inserted)} contacts of inserted spheres all unbonded, layer force up to {scale:.3g} N "
              f"within {worst:.2g} N of 1 rank's, sphere 3 dragged to x = {x3[-1] * 1e3:.3g} mm")


def budget_drift(text):
    # LIGGGHTS heads a variable's column without the `v_`
    total = thermo_column(text, "v_total") or thermo_column(text, "total")
    if not total:
        raise Failure("no thermo output")
    return total, max(abs(t - total[0]) for t in total) / total[0]


# The columns of the budget decks: broken bonds, stored energy, dissipated by
# damping and by hysteresis, then the sums of the intact bonds' own three.
BOND_ENERGY_COLUMNS = {
    "lammps": ("c_pg[2]", "PotEng", "c_pg[9]", "c_pg[10]", "c_bs[1]", "c_bs[2]", "c_bs[3]"),
    "liggghts": ("c_bc[2]", "c_en[1]", "c_en[2]", "c_en[3]", "c_bs[1]", "c_bs[2]", "c_bs[3]"),
}


def check_bond_energies(text, n, kind="lammps", stored_tolerance=1e-9):
    cols = [thermo_column(text, c) for c in BOND_ENERGY_COLUMNS[kind]]
    if not cols[0]:
        raise Failure(f"{n} ranks: no thermo output")
    before_breaks = 0
    for broken, pe, damping, hysteresis, stored, own_damping, own_hysteresis in zip(*cols):
        if abs(stored - pe) > stored_tolerance * max(abs(pe), 1e-30):
            raise Failure(f"{n} ranks: the bonds' own stored energies add up to {stored:.17g}, the budget's stored "
                          f"energy is {pe:.17g}")
        for own, term, name in ((own_damping, damping, "damping"), (own_hysteresis, hysteresis, "hysteresis")):
            scale = 1e-9 * max(abs(term), 1e-30)
            if (broken == 0 and abs(own - term) > scale) or own > term + scale:
                raise Failure(f"{n} ranks, {broken:g} broken: the intact bonds' own {name} adds up to {own:.17g}, "
                              f"the budget's is {term:.17g}")
        before_breaks += broken == 0 and damping > 0
    if before_breaks == 0:
        raise Failure(f"{n} ranks: no output between the first damping and the first break")


def state_slots():
    """The bond state's slot names in the core's order, from the table of
    docs/models/bond-nonlinear.md ("Bond state")."""
    path = os.path.join(HERE, "..", "..", "docs", "models", "bond-nonlinear.md")
    with open(path, encoding="utf-8") as f:
        text = f.read()
    table = text[text.index("## Bond state"):text.index("## Time step")]
    slots = []
    for line in table.splitlines():
        if not line.startswith("| `"):
            continue
        for name in line.split("|")[1].replace("`", "").split(","):
            name = name.strip()
            if name.endswith("_x/y/z"):
                slots += [name[:-5] + c for c in "xyz"]
            else:
                slots.append(name)
    return slots


def bond_dump_deck(workdir, every):
    """A deck fragment that dumps each intact bond's r0, r, stored energy and
    state with 17 digits every `every` steps to bonds.dump; returns its path."""
    os.makedirs(workdir, exist_ok=True)
    ncol = 3 + len(state_slots())
    path = os.path.join(workdir, "bond_dump.inc")
    with open(path, "w", encoding="utf-8") as f:
        f.write("compute bd all pair/gran/local/bond r0 r energy_stored state\n"
                f"dump bonds all local {every} bonds.dump " + " ".join(f"c_bd[{k}]" for k in range(1, ncol + 1)) +
                "\n" + 'dump_modify bonds format "' + " ".join(["%.17g"] * ncol) + '"\n')
    return path


# The elastic block's bond (free_body_budget_liggghts.in, elastic 1): spheres
# of 1 mm radius, lambda 0.5, and its stiffnesses per unit area.
ELASTIC_BOND = {"rb": 0.5e-3, "k_fn1": 2e7, "k_fn2": 2e9, "eps": 1e-4, "k_ft": 4e8, "k_tn": 8e8, "k_tt": 8e8}


def loading_curve_energy(r0, r, state):
    """The energy an elastic bond (ku = k, kc = 0) of ELASTIC_BOND stores for
    its state: each law's loading curve integrated from zero deformation
    (docs/models/bond-nonlinear.md, "Energy"; the core's elastic_energy)."""
    p = ELASTIC_BOND
    area = math.pi * p["rb"] ** 2
    polar = area * p["rb"] ** 2 / 2
    inertia = polar / 2
    d = r0 - r
    if d < 0:
        normal = p["k_fn2"] * area * d * d / 2
    elif d < p["eps"]:
        normal = p["k_fn1"] * area * d * d / (2 * math.sqrt(p["eps"]))
    else:
        normal = p["k_fn1"] * area * (2 / 3 * d ** 1.5 - p["eps"] ** 1.5 / 6)
    norm2 = lambda name: sum(state[name + c] ** 2 for c in "xyz")  # noqa: E731
    return (normal + norm2("shear_force_") / (2 * p["k_ft"] * area) + p["k_tn"] * polar * norm2("twist_angle_") / 2
            + p["k_tt"] * inertia * norm2("bend_angle_") / 2)


def check_stored_is_loading_curve(dump):
    """Each elastic bond's stored energy (energy_stored) is its loading
    curves' energy for its state, bond by bond, at every dumped step."""
    slots = state_slots()
    rows = worst = 0
    parts = set()
    with open(dump, encoding="utf-8") as f:
        lines = f.read().splitlines()
    at = 0
    while at < len(lines):
        if not lines[at].startswith("ITEM: NUMBER OF ENTRIES"):
            at += 1
            continue
        count = int(lines[at + 1])
        while not lines[at].startswith("ITEM: ENTRIES"):
            at += 1
        for line in lines[at + 1:at + 1 + count]:
            values = [float(v) for v in line.split()]
            r0, r, stored = values[:3]
            state = dict(zip(slots, values[3:]))
            want = loading_curve_energy(r0, r, state)
            scale = max(abs(want), 1e-30)
            worst = max(worst, abs(stored - want) / scale)
            if abs(stored - want) > 1e-9 * scale:
                raise Failure(f"bonds.dump: a bond (r0 {r0:.17g}, r {r:.17g}) stores {stored:.17g} J, its loading "
                              f"curves {want:.17g} J")
            parts.update(name for name in ("shear_force_x", "twist_angle_x", "bend_angle_x") if state[name] != 0)
            parts.add("tension" if r > r0 else "compression")
            rows += 1
        at += 1 + count
    if rows == 0 or len(parts) < 5:
        raise Failure(f"bonds.dump: {rows} rows, deformed in {sorted(parts)} only")
    print(f"ok: elastic block: each of {rows} bond rows stores its loading curves' energy for its state (within "
          f"{worst:.2g} of it; {', '.join(sorted(parts))})")


def check_liggghts_restart_budget(a, n, workdir):
    """The bonds that do not break, half the run, a restart file, the other
    half: after the restart as before it, the intact bonds' own energies add
    up to the budget's, which goes on through the file."""
    d = os.path.join(workdir, f"np{n}-restart")
    first = run(a, n, "free_body_budget_liggghts.in", d, {"stage": "2", "unbroken": "1"})
    second = run(a, n, "free_body_budget_liggghts.in", d, {"stage": "3", "unbroken": "1"})
    for label, text in (("before", first), ("after", second)):
        if thermo_column(text, "c_bc[2]")[-1] != 0:
            raise Failure(f"{n} ranks, {label} the restart file: bonds broke")
        check_bond_energies(text, n, "liggghts", 1e-13)
    damping = thermo_column(second, "c_en[2]")
    if not damping[0] >= thermo_column(first, "c_en[2]")[-1] > 0:
        raise Failure(f"{n} ranks: the damping's energy was {thermo_column(first, 'c_en[2]')[-1]:.17g} J at the "
                      f"restart file, {damping[0]:.17g} J after it")
    print(f"ok: {n} ranks, through a restart file: the intact bonds' own energies add up to the budget's before and "
          f"after it (damping {damping[-1]:.4g} J at the end)")


def check_budget(a, workdir):
    liggghts = a.kind == "liggghts"
    # LIGGGHTS: its counter is compute bond/counter, the budget compute granbond/energy
    deck = "free_body_budget_liggghts.in" if liggghts else "free_body_budget.in"
    counts = ("c_bc[1]", "c_bc[2]") if liggghts else ("c_pg[1]", "c_pg[2]")
    terms = ("c_en[2]", "c_en[3]", "c_en[4]") if liggghts else ("c_pg[9]", "c_pg[10]", "c_pg[11]")
    elastic_dir = os.path.join(workdir, "elastic")
    if liggghts:
        elastic = run(a, 1, deck, elastic_dir, {"elastic": "1", "dumpdeck": bond_dump_deck(elastic_dir, 500)})
        check_stored_is_loading_curve(os.path.join(elastic_dir, "bonds.dump"))
    else:
        elastic = run(a, 1, deck, elastic_dir, {"elastic": "1"})
    _, integrator = budget_drift(elastic)
    # the yardstick itself: elastic bonds conserve kinetic + stored energy
    if integrator > 1e-5:
        raise Failure(f"elastic block: kinetic + stored energy moved by {integrator:.3g} of itself")
    for n in [1, 2] if a.mpiexec else [1]:
        d = os.path.join(workdir, f"np{n}")
        text = run(a, n, deck, d)
        total, drift = budget_drift(text)
        created, broken = thermo_column(text, counts[0])[-1], thermo_column(text, counts[1])[-1]
        shares = {name: thermo_column(text, col)[-1] / total[0]
                  for name, col in zip(("damping", "hysteresis", "released"), terms)}
        if not 0 < broken < created or min(shares.values()) < 0.01:
            raise Failure(f"{n} ranks: {broken:g} of {created:g} bonds broke; shares of the budget {shares}")
        if drift > 2 * integrator:
            raise Failure(f"{n} ranks: the budget moved by {drift:.3g} of itself, kinetic + stored energy of the "
                          f"elastic block by {integrator:.3g}")
        # LIGGGHTS: the same numbers summed in the same order on each rank
        check_bond_energies(text, n, a.kind, 1e-13 if liggghts else 1e-9)
        print(f"ok: {n} ranks: {broken:g} of {created:g} bonds broke; damping {shares['damping']:.3f}, hysteresis "
              f"{shares['hysteresis']:.3f}, released {shares['released']:.3f} of the budget, which moved by "
              f"{drift:.2g} of itself (elastic block: {integrator:.2g}); the intact bonds' own energies add up to "
              f"the budget's")
        if liggghts:
            check_liggghts_restart_budget(a, n, workdir)
            continue
        # half the run, a restart file, the other half: the sums come back
        text = run(a, n, "free_body_budget.in", os.path.join(workdir, f"np{n}-restart"), {"restart": "1"})
        _, drift = budget_drift(text)
        if drift > 2 * integrator or thermo_column(text, "c_pg[2]")[-1] != broken:
            raise Failure(f"{n} ranks, through a restart file: the budget moved by {drift:.3g} of itself, "
                          f"{thermo_column(text, 'c_pg[2]')[-1]:g} bonds broke ({broken:g} without)")
        print(f"ok: {n} ranks, through a restart file: the budget moved by {drift:.2g} of itself")


if __name__ == "__main__":
    run_modes(__doc__, {"newton": check_newton, "switch": check_switch, "settype": check_settype, "data": check_data,
                         "rerun": check_rerun, "momentum": check_momentum, "energy": check_energy,
                         "insert": check_insert, "edge": check_edge, "wallinsert": check_wall_insert,
                         "budget": check_budget})
