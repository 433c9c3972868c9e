"""granbond bond/nonlinear against BPM bpm/rotational on the chain tension
cycle: chain force against elongation (tension zoom and whole cycle) and
over time.

    python3 plot.py OUTDIR    (OUTDIR holds bpm.txt, granbond.txt, granbond_eta.txt)
writes OUTDIR/bpm_beam.png and prints the measured stiffnesses.
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import beam  # noqa: E402

AMP, PERIOD = 1e-4, 0.1        # the deck's defaults (run.sh)
RUNS = (("bpm.txt", "BPM bpm/rotational (linear spring)", "tab:blue", "-"),
        ("granbond.txt", "granbond bond/nonlinear, eta = 0", "tab:red", "--"),
        ("granbond_eta.txt", "granbond bond/nonlinear, eta = 0.2", "tab:orange", ":"))


def main(out):
    fig, axes = plt.subplots(1, 3, figsize=(16, 5))
    k_expected = beam.expected_tension_stiffness()
    for name, label, colour, style in RUNS:
        rows = beam.read(os.path.join(out, name))
        el = [r[1] * 1e6 for r in rows]
        f = [beam.chain_force(r) for r in rows]
        t = [r[0] * 1e-3 for r in rows]          # ms (dt = 1 us)
        k = beam.virgin_tension_stiffness(rows, AMP, PERIOD)
        print(f"{label}: virgin tension stiffness {k:.4g} N/m "
              f"({k / k_expected:.4f} x k_fn2 A / (N-1) = {k_expected:.4g} N/m)")
        axes[0].plot(el, [x * 1e3 for x in f], color=colour, ls=style, label=f"{label}: {k:.1f} N/m")
        axes[1].plot(el, f, color=colour, ls=style, label=label)
        axes[2].plot(t, f, color=colour, ls=style, label=label)
    axes[0].set_ylim(-15, 15)
    axes[0].set_title("tension branch (zoom): same linear spring,\npercentage damping stiffens loading")
    axes[0].set_xlabel("chain elongation (um)")
    axes[0].set_ylabel("chain force (mN, tension > 0)")
    axes[1].set_yscale("symlog", linthresh=1e-2)
    axes[1].set_title("whole cycle: granbond's sqrt law in compression\nand unloading on ku (hysteresis)")
    axes[1].set_xlabel("chain elongation (um)")
    axes[1].set_ylabel("chain force (N, symlog)")
    axes[2].set_yscale("symlog", linthresh=1e-2)
    axes[2].set_xlabel("time (ms)")
    axes[2].set_ylabel("chain force (N, symlog)")
    axes[2].set_title(f"pulled end: wiggle {AMP * 1e6:.0f} um, period {PERIOD * 1e3:.0f} ms")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    path = os.path.join(out, "bpm_beam.png")
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
