//! Parameters of one bond type pair, their defaults, and their validation.
//!
//! Names follow the LAMMPS keywords of `pair_style granbond`; the table
//! [`PARAMETERS`] also gives the LIGGGHTS `fix property/global` name so an
//! error can name what the user actually wrote.

/// Parameters of `bond/nonlinear` (docs/models/bond-nonlinear.md, whose
/// equations the fields cite). Stiffnesses are per unit area of the bond
/// section; switches are 0 (off) or 1 (on).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BondParams {
    /// Radius multiplier: `rb = lambda min(R_i, R_j)`.
    pub lambda: f64,
    /// Compression, loading: `k_fn1` (N/m^2.5; force `k_fn1 A sqrt(d)`, eq. 6).
    pub k_fn1: f64,
    /// Compression, unloading: `ku_fn1` (N/m^2.5, `>= k_fn1`; eq. 6).
    pub ku_fn1: f64,
    /// Compression, reverse: `kc_fn1` (N/m^2.5; eq. 6).
    pub kc_fn1: f64,
    /// Tension, loading: `k_fn2` (N/m^3; force `k_fn2 A d`, eq. 6).
    pub k_fn2: f64,
    /// Tension, unloading: `ku_fn2` (N/m^3, `>= k_fn2`; eq. 6).
    pub ku_fn2: f64,
    /// Tension, reverse: `kc_fn2` (N/m^3; eq. 6).
    pub kc_fn2: f64,
    /// Shear: `k_ft` (N/m^3; eq. 8).
    pub k_ft: f64,
    /// Twisting, loading: `k_tn` (N/m^3; torque `k_tn J phi`, eq. 9).
    pub k_tn: f64,
    /// Twisting, unloading: `ku_tn` (N/m^3, `>= k_tn`; eq. 9).
    pub ku_tn: f64,
    /// Twisting, reverse: `kc_tn` (N/m^3; eq. 9).
    pub kc_tn: f64,
    /// Bending, loading: `k_tt` (N/m^3; torque `k_tt I x`, eq. 10).
    pub k_tt: f64,
    /// Bending, unloading: `ku_tt` (N/m^3, `>= k_tt`; eq. 10).
    pub ku_tt: f64,
    /// Bending, reverse: `kc_tt` (N/m^3; eq. 10).
    pub kc_tt: f64,
    /// Percentage damping of the normal force, in `[0, 1)` (eq. 11).
    pub eta_fn: f64,
    /// Percentage damping of the shear force, in `[0, 1)` (eq. 12).
    pub eta_ft: f64,
    /// Percentage damping of the twisting torque, in `[0, 1)` (eq. 12).
    pub eta_tn: f64,
    /// Percentage damping of the bending torque, in `[0, 1)` (eq. 12).
    pub eta_tt: f64,
    /// Distance mode: the bond breaks when the centre distance exceeds this
    /// (m; `inf` = never).
    pub max_distance: f64,
    /// Stress mode: normal strength `sigma_max` (Pa; eq. 15); `inf` = never.
    pub max_sigma: f64,
    /// Stress mode: shear strength `tau_max` (Pa; eq. 15); `inf` = never.
    pub max_tau: f64,
    /// gamma: tensile strength is `gamma * max_sigma` when `use_ratio` is on.
    pub tension_compression_ratio: f64,
    /// Bonds form between centres closer than this (m).
    pub create_distance: f64,
    /// `v_eps` of smooth damping for the forces (m/s): below it the damping
    /// is scaled down linearly.
    pub smooth_velocity: f64,
    /// `v_eps` of smooth damping for the torques (rad/s): below it the
    /// damping is scaled down linearly.
    pub smooth_angular_velocity: f64,
    /// `delta_eps` (m): the square-root compression law is continued linearly
    /// below this compression, bounding its stiffness. 0 = off (the law of docs/models/bond-nonlinear.md).
    pub compression_linear_below: f64,
    /// BPM mode: the tensile normal force `F_rc` (N) of the summed rule
    /// ([`super::breakage::summed_criterion`]); `inf` = its term is 0.
    pub max_normal_force: f64,
    /// BPM mode: the shear force `F_sc` (N).
    pub max_shear_force: f64,
    /// BPM mode: the bending torque `T_bc` (N m).
    pub max_bend_torque: f64,
    /// BPM mode: the twisting torque `T_tc` (N m).
    pub max_twist_torque: f64,
    /// Time step at which bonds are created (when `create_always` is off).
    pub create_step: i64,
    /// 0 = distance mode, 1 = stress mode.
    pub stress_break: i32,
    /// BPM mode (LAMMPS `bond_style bpm/rotational`'s summed rule) instead
    /// of the distance or stress mode.
    pub bpm_break: i32,
    /// Applies `tension_compression_ratio` to `max_sigma` while the bond is
    /// stretched.
    pub use_ratio: i32,
    /// Creates bonds at every step, between every pair closer than
    /// `create_distance` that has no intact bond (a broken one included).
    pub create_always: i32,
    /// LIGGGHTS-INL's history rule: being on one side of a law forgets the
    /// other side's extreme; off, the extremes last the bond's life.
    pub history_reset: i32,
    /// Percentage damping (eq. 11-12).
    pub damping: i32,
    /// Smooth percentage damping: `sgn(v)` and `v/|v|` scaled down below
    /// `smooth_velocity` / `smooth_angular_velocity`; implies `damping`.
    pub damping_smooth: i32,
    /// The tension half of the normal law.
    pub tension: i32,
    /// The compression half of the normal law.
    pub compression: i32,
    /// The shear force.
    pub shear: i32,
    /// The twisting torque.
    pub twist: i32,
    /// The bending torque.
    pub bend: i32,
    /// LIGGGHTS-INL's code instead of the write-up's law (`bond::inl`):
    /// compression without the section area, INL's history rule, damping
    /// and twisting and bending per Cartesian component, and the contact's
    /// tangential and rolling loads kept under an overlapping bond.
    pub inl_compatible: i32,
    /// The contact's state (the tangential spring, the rolling angle) goes
    /// on under an intact bond, stepped as if the bond were not there, and
    /// the contact acts from where it stands when the bond breaks; off, it
    /// is held at zero under the bond and starts afresh at the break. Which
    /// of the contact's loads act under the bond is the law's
    /// (`keeps_contact_loads`, `keeps_contact_tangential`). On by default for the
    /// linear bond ([`BondParams::linear_default_in_units`]), whose law
    /// keeps the contact's loads.
    pub contact_under_bond: i32,
    /// LIGGGHTS-INL's linear bond (`cohesion bond`,
    /// docs/models/bond-linear.md) instead of `bond/nonlinear`: the rows
    /// it reads are [`LINEAR_NAMES`].
    pub linear: i32,
    /// Linear bond: normal stiffness `k_n` (N/m^3; force `k_n A d`,
    /// bending torque increment `k_n I`).
    pub k_n: f64,
    /// Linear bond: tangential stiffness `k_t` (N/m^3; shear force
    /// increment `k_t A`, twisting torque increment `k_t J`).
    pub k_t: f64,
    /// Linear bond: the time over which the normal spring relaxes its rest
    /// length to the present distance (s; `inf` = never).
    pub dissipation_fn: f64,
    /// Linear bond: the relaxation time of the shear force (s).
    pub dissipation_ft: f64,
    /// Linear bond: the relaxation time of the twisting torque (s).
    pub dissipation_tn: f64,
    /// Linear bond: the relaxation time of the bending torque (s).
    pub dissipation_tt: f64,
    /// Linear bond: the springs relax over the dissipation times.
    pub dissipation: i32,
    /// Linear bond, stress mode with `drucker_prager`: the friction angle
    /// (degrees) by which compression raises the shear strength.
    pub friction_angle: f64,
    /// Linear bond, stress mode: the shear strength is `max_tau + sgn(d)
    /// sigma_n tan(friction_angle)` (Drucker-Prager).
    pub drucker_prager: i32,
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
            max_normal_force: f64::INFINITY,
            max_shear_force: f64::INFINITY,
            max_bend_torque: f64::INFINITY,
            max_twist_torque: f64::INFINITY,
            create_step: 0,
            stress_break: 0,
            bpm_break: 0,
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
            inl_compatible: 0,
            contact_under_bond: 0,
            linear: 0,
            k_n: 0.0,
            k_t: 0.0,
            dissipation_fn: f64::INFINITY,
            dissipation_ft: f64::INFINITY,
            dissipation_tn: f64::INFINITY,
            dissipation_tt: f64::INFINITY,
            dissipation: 0,
            friction_angle: 0.0,
            drucker_prager: 0,
        }
    }
}

