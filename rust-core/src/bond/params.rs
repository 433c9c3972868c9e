//! Parameters of one bond type pair, their defaults, and their validation.
//!
//! Names follow the LAMMPS keywords of `pair_style granbond`; the table
//! [`PARAMETERS`] also gives the LIGGGHTS `fix property/global` name so an
//! error can name what the user actually wrote.

/// Parameters of `bond/nonlinear` (docs/models/bond-nonlinear.md). Stiffnesses are
/// per unit area (N/m^3); switches are 0 (off) or 1 (on).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BondParams {
    /// Radius multiplier: `rb = lambda min(R_i, R_j)`.
    pub lambda: f64,
    pub k_fn1: f64,
    pub ku_fn1: f64,
    pub kc_fn1: f64,
    pub k_fn2: f64,
    pub ku_fn2: f64,
    pub kc_fn2: f64,
    pub k_ft: f64,
    pub k_tn: f64,
    pub ku_tn: f64,
    pub kc_tn: f64,
    pub k_tt: f64,
    pub ku_tt: f64,
    pub kc_tt: f64,
    pub eta_fn: f64,
    pub eta_ft: f64,
    pub eta_tn: f64,
    pub eta_tt: f64,
    /// Distance mode: the bond breaks when the centre distance exceeds this.
    pub max_distance: f64,
    pub max_sigma: f64,
    pub max_tau: f64,
    /// gamma: tensile strength is `gamma * max_sigma` when `use_ratio` is on.
    pub tension_compression_ratio: f64,
    /// Bonds form between centres closer than this.
    pub create_distance: f64,
    /// Below `smooth_velocity` (m/s) / `smooth_angular_velocity` (rad/s) the
    /// smooth damping option scales the damping down linearly.
    pub smooth_velocity: f64,
    pub smooth_angular_velocity: f64,
    /// `delta_eps` (m): the square-root compression law is continued linearly
    /// below this compression, bounding its stiffness. 0 = off (the law of docs/models/bond-nonlinear.md).
    pub compression_linear_below: f64,
    /// Time step at which bonds are created (when `create_always` is off).
    pub create_step: i64,
    /// 0 = distance mode, 1 = stress mode.
    pub stress_break: i32,
    pub use_ratio: i32,
    pub create_always: i32,
    pub history_reset: i32,
    pub damping: i32,
    pub damping_smooth: i32,
    pub tension: i32,
    pub compression: i32,
    pub shear: i32,
    pub twist: i32,
    pub bend: i32,
}

impl Default for BondParams {
    /// The reference implementation's switch defaults; physical values that a
    /// deck must set are zero (no force) and breakage is off (infinite limits).
    fn default() -> Self {
        Self {
            lambda: 1.0,
            k_fn1: 0.0,
            ku_fn1: 0.0,
            kc_fn1: 0.0,
            k_fn2: 0.0,
            ku_fn2: 0.0,
            kc_fn2: 0.0,
            k_ft: 0.0,
            k_tn: 0.0,
            ku_tn: 0.0,
            kc_tn: 0.0,
            k_tt: 0.0,
            ku_tt: 0.0,
            kc_tt: 0.0,
            eta_fn: 0.0,
            eta_ft: 0.0,
            eta_tn: 0.0,
            eta_tt: 0.0,
            max_distance: f64::INFINITY,
            max_sigma: f64::INFINITY,
            max_tau: f64::INFINITY,
            tension_compression_ratio: 1.0,
            create_distance: 0.0,
            smooth_velocity: 1e-5,
            smooth_angular_velocity: 1e-3,
            compression_linear_below: 0.0,
            create_step: 0,
            stress_break: 0,
            use_ratio: 0,
            create_always: 0,
            history_reset: 0,
            damping: 1,
            damping_smooth: 0,
            tension: 1,
            compression: 1,
            shear: 1,
            twist: 1,
            bend: 1,
        }
    }
}

pub use crate::parameters::ParameterError;
use crate::parameters::{check_ranges, refuse};

