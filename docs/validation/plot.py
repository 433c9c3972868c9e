"""Draws the figures of docs/validation.md from the JSON files that
tests/validation/check_validation.py --json writes (make-figures.sh).

    plot.py JSON_DIR OUT_DIR

The closed-form curves come from tests/validation/closed_forms.py, the same
functions the tests check against; the points are the engines' runs.
"""

import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests", "validation"))
import closed_forms as cf  # noqa: E402

STYLE = {"liggghts": dict(marker="o", mfc="none", color="C0", ls="none", label="LIGGGHTS"),
         "lammps": dict(marker="x", color="C3", ls="none", label="LAMMPS")}


def load(d, name):
    path = os.path.join(d, f"{name}.json")
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as f:
        return json.load(f)["series"]


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"{name}.png"), dpi=110)
    plt.close(fig)
    print(f"wrote {name}.png")


def normal(d, out):
    s = load(d, "normal")
    if not s:
        return
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    et = np.linspace(0.05, 1.0, 200)
    zeta = [cf.zeta_for_restitution(e) for e in et]
    ax[0].plot(et, et, "k-", lw=1, label="closed form, attraction allowed")
    ax[0].plot(et, [cf.restitution_no_attraction(z) for z in zeta], "k--", lw=1,
               label="closed form, noAttraction")
    ax[1].plot(et, [1 / math.sqrt(1 - z * z) for z in zeta], "k-", lw=1)
    ax[1].plot(et, [(math.pi - 2 * math.asin(z)) / (math.pi * math.sqrt(1 - z * z)) for z in zeta], "k--", lw=1)
    markers = {"wall": "o", "pair": "s"}
    colors = {"liggghts": "C0", "lammps": "C3"}
    for key, pts in s.items():
        eng, geom, attr = key.split("_")
        kw = dict(marker=markers[geom], color=colors[eng], ls="none", ms=6 if eng == "liggghts" else 4,
                  mfc="none" if eng == "liggghts" else colors[eng])
        label = f"{eng} {geom}" if attr == "attr" else None
        ax[0].plot([p["e_target"] for p in pts], [p["e"] for p in pts], label=label, **kw)
        ax[1].plot([p["e_target"] for p in pts], [p["t"] / p["t0"] for p in pts], **kw)
    ax[0].set_xlabel("target restitution e (design: gamma_n from the attraction-allowed formula)")
    ax[0].set_ylabel("measured restitution")
    ax[1].set_xlabel("target restitution e")
    ax[1].set_ylabel("contact time / (pi sqrt(m_eff/k_n))")
    ax[0].legend(fontsize=7)
    ax[0].set_title("Chung & Ooi test 3: normal impact, voigt", fontsize=9)
    ax[1].set_title("contact time (force nonzero)", fontsize=9)
    save(fig, out, "normal")


def oblique(d, out):
    s = load(d, "oblique")
    if not s:
        return
    thr = s["threshold"][0]["deg"]
    mu, e, v0, radius = 0.092, 0.98, 3.9, 2.5e-3
    deg = np.linspace(thr, 89, 200)
    closed = [cf.oblique_gross_sliding(math.radians(x), v0, radius, mu, e) for x in deg]
    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    for i, (key, lab) in enumerate((("et", "tangential restitution v_t'/v_t"), ("spin", "rebound spin [rad/s]"),
                                    ("rebound", "contact-point rebound angle [deg]"))):
        ys = [c[i] if i < 2 else math.degrees(c[2]) for c in closed]
        ax[i].plot(deg, ys, "k-", lw=1, label="closed form (gross sliding)")
        ax[i].axvspan(0, thr, color="0.9", label="not gross sliding: no closed form")
        for eng in ("liggghts", "lammps"):
            if eng in s:
                ax[i].plot([p["deg"] for p in s[eng]], [p[key] for p in s[eng]], **STYLE[eng])
        ax[i].set_xlabel("incident angle [deg]")
        ax[i].set_ylabel(lab)
        ax[i].set_xlim(0, 90)
    ax[0].legend(fontsize=7)
    ax[1].set_title("Chung & Ooi test 4: oblique impact on a plane, 3.9 m/s, mu = 0.092, e = 0.98", fontsize=9)
    save(fig, out, "oblique")