pub use crate::parameters::ParameterError;
use crate::parameters::{check_ranges, refuse, LiggghtsSource, Need, Phrase};

const MODEL: &str = "bond/nonlinear";
const LINEAR_MODEL: &str = "bond/linear";

const ALWAYS: Need<BondParams> = Need {
    when: "always",
    applies: |_| true,
};
const DAMPING: Need<BondParams> = Need {
    when: "damping on",
    applies: |p| p.damping_on(),
};
const SMOOTH_DAMPING: Need<BondParams> = Need {
    when: "smooth damping on",
    applies: |p| BondParams::switch(p.damping_smooth),
};
const DISTANCE_MODE: Need<BondParams> = Need {
    when: "distance mode (stress break off)",
    applies: |p| !BondParams::switch(p.stress_break),
};
const STRESS_MODE: Need<BondParams> = Need {
    when: "stress mode (stress break on)",
    applies: |p| BondParams::switch(p.stress_break),
};
const BPM_MODE: Need<BondParams> = Need {
    when: "BPM mode (bpm break on)",
    applies: |p| BondParams::switch(p.bpm_break),
};
const STRESS_RATIO: Need<BondParams> = Need {
    when: "stress mode with the tension ratio on",
    applies: |p| BondParams::switch(p.stress_break) && BondParams::switch(p.use_ratio),
};
const LINEAR: Need<BondParams> = Need {
    when: "linear bond",
    applies: |p| BondParams::switch(p.linear),
};
const LINEAR_DISSIPATION: Need<BondParams> = Need {
    when: "linear bond with dissipation on",
    applies: |p| BondParams::switch(p.linear) && BondParams::switch(p.dissipation),
};
const LINEAR_DRUCKER_PRAGER: Need<BondParams> = Need {
    when: "linear bond, stress mode with Drucker-Prager on",
    applies: |p| {
        BondParams::switch(p.linear)
            && BondParams::switch(p.stress_break)
            && BondParams::switch(p.drucker_prager)
    },
};
const AT_STEP: Need<BondParams> = Need {
    when: "bonds created at one step (create always off)",
    applies: |p| !BondParams::switch(p.create_always),
};

