"""Bad input of every granbond keyword: each run stops with an error naming it, warns, or runs.

Small valid base decks of both engines (decks/mutation/) are run with one
granbond input mutated at a time: every keyword of the LAMMPS `pair_coeff`
line (the values after `voigt` and of each phrase included), every
granbond `fix property/global` line and every granbond switch of the
LIGGGHTS `pair_style gran` and `fix wall/gran` lines, each given a bad
value (0, -0, 1e-300, 1e300, nan, inf, a word, no value, or repeated with
another value; a switch: a word, 1, no value, repeated with the other
state; a property line: also deleted). Each run is classified:

  named    stopped with an ERROR line naming the mutated word
  unnamed  stopped with ERROR lines none of which names it
  warned   ran, with a WARNING the base deck does not give
  ran      ran as the base deck does
  nan      printed nan in a thermo row
  crash    ended by a signal or an uncaught C++ exception
  hang     still running after the timeout

The check fails on any crash, hang, nan or unnamed error. By default it
runs a sample (each keyword with two of the values, in rotation, and the
cases the bad-input issue found); `--all` runs every keyword with every
value and `--report` prints the table without failing
(scripts/bad_input_campaign.sh).

usage: check_deck_mutations.py --liggghts EXE --lammps EXE --workdir DIR [--all] [--report] [--jobs N]
"""

import argparse
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))
from deck_runner import Failure, main  # noqa: E402

DECKS = os.path.join(HERE, "decks", "mutation")
TIMEOUT_S = 60
MISSING, REPEAT, DELETE = "<no value>", "<repeated>", "<line deleted>"
NUMBER_VALUES = ["0", "-0", "1e-300", "1e300", "nan", "inf", "word", MISSING, REPEAT]
SWITCH_VALUES = ["maybe", "1", MISSING, REPEAT]
CATEGORIES = ["named", "unnamed", "warned", "ran", "nan", "crash", "hang"]
FAILING = {"unnamed", "nan", "crash", "hang"}

# (engine, base deck, property names that are the engine's, not granbond's)
BASES = [
    ("lammps", "lammps_stress.in", set()),
    ("lammps", "lammps_distance.in", set()),
    ("liggghts", "liggghts_stress.in", {"youngsModulus", "poissonsRatio", "coefficientRestitution",
                                        "coefficientFriction"}),
    ("liggghts", "liggghts_voigt.in", set()),
]
# Switches of the LIGGGHTS lines that are granbond's (the bond's and voigt's).
LIGGGHTS_SWITCHES = {"stressBreak", "ratioTensionCompressionBond", "createBondAlways", "historyReset",
                     "dampingBond", "dampingBondSmooth", "tensionStress", "compressionStress", "shearStress",
                     "normalTorqueStress", "shearTorqueStress", "noAttraction", "contactUnderBond"}
VOIGT_HEAD = ["k_n", "gamma_n", "k_t", "gamma_t", "mu"]
ROLLING = ["k_r", "gamma_r", "mu_r", "eta_r"]
PHRASE_VALUES = {("break", "stress"): ["max_sigma", "max_tau"], ("break", "distance"): ["max_distance"]}


class Target:
    """One value a deck gives: where it is and the words an error must name."""

    def __init__(self, label, names, kind, line, pos, keyword):
        self.label, self.names, self.kind = label, names, kind
        self.line, self.pos, self.keyword = line, pos, keyword


def other_value(value, kind):
    """A different valid value of the same kind, for a conflicting repeat."""
    if kind == "switch":
        return {"yes": "no", "no": "yes", "on": "off", "off": "on"}[value]
    if kind == "int":
        return str(int(value) + 1)
    return repr(float(value) * 2.0)


def lammps_targets(lines):
    """The values of the pair_coeff statement (one logical line)."""
    start = next(k for k, l in enumerate(lines) if l.startswith("pair_coeff"))
    words = lines[start].split()[3:]
    targets, k = [], 0
    assert words[0] == "voigt"
    k = 1
    for name in VOIGT_HEAD:
        targets.append(Target(f"voigt {name}", [name, "voigt"], "real", start, 3 + k, None))
        k += 1
    while k < len(words):
        w = words[k]
        if w == "bond/nonlinear":
            k += 1
        elif w == "rolling":
            for j, name in enumerate(ROLLING):
                targets.append(Target(f"rolling {name}", [name, "rolling"], "real", start, 3 + k + 1 + j, k + 3))
            k += 1 + len(ROLLING)
        elif w == "break":
            names = PHRASE_VALUES[(w, words[k + 1])]
            for j, name in enumerate(names):
                targets.append(Target(f"break {words[k + 1]} {name}", [name, f"break {words[k + 1]}"], "real",
                                      start, 3 + k + 2 + j, k + 3))
            k += 2 + len(names)
        else:
            value = words[k + 1]
            kind = "switch" if value in ("yes", "no") else "int" if w == "create_step" else "real"
            targets.append(Target(w, [w], kind, start, 3 + k + 1, k + 3))
            k += 2
    return targets


