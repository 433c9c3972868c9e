//! Parameters of the Voigt contact, defaults of the seed's Table 1.

use crate::parameters::{check_ranges, ParameterError};

const MODEL: &str = "voigt";

/// Linear spring-dashpot contact with Coulomb friction and rolling
/// resistance (docs/models/voigt.md). Switches are 0 (off) or 1 (on).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VoigtParams {
    /// Normal spring (N/m) and dashpot (kg/s).
    pub k_n: f64,
    pub gamma_n: f64,
    /// Tangential spring (N/m) and dashpot (kg/s).
    pub k_t: f64,
    pub gamma_t: f64,
    /// Coulomb friction coefficient.
    pub mu: f64,
    /// Rolling spring (N m/rad), dashpot (N m s/rad), friction coefficient
    /// and viscous rolling resistance (N m s).
    pub k_r: f64,
    pub gamma_r: f64,
    pub mu_r: f64,
    pub eta_r: f64,
    /// Clamp the normal force at zero (no attraction on separation).
    pub no_attraction: i32,
    /// Rolling resistance on.
    pub rolling: i32,
}

impl Default for VoigtParams {
    /// Table 1 of the seed.
    fn default() -> Self {
        Self {
            k_n: 1.0e4,
            gamma_n: 1.0e-3,
            k_t: 6.0e3,
            gamma_t: 1.0e-3,
            mu: 0.5,
            k_r: 1.0e-6,
            gamma_r: 1.0e-8,
            mu_r: 5.0e-2,
            eta_r: 2.0e-8,
            no_attraction: 1,
            rolling: 1,
        }
    }
}

crate::parameter_table!(VOIGT_PARAMETERS: VoigtParams {
    k_n, "kn", Positive;
    gamma_n, "gamman_abs", NonNegative;
    k_t, "kt", NonNegative;
    gamma_t, "gammat_abs", NonNegative;
    mu, "coefficientFriction", NonNegative;
    k_r, "rollingStiffness", NonNegative;
    gamma_r, "rollingDamping", NonNegative;
    mu_r, "coefficientRollingFriction", NonNegative;
    eta_r, "rollingViscousDamping", NonNegative;
    no_attraction, "noAttraction", Switch;
    rolling, "rolling_friction voigt", Switch;
});

impl VoigtParams {
    pub fn validate(&self) -> Result<(), ParameterError> {
        check_ranges(MODEL, VOIGT_PARAMETERS, self)
    }
}