// name (= LAMMPS keyword), LIGGGHTS name, where LIGGGHTS decks give it, unit,
// allowed values, when the model reads it. Defaults: `BondParams::default`.
crate::parameter_table!(
    /// The rows of [`BondParams`], one per field in its order: the table
    /// of docs/models/bond-nonlinear.md, "Parameters".
    PARAMETERS: BondParams {
        lambda, "radiusMultiplierBondnonlinear", PerTypePair, "-", Positive, ALWAYS;
        k_fn1, "stiffnessPerUnitAreaK_fn1", PerTypePair, "N/m^2.5", NonNegative, ALWAYS;
        ku_fn1, "stiffnessPerUnitAreaKu_fn1", PerTypePair, "N/m^2.5", NonNegative, ALWAYS;
        kc_fn1, "stiffnessPerUnitAreaKc_fn1", PerTypePair, "N/m^2.5", NonNegative, ALWAYS;
        k_fn2, "stiffnessPerUnitAreaK_fn2", PerTypePair, "N/m^3", NonNegative, ALWAYS;
        ku_fn2, "stiffnessPerUnitAreaKu_fn2", PerTypePair, "N/m^3", NonNegative, ALWAYS;
        kc_fn2, "stiffnessPerUnitAreaKc_fn2", PerTypePair, "N/m^3", NonNegative, ALWAYS;
        k_ft, "stiffnessPerUnitAreaK_ft", PerTypePair, "N/m^3", NonNegative, ALWAYS;
        k_tn, "stiffnessPerUnitAreaK_tn", PerTypePair, "N/m^3", NonNegative, ALWAYS;
        ku_tn, "stiffnessPerUnitAreaKu_tn", PerTypePair, "N/m^3", NonNegative, ALWAYS;
        kc_tn, "stiffnessPerUnitAreaKc_tn", PerTypePair, "N/m^3", NonNegative, ALWAYS;
        k_tt, "stiffnessPerUnitAreaK_tt", PerTypePair, "N/m^3", NonNegative, ALWAYS;
        ku_tt, "stiffnessPerUnitAreaKu_tt", PerTypePair, "N/m^3", NonNegative, ALWAYS;
        kc_tt, "stiffnessPerUnitAreaKc_tt", PerTypePair, "N/m^3", NonNegative, ALWAYS;
        eta_fn, "dampingNormalForceBondnonlinear", PerTypePair, "-", Fraction, DAMPING;
        eta_ft, "dampingTangentialForceBondnonlinear", PerTypePair, "-", Fraction, DAMPING;
        eta_tn, "dampingNormalTorqueBondnonlinear", PerTypePair, "-", Fraction, DAMPING;
        eta_tt, "dampingTangentialTorqueBondnonlinear", PerTypePair, "-", Fraction, DAMPING;
        max_distance, "maxDistanceBondnonlinear", PerTypePair, "m", PositiveOrInfinite, DISTANCE_MODE;
        max_sigma, "maxSigmaBondnonlinear", PerTypePair, "Pa", PositiveOrInfinite, STRESS_MODE;
        max_tau, "maxTauBondnonlinear", PerTypePair, "Pa", PositiveOrInfinite, STRESS_MODE;
        tension_compression_ratio, "ratioTensionCompressionBondnonlinear", PerTypePair, "-", Positive, STRESS_RATIO;
        create_distance, "createDistanceBondnonlinear", PerTypePair, "m", NonNegative, ALWAYS;
        smooth_velocity, "dampingBondSmooth velocity", Fixed, "m/s", Positive, SMOOTH_DAMPING;
        smooth_angular_velocity, "dampingBondSmooth angular velocity", Fixed, "rad/s", Positive, SMOOTH_DAMPING;
        compression_linear_below, "compressionLinearBelowBondnonlinear", OptionalPerTypePair, "m", NonNegative, ALWAYS;
        max_normal_force, "maxNormalForceBondnonlinear", PerTypePair, "N", PositiveOrInfinite, BPM_MODE;
        max_shear_force, "maxShearForceBondnonlinear", PerTypePair, "N", PositiveOrInfinite, BPM_MODE;
        max_bend_torque, "maxBendTorqueBondnonlinear", PerTypePair, "N m", PositiveOrInfinite, BPM_MODE;
        max_twist_torque, "maxTwistTorqueBondnonlinear", PerTypePair, "N m", PositiveOrInfinite, BPM_MODE;
        create_step, "tsCreateBondnonlinear", Scalar, "step", Step, AT_STEP;
        stress_break, "stressBreak", Switch, "switch", Switch, ALWAYS;
        bpm_break, "bpmBreak", Switch, "switch", Switch, ALWAYS;
        use_ratio, "ratioTensionCompressionBond", Switch, "switch", Switch, ALWAYS;
        create_always, "createBondAlways", Switch, "switch", Switch, ALWAYS;
        history_reset, "historyReset", Switch, "switch", Switch, ALWAYS;
        damping, "dampingBond", Switch, "switch", Switch, ALWAYS;
        damping_smooth, "dampingBondSmooth", Switch, "switch", Switch, ALWAYS;
        tension, "tensionStress", Switch, "switch", Switch, ALWAYS;
        compression, "compressionStress", Switch, "switch", Switch, ALWAYS;
        shear, "shearStress", Switch, "switch", Switch, ALWAYS;
        twist, "normalTorqueStress", Switch, "switch", Switch, ALWAYS;
        bend, "shearTorqueStress", Switch, "switch", Switch, ALWAYS;
        inl_compatible, "inlCompatible", Switch, "switch", Switch, ALWAYS;
        contact_under_bond, "contactUnderBond", Switch, "switch", Switch, ALWAYS;
        linear, "cohesion bond", Fixed, "switch", Switch, ALWAYS;
        k_n, "normalBondStiffnessPerUnitArea", PerTypePair, "N/m^3", NonNegative, LINEAR;
        k_t, "tangentialBondStiffnessPerUnitArea", PerTypePair, "N/m^3", NonNegative, LINEAR;
        dissipation_fn, "dissipationNormalForceBond", PerTypePair, "s", PositiveOrInfinite, LINEAR_DISSIPATION;
        dissipation_ft, "dissipationTangentialForceBond", PerTypePair, "s", PositiveOrInfinite, LINEAR_DISSIPATION;
        dissipation_tn, "dissipationNormalTorqueBond", PerTypePair, "s", PositiveOrInfinite, LINEAR_DISSIPATION;
        dissipation_tt, "dissipationTangentialTorqueBond", PerTypePair, "s", PositiveOrInfinite, LINEAR_DISSIPATION;
        dissipation, "dissipationBond", Switch, "switch", Switch, ALWAYS;
        friction_angle, "frictionAngle", PerTypePair, "deg", NonNegative, LINEAR_DRUCKER_PRAGER;
        drucker_prager, "druckerPrager", Switch, "switch", Switch, ALWAYS;
    }
);

