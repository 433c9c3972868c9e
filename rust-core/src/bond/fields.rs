//! What the engines' per-bond outputs show of a bond (LAMMPS `compute
//! granbond/local`, LIGGGHTS `compute pair/gran/local/bond`): named fields
//! read from its pair record (state and the loads of the latest force pass)
//! and the centres of its two spheres. One table names them, so both
//! engines' keywords and the reference pages' columns come from here.
//!
//! Everything is seen from the sphere whose record it is (`i`): the force is
//! the one on `i`, the normal `n` points from `j` to `i`.

use super::laws::BondLaws;
use super::output_slots::{load_output, BOND_OUTPUT_LEN};
use super::state::BondState;

/// One field: its keyword, SI unit and meaning.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BondField {
    /// The keyword of the engines' outputs (a column name).
    pub name: &'static str,
    /// SI unit, `-` when dimensionless.
    pub unit: &'static str,
    /// What the value means, in words.
    pub description: &'static str,
}

const fn field(name: &'static str, unit: &'static str, description: &'static str) -> BondField {
    BondField {
        name,
        unit,
        description,
    }
}

/// Number of fields of [`BOND_FIELDS`].
pub const BOND_FIELD_COUNT: usize = 38;

/// The fields, in the order [`bond_fields`] writes them.
pub const BOND_FIELDS: [BondField; BOND_FIELD_COUNT] = [
    field("status", "-", "1 intact, 2 broken, 0 never bonded"),
    field("r0", "m", "centre distance at creation"),
    field("r", "m", "centre distance now"),
    field("stretch", "m", "r - r0 (positive: stretched)"),
    field(
        "normal_force",
        "N",
        "force on sphere i along n (from j to i) in the latest force pass, damping included; positive pushes the spheres apart",
    ),
    field(
        "shear_force",
        "N",
        "length of the force on sphere i across n in the latest force pass",
    ),
    field("force_x", "N", "force on sphere i, x (latest force pass)"),
    field("force_y", "N", "force on sphere i, y"),
    field("force_z", "N", "force on sphere i, z"),
    field(
        "torque_i",
        "N m",
        "length of the bond's torque on sphere i (latest force pass)",
    ),
    field("torque_j", "N m", "length of the bond's torque on sphere j"),
    field(
        "sigma",
        "Pa",
        "normal stress of the section from the undamped loads (eq. 14)",
    ),
    field(
        "sigma_max",
        "Pa",
        "its limit at the present stretch (sigma_max, times gamma while stretched with ratio); 0 in distance mode",
    ),
    field(
        "sigma_ratio",
        "-",
        "sigma / sigma_max: the bond breaks at 1; 0 in distance mode",
    ),
    field(
        "tau",
        "Pa",
        "shear stress of the section from the undamped loads (eq. 14)",
    ),
    field("tau_max", "Pa", "its limit; 0 in distance mode"),
    field(
        "tau_ratio",
        "-",
        "tau / tau_max: the bond breaks at 1; 0 in distance mode",
    ),
    field(
        "delta_max",
        "m",
        "largest compression r0 - r reached (history)",
    ),
    field(
        "delta_min",
        "m",
        "smallest compression r0 - r reached, negative when stretched (history)",
    ),
    field(
        "twist_max",
        "rad",
        "largest signed twisting angle reached (history)",
    ),
    field(
        "twist_min",
        "rad",
        "smallest signed twisting angle reached (history)",
    ),
    field(
        "bend_leading",
        "rad",
        "length of the bending angle of the extreme reached on the leading side (history)",
    ),
    field(
        "bend_opposite",
        "rad",
        "extreme bending angle reached on the opposite side (history)",
    ),
    field("torque_x", "N m", "the bond's torque on sphere i, x (latest force pass)"),
    field("torque_y", "N m", "the bond's torque on sphere i, y"),
    field("torque_z", "N m", "the bond's torque on sphere i, z"),
    field("force_normal_x", "N", "the part of the force on sphere i along n, x"),
    field("force_normal_y", "N", "the part of the force on sphere i along n, y"),
    field("force_normal_z", "N", "the part of the force on sphere i along n, z"),
    field("force_tangential_x", "N", "the part of the force on sphere i across n, x"),
    field("force_tangential_y", "N", "the part of the force on sphere i across n, y"),
    field("force_tangential_z", "N", "the part of the force on sphere i across n, z"),
    field("torque_normal_x", "N m", "the part of the torque on sphere i along n, x"),
    field("torque_normal_y", "N m", "the part of the torque on sphere i along n, y"),
    field("torque_normal_z", "N m", "the part of the torque on sphere i along n, z"),
    field("torque_tangential_x", "N m", "the part of the torque on sphere i across n, x"),
    field("torque_tangential_y", "N m", "the part of the torque on sphere i across n, y"),
    field("torque_tangential_z", "N m", "the part of the torque on sphere i across n, z"),
];

