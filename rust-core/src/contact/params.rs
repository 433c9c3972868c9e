//! Parameters of the Voigt contact, with the defaults of
//! docs/models/voigt.md's parameter table.

use crate::parameters::{check_ranges, Need, ParameterError, Phrase};

const MODEL: &str = "voigt";

/// Linear spring-dashpot contact with Coulomb friction and rolling
/// resistance (docs/models/voigt.md). Switches are 0 (off) or 1 (on).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VoigtParams {
    /// Normal spring `k_n` (N/m).
    pub k_n: f64,
    /// Normal dashpot `gamma_n` (kg/s).
    pub gamma_n: f64,
    /// Tangential spring `k_t` (N/m).
    pub k_t: f64,
    /// Tangential dashpot `gamma_t` (kg/s).
    pub gamma_t: f64,
    /// Coulomb friction coefficient `mu`: the tangential force is capped at
    /// `mu |Fn|`.
    pub mu: f64,
    /// Rolling spring `k_r` (N m/rad).
    pub k_r: f64,
    /// Rolling dashpot `gamma_r` (N m s/rad).
    pub gamma_r: f64,
    /// Rolling friction coefficient `mu_r`: the rolling torque is capped at
    /// `mu_r |Fn| R*`.
    pub mu_r: f64,
    /// Viscous rolling resistance `eta_r` (N m s), not capped.
    pub eta_r: f64,
    /// Clamp the normal force at zero (no attraction on separation).
    pub no_attraction: i32,
    /// Rolling resistance on.
    pub rolling: i32,
}

impl Default for VoigtParams {
    /// The defaults of docs/models/voigt.md's parameter table.
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

const ALWAYS: Need<VoigtParams> = Need {
    when: "always",
    applies: |_| true,
};
const ROLLING: Need<VoigtParams> = Need {
    when: "rolling on",
    applies: |p| p.rolling != 0,
};

// name (= field), LIGGGHTS name, where LIGGGHTS decks give it, unit, allowed
// values, when the model reads it. Defaults: `VoigtParams::default`.
crate::parameter_table!(
    /// The rows of [`VoigtParams`], one per field in its order: the table
    /// of docs/models/voigt.md, "Parameters".
    VOIGT_PARAMETERS: VoigtParams {
        k_n, "kn", PerTypePair, "N/m", Positive, ALWAYS;
        gamma_n, "gamman_abs", PerTypePair, "kg/s", NonNegative, ALWAYS;
        k_t, "kt", PerTypePair, "N/m", NonNegative, ALWAYS;
        gamma_t, "gammat_abs", PerTypePair, "kg/s", NonNegative, ALWAYS;
        mu, "coefficientFriction", PerTypePair, "-", NonNegative, ALWAYS;
        k_r, "rollingStiffness", PerTypePair, "N m/rad", NonNegative, ROLLING;
        gamma_r, "rollingDamping", PerTypePair, "N m s/rad", NonNegative, ROLLING;
        mu_r, "coefficientRollingFriction", PerTypePair, "-", NonNegative, ROLLING;
        eta_r, "rollingViscousDamping", PerTypePair, "N m s", NonNegative, ROLLING;
        no_attraction, "noAttraction", Switch, "switch", Switch, ALWAYS;
        rolling, "rolling_friction voigt", Fixed, "switch", Switch, ALWAYS;
    }
);

/// The part of the contact whose law reads a parameter (the sections of
/// docs/models/voigt.md): an engine that composes the contact from
/// sub-models (LIGGGHTS) hands each part its own values.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ContactPart {
    /// The normal spring and dashpot, and the no-attraction clamp.
    Normal = 0,
    /// The Cundall-Strack tangential spring, its dashpot and Coulomb friction.
    Tangential = 1,
    /// Iwashita-Oda rolling resistance.
    Rolling = 2,
}

/// The part of each row of [`VOIGT_PARAMETERS`], in its order.
pub const VOIGT_PARTS: &[(&str, ContactPart)] = &[
    ("k_n", ContactPart::Normal),
    ("gamma_n", ContactPart::Normal),
    ("k_t", ContactPart::Tangential),
    ("gamma_t", ContactPart::Tangential),
    ("mu", ContactPart::Tangential),
    ("k_r", ContactPart::Rolling),
    ("gamma_r", ContactPart::Rolling),
    ("mu_r", ContactPart::Rolling),
    ("eta_r", ContactPart::Rolling),
    ("no_attraction", ContactPart::Normal),
    ("rolling", ContactPart::Rolling),
];

/// A sub-model of an engine that composes the contact from one per part
/// (LIGGGHTS): the words a deck names it by, and the parts whose rows it
/// reads.
pub struct SubModel {
    /// The part it computes.
    pub part: ContactPart,
    /// The words of `pair_style gran` and `fix wall/gran` that name it.
    pub words: &'static str,
    /// The parts whose rows it reads from the deck.
    pub reads: &'static [ContactPart],
}

/// LIGGGHTS's voigt sub-models, one per part in the order of
/// [`ContactPart`]. `model voigt` reads the tangential part too: it hands
/// `k_t` and `gamma_t` on (with `k_n` and `gamma_n`) to a stock tangential,
/// rolling or cohesion model after it, which reads them from the engine's
/// contact data rather than the deck.
pub const VOIGT_SUB_MODELS: &[SubModel] = &[
    SubModel {
        part: ContactPart::Normal,
        words: "model voigt",
        reads: &[ContactPart::Normal, ContactPart::Tangential],
    },
    SubModel {
        part: ContactPart::Tangential,
        words: "tangential voigt",
        reads: &[ContactPart::Tangential],
    },
    SubModel {
        part: ContactPart::Rolling,
        words: "rolling_friction voigt",
        reads: &[ContactPart::Rolling],
    },
];

/// The `voigt` phrases of `pair_coeff` (docs/reference/pair_granbond.md): the
/// five values after the model's name, rolling resistance with its four, the
/// attraction switch.
pub const VOIGT_PHRASES: &[Phrase] = &[
    Phrase {
        words: "",
        follows: "",
        reads: &["k_n", "gamma_n", "k_t", "gamma_t", "mu"],
        sets: &[("rolling", 0.0)],
    },
    Phrase {
        words: "rolling",
        follows: "",
        reads: &["k_r", "gamma_r", "mu_r", "eta_r"],
        sets: &[("rolling", 1.0)],
    },
    Phrase {
        words: "noattraction",
        follows: "",
        reads: &["no_attraction"],
        sets: &[],
    },
];

impl VoigtParams {
    /// Checks every value against its row's range; the error names the first
    /// parameter refused.
    pub fn validate(&self) -> Result<(), ParameterError> {
        check_ranges(MODEL, VOIGT_PARAMETERS, self)
    }
}