def spinning(d, out):
    s = load(d, "spinning")
    if not s:
        return
    thr = s["threshold"][0]["w0"]
    v0, mu, e, radius = 0.05, 0.092, 0.98, 2.5e-3
    w = np.linspace(thr, 110, 100)
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot(w, [cf.spinning_pair_gross_sliding(x, v0, radius, mu, e)[0] for x in w], "k-", lw=1,
               label="closed form (gross sliding)")
    ax[1].plot(w, [cf.spinning_pair_gross_sliding(x, v0, radius, mu, e)[1] for x in w], "k-", lw=1)
    for a in ax:
        a.axvspan(0, thr, color="0.9", label="sticks before the end: no closed form")
        a.set_xlabel("initial spin of each sphere w0 [rad/s]")
    for eng in ("liggghts", "lammps"):
        if eng in s:
            ax[0].plot([p["w0"] for p in s[eng]], [p["vy2"] for p in s[eng]], **STYLE[eng])
            ax[1].plot([p["w0"] for p in s[eng]], [p["w2"] for p in s[eng]], **STYLE[eng])
    ax[0].set_ylabel("sideways speed after [m/s]")
    ax[1].set_ylabel("spin after [rad/s]")
    ax[0].legend(fontsize=7)
    ax[0].set_title("two spheres spinning the same way, head on, +-0.05 m/s", fontsize=9)
    save(fig, out, "spinning")


def tangential(d, out):
    s = load(d, "tangential")
    if not s:
        return
    r = np.linspace(0, 1.6, 300)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(r, [cf.tangential_ratio_no_slip(x) for x in r], "k-", lw=1, label="cos(pi sqrt(7 kt / 2 kn))")
    for eng in ("liggghts", "lammps"):
        if eng in s:
            ax.plot([p["ratio"] for p in s[eng]], [p["measured"] for p in s[eng]], **STYLE[eng])
    ax.set_xlabel("kt / kn")
    ax.set_ylabel("contact-point tangential velocity after / before")
    ax.set_title("linear tangential spring without slip (mu = 1e6, no damping)", fontsize=9)
    ax.legend(fontsize=7)
    save(fig, out, "tangential")


def rolling(d, out):
    s = load(d, "rolling")
    t = load(d, "spindown")
    if not s:
        return
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    roll = s["roll"][0]
    tt = np.array(roll["t"])
    ax[0].plot(tt, roll["vx"], "C0.", ms=2, label="LIGGGHTS")
    ax[0].plot(tt, np.maximum(roll["v0"] - roll["a"] * tt, 0), "k-", lw=1, label="v0 - 5/7 mu_r g t")
    ax[0].set_xlabel("t [s]")
    ax[0].set_ylabel("v [m/s]")
    ax0b = ax[0].twinx()
    ax0b.plot(tt, np.array(roll["x"]) * 1e3, "C2-", lw=1, label="x (LIGGGHTS)")
    ax0b.axhline(roll["x_stop"] * 1e3, color="C2", ls="--", lw=1, label="7 v0^2 / (10 mu_r g)")
    ax0b.set_ylabel("x [mm]")
    ax[0].legend(fontsize=7, loc="center left")
    ax0b.legend(fontsize=7, loc="center right")
    ax[0].set_title("sphere launched rolling, mu_r = 0.05", fontsize=9)
    inc = s["incline"]
    r = np.linspace(0, 4.2, 200)
    closed = [max(0.0, cf.rolling_deceleration(0.05, math.atan(x * 0.05))) for x in r]
    ax[1].plot(r, closed, "k-", lw=1, label="0 if tan(alpha) < mu_r, else 5/7 g (sin - mu_r cos)")
    ax[1].plot([p["ratio"] for p in inc], [p["acc"] if p["ratio"] > 1 else 0.0 for p in inc], "C0o", mfc="none",
               label="LIGGGHTS (staying: 0, it rocks in place)")
    ax[1].set_xlabel("tan(alpha) / mu_r")
    ax[1].set_ylabel("acceleration down the slope [m/s^2]")
    ax[1].legend(fontsize=7)
    ax[1].set_title("incline: roll or stay", fontsize=9)
    if t:
        for key, pts in t.items():
            eng, name = key.split("_")
            p = pts[0]
            ax[2].plot(p["t"][::10], p["w"][::10], STYLE[eng]["marker"], color=STYLE[eng]["color"], ms=3,
                       mfc="none", label=f"{eng} {name}")
            ax[2].plot(p["t"], p["w_x"], "k-", lw=0.7)
        ax[2].set_xlabel("t [s]")
        ax[2].set_ylabel("spin [rad/s]")
        ax[2].set_title("spin-down on a frictionless plane (lines: closed forms)", fontsize=9)
        ax[2].legend(fontsize=6)
    save(fig, out, "rolling")