def liggghts_targets(lines, skip):
    targets = []
    for n, line in enumerate(lines):
        w = line.split()
        if len(w) > 4 and w[0] == "fix" and w[3] == "property/global" and w[4] not in skip:
            targets.append(Target(w[4], [w[4]], "int" if w[5] == "scalar" and "ts" in w[4] else "real", n,
                                  len(w) - 1, 4))
        elif w[:2] == ["pair_style", "gran"] or (len(w) > 3 and w[0] == "fix" and w[3] == "wall/gran"):
            where = "wall " if w[0] == "fix" else ""
            for k in range(len(w) - 1):
                if w[k] in LIGGGHTS_SWITCHES and w[k + 1] in ("on", "off"):
                    targets.append(Target(f"{where}{w[k]}", [w[k]], "switch", n, k + 1, k))
    return targets


def logical_lines(text):
    """The deck's lines with '&' continuations joined."""
    out, pending = [], ""
    for line in text.splitlines():
        if line.rstrip().endswith("&"):
            pending += line.rstrip()[:-1] + " "
        else:
            out.append(pending + line)
            pending = ""
    return out


def mutate(lines, t, value, engine):
    """The deck's lines with target `t` given `value`."""
    lines = list(lines)
    w = lines[t.line].split()
    original = w[t.pos]
    if value == DELETE:
        lines[t.line] = "# deleted: " + lines[t.line]
    elif value == MISSING:
        if t.kind == "switch" and engine == "liggghts":
            # a switch without a value at the end of its line
            name = w[t.keyword]
            del w[t.keyword:t.pos + 1]
            w.append(name)
        else:
            del w[t.pos]
        lines[t.line] = " ".join(w)
    elif value == REPEAT:
        again = other_value(original, t.kind)
        if engine == "liggghts" and t.kind != "switch":
            extra = w[:]
            extra[1] += "again"
            extra[-1] = again
            lines.insert(t.line + 1, " ".join(extra))
        elif engine == "liggghts":
            w += [w[t.keyword], again]
            lines[t.line] = " ".join(w)
        elif t.keyword is None or t.label.startswith("rolling"):
            # a voigt value: its keyword right after the values of `voigt`
            w.insert(3 + 1 + len(VOIGT_HEAD), f"{t.names[0]} {again}")
            lines[t.line] = " ".join(w)
        elif t.label.startswith("break"):
            phrase = w[t.keyword:t.keyword + 2]
            count = len(PHRASE_VALUES[tuple(phrase)])
            w += phrase + [other_value(v, "real") for v in w[t.keyword + 2:t.keyword + 2 + count]]
            lines[t.line] = " ".join(w)
        else:
            w += [w[t.keyword], again]
            lines[t.line] = " ".join(w)
    else:
        w[t.pos] = value
        lines[t.line] = " ".join(w)
    return lines


THERMO_ROW = re.compile(r"^\s*\d+(\s+\S+)+\s*$")
NAN = re.compile(r"(?<![A-Za-z])[-+]?nan\b", re.IGNORECASE)