/// The rows LIGGGHTS-INL's linear bond (`cohesion bond`) reads, each with
/// the name INL's decks give it where it differs from `bond/nonlinear`'s
/// (empty: the row's own name). Every other row belongs to `bond/nonlinear`
/// alone; the rows from `linear` on to the linear bond alone.
pub const LINEAR_NAMES: &[(&str, &str)] = &[
    ("lambda", "radiusMultiplierBond"),
    ("k_n", ""),
    ("k_t", ""),
    ("eta_fn", "dampingNormalForceBond"),
    ("eta_ft", "dampingTangentialForceBond"),
    ("eta_tn", "dampingNormalTorqueBond"),
    ("eta_tt", "dampingTangentialTorqueBond"),
    ("dissipation_fn", ""),
    ("dissipation_ft", ""),
    ("dissipation_tn", ""),
    ("dissipation_tt", ""),
    ("max_distance", "maxDistanceBond"),
    ("max_sigma", "maxSigmaBond"),
    ("max_tau", "maxTauBond"),
    ("tension_compression_ratio", "ratioTensionCompression"),
    ("friction_angle", ""),
    ("create_distance", "createDistanceBond"),
    ("create_step", "tsCreateBond"),
    ("stress_break", ""),
    ("use_ratio", "ratioTensionCompression"),
    ("create_always", ""),
    ("damping", ""),
    ("damping_smooth", ""),
    ("dissipation", ""),
    ("drucker_prager", ""),
    ("contact_under_bond", ""),
    ("tension", ""),
    ("compression", ""),
    ("shear", ""),
    ("twist", ""),
    ("bend", ""),
];

