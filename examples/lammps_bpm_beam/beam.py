"""Reading and measuring the beam runs of in.lammps_bpm_beam (used by
plot.py and by the ctest lammps_bpm-beam).

A row: step, elongation of the chain, force of the chain on the pulled
sphere (x), on the held sphere (x). The chain force is the mean of the two
(the same in a static chain; the mean cancels the drag on the free spheres
to first order), positive in tension.
"""
import math

NSPHERES = 10                  # the deck's default
RADIUS = 1e-3                  # m
AREA = math.pi * (0.5 * RADIUS) ** 2   # bond cross-section, lambda = 0.5
K_FN2 = 1e9                    # N/m^3, virgin tension (params.in)
K_FN1 = 1e9                    # N/m^2.5, virgin compression (params.in)


def read(path):
    rows = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(c) for c in line.split()])
    return rows


def chain_force(row):
    """Tension > 0: the chain pulls the pulled sphere back (-x)."""
    return 0.5 * (row[3] - row[2])


def expected_tension_stiffness(nspheres=NSPHERES):
    """N - 1 identical springs k_fn2 A in series."""
    return K_FN2 * AREA / (nspheres - 1)


def expected_compression_force(shortening, nspheres=NSPHERES):
    """Virgin compression of every bond by shortening / (N - 1): k_fn1 A d^1/2."""
    return K_FN1 * AREA * math.sqrt(shortening / (nspheres - 1))


def virgin_tension_stiffness(rows, amp, period, dt=1e-6):
    """Least-squares slope of chain force against elongation over the first
    quarter period (virgin tension), elongations between 0.3 and 0.95 amp."""
    quarter = period / 4 / dt
    pts = [(r[1], chain_force(r)) for r in rows
           if 0 < r[0] <= quarter and 0.3 * amp <= r[1] <= 0.95 * amp]
    if len(pts) < 10:
        raise ValueError(f"only {len(pts)} samples in the virgin tension window")
    n = len(pts)
    mx = sum(p[0] for p in pts) / n
    my = sum(p[1] for p in pts) / n
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in pts)
    return sxy / sxx


def at_step(rows, step):
    for r in rows:
        if r[0] == step:
            return r
    raise ValueError(f"no row at step {step}")