def run(command, lines, workdir):
    """(exit code or None on timeout, screen + log)."""
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    with open(os.path.join(workdir, "in.deck"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    try:
        proc = subprocess.run(list(command) + ["-in", "in.deck", "-log", "log.txt"], cwd=workdir,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=TIMEOUT_S, check=False)
    except subprocess.TimeoutExpired:
        return None, ""
    text = proc.stdout.decode("utf-8", "replace")
    log = os.path.join(workdir, "log.txt")
    if os.path.exists(log):
        with open(log, encoding="utf-8", errors="replace") as f:
            text += "\n" + f.read()
    return proc.returncode, text


def warnings_of(text):
    return {re.sub(r"\s*\(.*:\d+\)$", "", l.strip()) for l in text.splitlines() if l.startswith("WARNING")}


def classify(rc, text, names, base_warnings):
    """The category of a run, and the line that decided it."""
    if rc is None:
        return "hang", f"still running after {TIMEOUT_S} s"
    crash = re.search(r"terminate called|Segmentation fault|Aborted|core dumped|std::logic_error", text)
    if rc < 0 or rc >= 128 or crash:
        return "crash", f"exit {rc}" + (f": {crash.group(0)}" if crash else "")
    for line in text.splitlines():
        if THERMO_ROW.match(line) and NAN.search(line):
            return "nan", line.strip()
    if rc != 0:
        errors = [l.strip() for l in text.splitlines() if "ERROR" in l]
        for line in errors:
            message = re.sub(r"\s*\([^()]*:\d+\)$", "", line)
            if any(n in message for n in names):
                return "named", line
        return "unnamed", errors[0] if errors else text.strip().splitlines()[-1:]
    fresh = warnings_of(text) - base_warnings
    if fresh:
        return "warned", sorted(fresh)[0]
    return "ran", ""


def cases(all_values):
    """(engine, deck, target, value) of every run."""
    out = []
    for engine, deck, skip in BASES:
        with open(os.path.join(DECKS, deck), encoding="utf-8") as f:
            lines = logical_lines(f.read())
        targets = lammps_targets(lines) if engine == "lammps" else liggghts_targets(lines, skip)
        for i, t in enumerate(targets):
            values = SWITCH_VALUES if t.kind == "switch" else list(NUMBER_VALUES)
            if engine == "liggghts" and t.kind != "switch":
                values.append(DELETE)
            if all_values:
                chosen = values
            else:
                chosen = [values[(2 * i) % len(values)], values[(2 * i + 1) % len(values)]]
                # the defects the bad-input issue found stay in the sample
                if t.kind == "switch" and engine == "liggghts":
                    chosen.append(MISSING)
                if t.label in ("k_fn1", "compression_linear_below", "stiffnessPerUnitAreaK_fn1",
                               "compressionLinearBelowBondnonlinear", "create_distance", "break stress max_sigma",
                               "break distance max_distance"):
                    chosen += ["0", "1e300", REPEAT]
            for v in dict.fromkeys(chosen):
                out.append((engine, deck, lines, t, v))
    return out


def check(args):
    commands = {"lammps": [args.lammps], "liggghts": [args.liggghts]}
    base_warnings = {}
    for engine, deck, _ in BASES:
        with open(os.path.join(DECKS, deck), encoding="utf-8") as f:
            lines = logical_lines(f.read())
        rc, text = run(commands[engine], lines, os.path.join(args.workdir, "base_" + deck))
        if rc != 0:
            raise Failure(f"the base deck {deck} does not run (exit {rc}):\n{text[-2000:]}")
        base_warnings[deck] = warnings_of(text)

    todo = cases(args.all)

    def one(k):
        engine, deck, lines, t, value = todo[k]
        rc, text = run(commands[engine], mutate(lines, t, value, engine), os.path.join(args.workdir, f"run{k}"))
        category, why = classify(rc, text, t.names, base_warnings[deck])
        if category not in FAILING:
            shutil.rmtree(os.path.join(args.workdir, f"run{k}"), ignore_errors=True)
        return engine, deck, t.label, value, category, why, k

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(one, range(len(todo))))

    table = {e: {c: 0 for c in CATEGORIES} for e in ("liggghts", "lammps")}
    failures = []
    for engine, deck, label, value, category, why, k in results:
        table[engine][category] += 1
        if args.verbose or category in FAILING:
            print(f"{category:8} {deck}: {label} = {value}: {why}")
        if category in FAILING:
            failures.append(f"{deck}: {label} = {value}: {category}: {why} (deck: run{k}/in.deck)")
    print()
    print("| | " + " | ".join(CATEGORIES) + " |")
    print("|---" * (len(CATEGORIES) + 1) + "|")
    for engine in ("liggghts", "lammps"):
        total = sum(table[engine].values())
        print(f"| {engine}, {total} runs | " + " | ".join(str(table[engine][c]) for c in CATEGORIES) + " |")
    if failures and not args.report:
        raise Failure(f"{len(failures)} of {len(results)} runs crashed, hung, gave nan or stopped without "
                      "naming the input:\n" + "\n".join(failures))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", required=True)
    parser.add_argument("--lammps", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--all", action="store_true", help="every keyword with every value")
    parser.add_argument("--report", action="store_true", help="print the table, do not fail")
    parser.add_argument("--verbose", action="store_true", help="print every run")
    parser.add_argument("--jobs", type=int, default=2)
    a = parser.parse_args()
    main(lambda: check(a))
