//! The parts of the bond a model computes, as bits (`bond::switches`
//! says how a compiled step reads them).

use super::params::BondParams;

/// The tension half of the normal law (docs/models/bond-nonlinear.md eq. 6, `d < 0`).
pub const TENSION: u32 = 1;
/// The compression half of the normal law (docs/models/bond-nonlinear.md eq. 6, `d >= 0`).
pub const COMPRESSION: u32 = 2;
/// The shear force (docs/models/bond-nonlinear.md eq. 7-8).
pub const SHEAR: u32 = 4;
/// The twisting torque (docs/models/bond-nonlinear.md eq. 9).
pub const TWIST: u32 = 8;
/// The bending torque (docs/models/bond-nonlinear.md eq. 10).
pub const BEND: u32 = 16;
/// Percentage damping (docs/models/bond-nonlinear.md eq. 11-12).
pub const DAMPING: u32 = 32;
/// Smooth percentage damping: `sgn(v)` and `v/|v|` of eq. 11-12 scaled
/// down below the smooth velocities (set only with [`DAMPING`]).
pub const SMOOTH: u32 = 64;
/// The number of values the seven bits above can take together.
pub const FEATURE_COMBINATIONS: usize = 128;

/// Every law of the bond, without damping.
const ALL_LAWS: u32 = TENSION | COMPRESSION | SHEAR | TWIST | BEND;

/// The combinations that have steps compiled for them alone: the full bond
/// and the reductions decks use (no twist, no bend, normal and shear,
/// normal only, tension only), each undamped, damped and smoothly damped.
/// Every other combination runs the steps that read the bits at run time.
pub const COMPILED_ALONE: [u32; 18] = {
    let laws = [
        ALL_LAWS,
        ALL_LAWS & !TWIST,
        ALL_LAWS & !BEND,
        TENSION | COMPRESSION | SHEAR,
        TENSION | COMPRESSION,
        TENSION,
    ];
    let damping = [0, DAMPING, DAMPING | SMOOTH];
    let mut all = [0; 18];
    let mut i = 0;
    while i < 18 {
        all[i] = laws[i / 3] | damping[i % 3];
        i += 1;
    }
    all
};

/// The bits `params` switch on. Damping with every ratio zero changes
/// nothing, so it is left out.
pub fn features(params: &BondParams) -> u32 {
    let on = BondParams::switch;
    let p = params;
    let mut bits = 0;
    for (flag, bit) in [
        (p.tension, TENSION),
        (p.compression, COMPRESSION),
        (p.shear, SHEAR),
        (p.twist, TWIST),
        (p.bend, BEND),
    ] {
        if on(flag) {
            bits |= bit;
        }
    }
    let any_eta = p.eta_fn > 0.0 || p.eta_ft > 0.0 || p.eta_tn > 0.0 || p.eta_tt > 0.0;
    if p.damping_on() && any_eta {
        bits |= DAMPING;
        if on(p.damping_smooth) {
            bits |= SMOOTH;
        }
    }
    bits
}