/// The first row of the linear bond's own (`linear`): the rows from it on
/// are not `bond/nonlinear`'s.
const FIRST_LINEAR_ROW: &str = "linear";

/// The name a LIGGGHTS deck of the linear bond (`linear`) or of
/// `bond/nonlinear` gives row `id` of [`PARAMETERS`], or `None` when that
/// model does not have the row.
pub fn liggghts_name(linear: bool, id: usize) -> Option<&'static str> {
    let row = PARAMETERS.get(id)?;
    if linear {
        let (_, name) = LINEAR_NAMES.iter().find(|(k, _)| *k == row.name)?;
        Some(if name.is_empty() { row.liggghts_name } else { name })
    } else {
        let first = PARAMETERS.iter().position(|r| r.name == FIRST_LINEAR_ROW)?;
        (id < first).then_some(row.liggghts_name)
    }
}

/// The rows that say when and between which pairs bonds form. Where an
/// engine's topology names the bonds (LAMMPS `bond_style granbond`), a deck
/// gives none of them: a listed bond exists from the start, at rest at its
/// length.
pub const CREATION_ROWS: &[&str] = &["create_distance", "create_step", "create_always"];

/// The rows of bonds a pair style forms between touching spheres beyond
/// [`CREATION_ROWS`]: what the contact does under the bond. Where an
/// engine's topology names the bonds, whether a bonded pair's contact acts
/// is the topology's own setting (LAMMPS `special_bonds`).
pub const PAIR_BOND_ROWS: &[&str] = &["contact_under_bond"];