/// Number of fields of [`BOND_ENERGY_FIELDS`].
pub const BOND_ENERGY_FIELD_COUNT: usize = 3;

/// A bond's energies: fields the bond store gives
/// (`granbond_bond_store_bond_energy`), not its record, in that order; the
/// dissipated ones while the store keeps each bond's share of the energy
/// budget.
pub const BOND_ENERGY_FIELDS: [BondField; BOND_ENERGY_FIELD_COUNT] = [
    field(
        "energy_stored",
        "J",
        "energy the bond stores now: each law integrated from zero deformation at its present history",
    ),
    field(
        "energy_damping",
        "J",
        "energy the bond's damping dissipated since it first kept its budget (restart files carry it)",
    ),
    field(
        "energy_hysteresis",
        "J",
        "energy the bond's hysteresis dissipated since it first kept its budget",
    ),
];

/// `v` split into its part along the unit vector `n` and the rest.
fn split(v: [f64; 3], n: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let along = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    let normal = n.map(|c| along * c);
    (normal, [v[0] - normal[0], v[1] - normal[1], v[2] - normal[2]])
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// The fields of the bond whose state is `state` and whose latest force
/// pass left `loads` ([`super::output_slots`]), both as sphere `i` keeps
/// them, with the spheres' centres `x_i` and `x_j` (apart: `r > 0`).
pub fn bond_fields(
    laws: &BondLaws,
    state: &BondState,
    loads: &[f64; BOND_OUTPUT_LEN],
    x_i: [f64; 3],
    x_j: [f64; 3],
) -> [f64; BOND_FIELD_COUNT] {
    let out = load_output(loads);
    let d = [x_i[0] - x_j[0], x_i[1] - x_j[1], x_i[2] - x_j[2]];
    let r = norm(d);
    let n = d.map(|c| c / r);
    let f = out.force_i;
    let normal = f[0] * n[0] + f[1] * n[1] + f[2] * n[2];
    let across = [f[0] - normal * n[0], f[1] - normal * n[1], f[2] - normal * n[2]];
    let (sigma_max, tau_max) = laws.stress_limits_at(state.r0() - r);
    let ratio = |x: f64, limit: f64| if limit > 0.0 { x / limit } else { 0.0 };
    let t = out.torque_i;
    let (f_n, f_t) = split(f, n);
    let (t_n, t_t) = split(t, n);
    [
        state.status() as i32 as f64,
        state.r0(),
        r,
        r - state.r0(),
        normal,
        norm(across),
        f[0],
        f[1],
        f[2],
        norm(out.torque_i),
        norm(out.torque_j),
        out.sigma,
        sigma_max,
        ratio(out.sigma, sigma_max),
        out.tau,
        tau_max,
        ratio(out.tau, tau_max),
        state.delta_max,
        state.delta_min,
        state.twist_max,
        state.twist_min,
        norm(state.bend_history),
        state.bend_opposite,
        t[0],
        t[1],
        t[2],
        f_n[0],
        f_n[1],
        f_n[2],
        f_t[0],
        f_t[1],
        f_t[2],
        t_n[0],
        t_n[1],
        t_n[2],
        t_t[0],
        t_t[1],
        t_t[2],
    ]
}