const MODEL: &str = "bond/nonlinear";

crate::parameter_table!(PARAMETERS: BondParams {
    lambda, "radiusMultiplierBondnonlinear", Positive;
    k_fn1, "stiffnessPerUnitAreaK_fn1", NonNegative;
    ku_fn1, "stiffnessPerUnitAreaKu_fn1", NonNegative;
    kc_fn1, "stiffnessPerUnitAreaKc_fn1", NonNegative;
    k_fn2, "stiffnessPerUnitAreaK_fn2", NonNegative;
    ku_fn2, "stiffnessPerUnitAreaKu_fn2", NonNegative;
    kc_fn2, "stiffnessPerUnitAreaKc_fn2", NonNegative;
    k_ft, "stiffnessPerUnitAreaK_ft", NonNegative;
    k_tn, "stiffnessPerUnitAreaK_tn", NonNegative;
    ku_tn, "stiffnessPerUnitAreaKu_tn", NonNegative;
    kc_tn, "stiffnessPerUnitAreaKc_tn", NonNegative;
    k_tt, "stiffnessPerUnitAreaK_tt", NonNegative;
    ku_tt, "stiffnessPerUnitAreaKu_tt", NonNegative;
    kc_tt, "stiffnessPerUnitAreaKc_tt", NonNegative;
    eta_fn, "dampingNormalForceBondnonlinear", Fraction;
    eta_ft, "dampingTangentialForceBondnonlinear", Fraction;
    eta_tn, "dampingNormalTorqueBondnonlinear", Fraction;
    eta_tt, "dampingTangentialTorqueBondnonlinear", Fraction;
    max_distance, "maxDistanceBondnonlinear", PositiveOrInfinite;
    max_sigma, "maxSigmaBondnonlinear", PositiveOrInfinite;
    max_tau, "maxTauBondnonlinear", PositiveOrInfinite;
    tension_compression_ratio, "ratioTensionCompressionBondnonlinear", Positive;
    create_distance, "createDistanceBondnonlinear", NonNegative;
    smooth_velocity, "dampingBondSmooth velocity", Positive;
    smooth_angular_velocity, "dampingBondSmooth angular velocity", Positive;
    compression_linear_below, "compressionLinearBelow", NonNegative;
    create_step, "tsCreateBondnonlinear", Step;
    stress_break, "stressBreak", Switch;
    use_ratio, "ratioTensionCompressionBond", Switch;
    create_always, "createBondAlways", Switch;
    history_reset, "historyReset", Switch;
    damping, "dampingBond", Switch;
    damping_smooth, "dampingBondSmooth", Switch;
    tension, "tensionStress", Switch;
    compression, "compressionStress", Switch;
    shear, "shearStress", Switch;
    twist, "normalTorqueStress", Switch;
    bend, "shearTorqueStress", Switch;
});

impl BondParams {
    pub fn switch(v: i32) -> bool {
        v != 0
    }

    /// Checks every value against its range, then the relations between
    /// stiffnesses that keep the hysteresis loop well formed: unloading must
    /// be at least as stiff as loading (`ku >= k`), otherwise the unloading
    /// line would cross the virgin curve.
    pub fn validate(&self) -> Result<(), ParameterError> {
        check_ranges(MODEL, PARAMETERS, self)?;
        for (k, ku, ku_name) in [
            (self.k_fn1, self.ku_fn1, "ku_fn1"),
            (self.k_fn2, self.ku_fn2, "ku_fn2"),
            (self.k_tn, self.ku_tn, "ku_tn"),
            (self.k_tt, self.ku_tt, "ku_tt"),
        ] {
            if ku < k {
                let loading = ku_name.replacen("ku", "k", 1);
                return Err(refuse(
                    MODEL,
                    PARAMETERS,
                    ku_name,
                    &format!(">= {} = {} (unloading at least as stiff as loading)", loading, k),
                    ku,
                ));
            }
        }
        Ok(())
    }
}