/// The `bond/nonlinear` phrases of `pair_coeff` (docs/reference/pair_granbond.md):
/// a break mode is the stress or BPM switch, a tension ratio switches the ratio on,
/// a creation step means creation at that step only.
pub const PHRASES: &[Phrase] = &[
    Phrase {
        words: "break distance",
        follows: "",
        reads: &["max_distance"],
        sets: &[("stress_break", 0.0), ("bpm_break", 0.0)],
    },
    Phrase {
        words: "break stress",
        follows: "",
        reads: &["max_sigma", "max_tau"],
        sets: &[("stress_break", 1.0), ("bpm_break", 0.0)],
    },
    Phrase {
        words: "break bpm",
        follows: "",
        // BPM's own order in bond_coeff: F_rc F_sc T_tc T_bc
        reads: &[
            "max_normal_force",
            "max_shear_force",
            "max_twist_torque",
            "max_bend_torque",
        ],
        sets: &[("stress_break", 0.0), ("bpm_break", 1.0)],
    },
    Phrase {
        words: "ratio",
        follows: "break stress",
        reads: &["tension_compression_ratio"],
        sets: &[("use_ratio", 1.0)],
    },
    Phrase {
        words: "smooth_damping",
        follows: "",
        reads: &["damping_smooth"],
        sets: &[],
    },
    Phrase {
        words: "create_step",
        follows: "",
        reads: &["create_step"],
        sets: &[("create_always", 0.0)],
    },
];

impl BondParams {
    /// Whether a switch field is on (any non-zero value).
    pub fn switch(v: i32) -> bool {
        v != 0
    }

    /// Whether the model of these parameters reads row `id` of
    /// [`PARAMETERS`]: its law has the row ([`liggghts_name`]) and the
    /// switches ask for it.
    pub fn reads(&self, id: usize) -> bool {
        liggghts_name(Self::switch(self.linear), id).is_some() && PARAMETERS[id].needed(self)
    }

    /// The defaults in the deck units of the engine's `units` style: the
    /// smoothing velocities are physical quantities (1e-5 m/s, 1e-3 rad/s),
    /// converted for `si`, `cgs`, `micro` and `nano`; a style without a
    /// physical scale (`lj`) or one not known here gets no value for them
    /// (NaN), so smooth damping there needs them given.
    pub fn default_in_units(style: &str) -> Self {
        // metres and seconds in one deck unit of length and time
        let scale = match style {
            "si" => Some((1.0, 1.0)),
            "cgs" => Some((1e-2, 1.0)),
            "micro" => Some((1e-6, 1e-6)),
            "nano" => Some((1e-9, 1e-9)),
            _ => None,
        };
        let d = Self::default();
        let (v, w) = match scale {
            Some((metre, second)) => (
                d.smooth_velocity * second / metre,
                d.smooth_angular_velocity * second,
            ),
            None => (f64::NAN, f64::NAN),
        };
        Self {
            smooth_velocity: v,
            smooth_angular_velocity: w,
            ..d
        }
    }

    /// [`Self::default_in_units`] for LIGGGHTS-INL's linear bond: `linear`
    /// on, and the contact goes on under its bonds (`contact_under_bond`),
    /// as the law keeps the contact's loads there.
    pub fn linear_default_in_units(style: &str) -> Self {
        Self {
            linear: 1,
            contact_under_bond: 1,
            ..Self::default_in_units(style)
        }
    }

    /// Whether the law keeps every load of the contact on an overlapping
    /// pair under an intact bond, the bond's added to them (LIGGGHTS-INL's
    /// linear bond, `linear`).
    pub fn keeps_contact_loads(&self) -> bool {
        Self::switch(self.linear)
    }

    /// Whether the law keeps the contact's tangential and rolling loads
    /// under an intact bond, the bond taking the place of the normal load
    /// alone (LIGGGHTS-INL's code, `inl_compatible`).
    pub fn keeps_contact_tangential(&self) -> bool {
        Self::switch(self.inl_compatible)
    }

    /// Sets `contact_under_bond` for a deck that does not give it: on where
    /// the law keeps some of the contact's loads under the bond, so the
    /// loads kept come from the contact's state as it goes on (as in
    /// LIGGGHTS-INL), off where the bond replaces the contact. Both engines
    /// call this once the deck's other switches are read.
    pub fn contact_under_bond_by_law(&mut self) {
        self.contact_under_bond = i32::from(self.keeps_contact_loads() || self.keeps_contact_tangential());
    }

    /// Smooth damping is a kind of damping: either switch turns it on.
    pub fn damping_on(&self) -> bool {
        Self::switch(self.damping) || Self::switch(self.damping_smooth)
    }

