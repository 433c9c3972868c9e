"""Reading and analysing the flicked chain's output (shared by plot.py and
the ctest tests/adapters/check_flicked_chain.py).

chain.txt: step, then x z vx omega_y of spheres 2..5 (fix print).
bonds dump (dump local of compute pair/gran/local/bond id status state):
id1 id2 status, then the bond state slots in the core's order (rest
delta_max delta_min shear_force_xyz twist_angle_xyz bend_angle_xyz twist_max
twist_min bend_history_xyz bend_opposite).
"""

DT = 1.0e-6
# 0-based columns of the bonds dump
ID1, ID2, STATUS = 0, 1, 2
BEND_Y, BEND_HISTORY_Y, BEND_OPPOSITE = 13, 18, 20
K_OVER_KU = 0.5


def load_chain(path):
    rows = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(v) for v in line.split()])
    return rows


def load_bond_angles(path):
    """{(id1, id2): [(step, bend_y, beta_y, beta_opp)]} from the bonds dump."""
    series = {}
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            count = int(lines[k + 3])
            for line in lines[k + 9:k + 9 + count]:
                v = [float(c) for c in line.split()]
                if v[STATUS] != 1.0:
                    continue
                key = (int(v[ID1]), int(v[ID2]))
                series.setdefault(key, []).append((step, v[BEND_Y], v[BEND_HISTORY_Y], v[BEND_OPPOSITE]))
            k += 9 + count
        else:
            k += 1
    return series


def last_fifth(values):
    return values[len(values) * 4 // 5:]


def residual(samples):
    """(mean bending angle over the last fifth, the residual the law
    predicts, its range over the last fifth). The bend is planar (about y),
    so the signed angle is its y component; the leading side is the sign of
    beta_y. A bond that ends on the leading side's unloading line rests at
    (1 - k/ku) beta, one on the opposite side at -(1 - k/ku) beta_opp."""
    tail = last_fifth(samples)
    angles = [s[1] for s in tail]
    mean = sum(angles) / len(angles)
    _, bend, beta, beta_opp = tail[-1]
    leading = bend * beta >= 0.0
    predicted = (1 - K_OVER_KU) * (beta if leading else -beta_opp if beta > 0 else beta_opp)
    return mean, predicted, (min(angles), max(angles))


def amplitude(values):
    return (max(values) - min(values)) / 2


def top_amplitudes(rows):
    """Sideways amplitude of the top sphere over the first and the last
    fifth of the run."""
    x = [r[13] for r in rows]
    return amplitude(x[:len(x) // 5]), amplitude(last_fifth(x))


def residual_summary(series):
    lines = ["bond  mean bend (last fifth)  (1-k/ku) x extreme"]
    for key in sorted(series):
        mean, predicted, _ = residual(series[key])
        lines.append(f"{key[0]}-{key[1]}   {mean: .4e}            {predicted: .4e}")
    return lines