def hertz(d, out):
    s = load(d, "hertz")
    if not s:
        return
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for i, (geom, title) in enumerate((("pair", "Chung & Ooi test 1: glass spheres, +-10 m/s"),
                                       ("wall", "Chung & Ooi test 2: aluminium alloy on a plane, 0.2 m/s"))):
        c = s[f"{geom}_closed"][0]
        dd = np.linspace(0, c["d_h"], 200)
        ax[i].plot(dd * 1e6, 4 / 3 * c["e_star"] * math.sqrt(c["r_eff"]) * dd**1.5 / 1e3, "k-", lw=1,
                   label="Hertz theory")
        ax[i].plot(dd * 1e6, c["kn"] * dd / 1e3, "k--", lw=1, label="linear kn d, same max overlap")
        h = s[f"{geom}_hertz"][0]
        v = s[f"{geom}_voigt"][0]
        ax[i].plot(np.array(h["overlap"][::25]) * 1e6, np.array(h["force"][::25]) / 1e3, "C1^", ms=4, mfc="none",
                   label="LIGGGHTS model hertz (comparison)")
        ax[i].plot(np.array(v["overlap"][::25]) * 1e6, np.array(v["force"][::25]) / 1e3, "C0o", ms=4, mfc="none",
                   label="granbond voigt (LIGGGHTS)")
        ax[i].set_xlabel("overlap [um]")
        ax[i].set_ylabel("normal force [kN]")
        ax[i].set_title(title, fontsize=9)
        ax[i].legend(fontsize=7)
    save(fig, out, "hertz")


def bonds(d, out):
    c = load(d, "cantilever")
    b = load(d, "beam-frequency")
    w = load(d, "chain-waves")
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    if c:
        sh = c["shape"][0]
        ax[0].plot(np.array(sh["x"]) * 1e3, np.array(sh["eb"]) * 1e6, "k-", lw=1,
                   label="Euler-Bernoulli + Timoshenko")
        ax[0].plot(np.array(sh["x"]) * 1e3, np.array(sh["w"]) * 1e6, "C0o", mfc="none", label="LIGGGHTS")
        ax[0].set_xlabel("x [mm]")
        ax[0].set_ylabel("deflection [um]")
        ax[0].set_title("cantilever, 21 spheres, 5e-5 N at the tip", fontsize=9)
        ax[0].legend(fontsize=7)
    if b:
        cl = b["closed"][0]
        for eng in ("liggghts", "lammps"):
            if eng in b:
                p = b[eng][0]
                ax[1].plot(np.array(p["t"]) * 1e3, np.array(p["z"]) * 1e6, color=STYLE[eng]["color"], lw=1,
                           ls="-" if eng == "liggghts" else ":",
                           label=f"{eng}: w1 = {p['w']:.2f} rad/s")
        ax[1].set_title(f"free cantilever tip: lumped beam w1 = {cl['w_disc']:.2f}, "
                        f"Euler-Bernoulli {cl['w_eb']:.2f} rad/s", fontsize=8)
        ax[1].set_xlabel("t [ms]")
        ax[1].set_ylabel("tip z [um]")
        ax[1].legend(fontsize=7)
    if w:
        m = w["modes"]
        ka = np.linspace(0, math.pi, 200)
        c0 = m[0]["c0"]
        a = 2e-3
        ax[2].plot(ka, c0 * np.sin(ka / 2) / (ka / 2 + 1e-300) * (ka > 0) + c0 * (ka == 0), "k-", lw=1,
                   label="lattice: w = 2 sqrt(K/m) sin(k a/2)")
        ax[2].axhline(c0, color="k", ls="--", lw=1, label="rod: c0 = a sqrt(K/m)")
        ax[2].plot([p["k"] * a for p in m], [p["c"] for p in m], "C3x", label="LAMMPS, modes 1..9")
        ax[2].set_xlabel("k a")
        ax[2].set_ylabel("phase velocity w/k [m/s]")
        ax[2].set_title("axial waves, free chain of 10 bonded spheres", fontsize=9)
        ax[2].legend(fontsize=7)
    save(fig, out, "bonds")


def main():
    d, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    for f in (normal, oblique, spinning, tangential, rolling, hertz, bonds):
        f(d, out)


if __name__ == "__main__":
    main()