    /// Checks every value against its range, then the relations between
    /// stiffnesses that keep the hysteresis loop well formed: unloading must
    /// be at least as stiff as loading (`ku >= k`), otherwise the unloading
    /// line would cross the virgin curve.
    pub fn validate(&self) -> Result<(), ParameterError> {
        self.validate_rows().map_err(|e| self.in_own_words(e))
    }

    /// A refusal as the linear bond's decks name the model and the
    /// parameter ([`LINEAR_NAMES`]); `bond/nonlinear`'s unchanged.
    fn in_own_words(&self, mut e: ParameterError) -> ParameterError {
        if !Self::switch(self.linear) {
            return e;
        }
        let row = &PARAMETERS[e.parameter];
        if let Some(name) = liggghts_name(true, e.parameter) {
            e.message = e
                .message
                .replacen(&format!("({})", row.liggghts_name), &format!("({name})"), 1);
        }
        e.message = e.message.replacen(MODEL, LINEAR_MODEL, 1);
        e
    }

    fn validate_rows(&self) -> Result<(), ParameterError> {
        // The smoothing velocities have no default in a unit style without
        // a physical scale (`default_in_units`): needed only when read.
        let mut checked = *self;
        for (name, value, si) in [
            (
                "smooth_velocity",
                &mut checked.smooth_velocity,
                Self::default().smooth_velocity,
            ),
            (
                "smooth_angular_velocity",
                &mut checked.smooth_angular_velocity,
                Self::default().smooth_angular_velocity,
            ),
        ] {
            if !value.is_nan() {
                continue;
            }
            if Self::switch(self.damping_smooth) {
                return Err(refuse(
                    MODEL,
                    PARAMETERS,
                    name,
                    "given with smooth damping in this unit style (its default is a physical quantity, \
                     and the style has no physical scale to convert it to, as in units lj)",
                    *value,
                ));
            }
            *value = si;
        }
        check_ranges(MODEL, PARAMETERS, &checked)?;
        // a parameter of the other law would be silently ignored
        let linear = Self::switch(self.linear);
        let defaults = Self::default();
        for (id, row) in PARAMETERS.iter().enumerate() {
            let value = (row.get)(self);
            // (a row no LIGGGHTS deck sets has a default that may depend
            // on the unit style, `default_in_units`)
            if row.source != LiggghtsSource::Fixed
                && liggghts_name(linear, id).is_none()
                && value != (row.get)(&defaults)
            {
                let (this, other) = if linear {
                    (LINEAR_MODEL, MODEL)
                } else {
                    (MODEL, LINEAR_MODEL)
                };
                return Err(refuse(
                    MODEL,
                    PARAMETERS,
                    row.name,
                    &format!(
                        "left at its default {} ({other}'s parameter, which {this} does not read)",
                        (row.get)(&defaults)
                    ),
                    value,
                ));
            }
        }
        if Self::switch(self.bpm_break)
            && (Self::switch(self.stress_break) || Self::switch(self.inl_compatible))
        {
            let other = if Self::switch(self.stress_break) {
                "stress_break (break stress)"
            } else {
                "inl_compatible"
            };
            return Err(refuse(
                MODEL,
                PARAMETERS,
                "bpm_break",
                &format!("0 with {other} on: a bond breaks by one rule"),
                f64::from(self.bpm_break),
            ));
        }
        for (k, ku, ku_name) in [
            (self.k_fn1, self.ku_fn1, "ku_fn1"),
            (self.k_fn2, self.ku_fn2, "ku_fn2"),
            (self.k_tn, self.ku_tn, "ku_tn"),
            (self.k_tt, self.ku_tt, "ku_tt"),
        ] {
            if ku < k {
                let loading = ku_name.replacen("ku", "k", 1);
                let row = PARAMETERS
                    .iter()
                    .find(|r| r.name == loading)
                    .expect("every unloading stiffness has its loading row");
                return Err(refuse(
                    MODEL,
                    PARAMETERS,
                    ku_name,
                    &format!(
                        ">= {} ({}) = {:e} (unloading at least as stiff as loading)",
                        row.name, row.liggghts_name, k
                    ),
                    ku,
                ));
            }
        }
        Ok(())
    }
}
