//! Whether the creation and break rules of a bond type contradict each other
//! or the spheres present: checked by the engines at every `run`.
//! LIGGGHTS-INL runs a deck with any such combination, so each
//! finding is a warning that names the parameters as the deck spells them.

use super::laws::BondLaws;
use super::params::{liggghts_name, BondParams, ParameterError, PARAMETERS};
use crate::timestep_check::{TypeBodies, UnitNames};

/// Which spelling of the parameter names the messages use.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Naming {
    /// `pair_coeff ... bond/nonlinear` keywords (LAMMPS).
    Lammps = 0,
    /// `fix property/global` names and switches (LIGGGHTS).
    Liggghts = 1,
    /// `pair_coeff ... bond/linear` keywords: the linear bond's stiffnesses
    /// `k_n`, `k_t` where `bond/nonlinear`'s would be named.
    LammpsLinear = 2,
    /// The names LIGGGHTS-INL's `cohesion bond` decks give the linear
    /// bond's parameters ([`crate::bond::params::LINEAR_NAMES`]).
    LiggghtsLinear = 3,
}

impl Naming {
    /// The engine's naming for a bond of the linear law (`linear`) or of
    /// `bond/nonlinear`.
    pub fn for_law(self, linear: bool) -> Self {
        match (self.base(), linear) {
            (Naming::Lammps, true) => Naming::LammpsLinear,
            (Naming::Liggghts, true) => Naming::LiggghtsLinear,
            (base, _) => base,
        }
    }

    /// The engine's naming, whatever the law.
    pub fn base(self) -> Self {
        match self {
            Naming::LammpsLinear => Naming::Lammps,
            Naming::LiggghtsLinear => Naming::Liggghts,
            n => n,
        }
    }
}

/// One contradiction found, with the type pair it was first seen on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Finding {
    /// Distance mode, `create_distance > max_distance`: a pair between the
    /// two distances is bonded and broken in the same step (every step under
    /// `create_always`).
    CreatedBroken {
        /// `max_distance` is below the contact distance of the smallest
        /// spheres too.
        touching_breaks: bool,
    },
    /// `create_distance` below the contact distance of the smallest spheres:
    /// only pairs overlapping by the difference bond.
    CreateBelowContact,
    /// `create_distance` reaches more than a radius of the smallest spheres
    /// beyond their contact distance: such spheres bond without touching.
    CreateBeyondContact,
    /// A law switched on whose loading stiffness is 0 (the value of a
    /// stiffness left out): the bond resists nothing in that direction.
    ZeroStiffness,
    /// `create_step` is not after the step the model's first run started
    /// from, bonds are not created every step, and no bond exists: this
    /// model never forms a bond (the first force step of a run is the one
    /// after its start). A run that continues bonds (from a restart file)
    /// is not a finding: its bonds were formed before.
    CreateStepPassed,
}

/// The pairs of types `1..=ntypes` (`a <= b`; for a wall bond every
/// `(a, b)` with `b` the wall's type, whose radius does not count) whose
/// parameters `params(a, b)` give a [`Finding`]; each finding once, on the
/// first pair that shows it. Types without atoms are skipped (the wall's
/// type is not). `first_step`: the step the first run of the model started
/// from; `bonds_exist`: intact bonds of the model exist (over all ranks).
pub fn findings(
    ntypes: usize,
    bodies: &[TypeBodies],
    params: impl Fn(usize, usize) -> Option<BondParams>,
    first_step: i64,
    bonds_exist: bool,
    wall: bool,
) -> Vec<(Finding, usize, usize)> {
    let mut found: Vec<(Finding, usize, usize)> = Vec::new();
    let mut note = |f: Finding, a: usize, b: usize| {
        if !found
            .iter()
            .any(|(g, _, _)| std::mem::discriminant(g) == std::mem::discriminant(&f))
        {
            found.push((f, a, b));
        }
    };
    for a in 1..=ntypes {
        let first_b = if wall { 1 } else { a };
        for b in first_b..=ntypes {
            if !bodies[a].present() || !(wall || bodies[b].present()) {
                continue;
            }
            let Some(p) = params(a, b) else { continue };
            let contact = contact_distance(bodies, a, b, wall);
            // LIGGGHTS-INL's wall bond (`inl_compatible`) forms within half
            // the creation distance of the wall and breaks on the distance
            // to the wall point (`bond::inl`).
            let inl_wall = wall && (BondParams::switch(p.inl_compatible) || BondParams::switch(p.linear));
            let reach = if inl_wall {
                0.5 * p.create_distance
            } else {
                p.create_distance
            };
            // and touches it at its radius, half the stand-in sphere's contact
            let touching = if inl_wall { 0.5 * contact } else { contact };
            if !BondParams::switch(p.stress_break) && reach > p.max_distance {
                note(
                    Finding::CreatedBroken {
                        touching_breaks: p.max_distance < touching,
                    },
                    a,
                    b,
                );
            }
            if p.create_distance < contact {
                note(Finding::CreateBelowContact, a, b);
            }
            if !zero_stiffness(&p).is_empty() {
                note(Finding::ZeroStiffness, a, b);
            }
            if p.create_distance - contact > smallest_radius(bodies, a, b, wall) {
                note(Finding::CreateBeyondContact, a, b);
            }
            if !BondParams::switch(p.create_always) && p.create_step <= first_step && !bonds_exist {
                note(Finding::CreateStepPassed, a, b);
            }
        }
    }
    found
}

/// Centre distance of the smallest touching spheres of types `a` and `b`;
/// for a wall, to the stand-in sphere of the particle's radius behind it
/// (`wall.rs`), which is the distance wall bonds form and break by.
fn contact_distance(bodies: &[TypeBodies], a: usize, b: usize, wall: bool) -> f64 {
    bodies[a].radius_min
        + if wall {
            bodies[a].radius_min
        } else {
            bodies[b].radius_min
        }
}

/// The laws switched on with a loading stiffness of 0, as (switch,
/// stiffness) fields. Compression is not among them: without its stiffness
/// the bond is refused ([`refusal`]); tension in stress mode neither
/// ([`reach_refusal`]).
/// The linear bond's stiffnesses stand for them (`k_n`, `k_t`,
/// [`parameter_name`] names them so).
fn zero_stiffness(p: &BondParams) -> Vec<(&'static str, &'static str)> {
    let stress = BondParams::switch(p.stress_break);
    let linear = BondParams::switch(p.linear);
    let pick = |nonlinear: f64, linear_k: f64| if linear { linear_k } else { nonlinear };
    [
        ("tension", "k_fn2", p.tension, pick(p.k_fn2, p.k_n), !stress),
        ("shear", "k_ft", p.shear, pick(p.k_ft, p.k_t), true),
        ("twist", "k_tn", p.twist, pick(p.k_tn, p.k_t), true),
        ("bend", "k_tt", p.bend, pick(p.k_tt, p.k_n), true),
    ]
    .into_iter()
    .filter(|&(_, _, on, k, checked)| checked && BondParams::switch(on) && k == 0.0)
    .map(|(law, k, _, _, _)| (law, k))
    .collect()
}

/// The smallest radius of the spheres of types `a` and `b` (of `a` for a
/// wall).
fn smallest_radius(bodies: &[TypeBodies], a: usize, b: usize, wall: bool) -> f64 {
    if wall {
        bodies[a].radius_min
    } else {
        bodies[a].radius_min.min(bodies[b].radius_min)
    }
}

/// A parameter's name as the engine's decks spell it.
/// Under the linear law (`Naming::*Linear`) the stiffness that plays the
/// part of a `bond/nonlinear` one is named instead (`k_n` for the normal and
/// bending stiffnesses, `k_t` for the shear and twisting ones).
pub fn parameter_name(field: &str, naming: Naming) -> &'static str {
    let linear = naming != naming.base();
    let field = match field {
        "k_fn1" | "ku_fn1" | "k_fn2" | "k_tt" if linear => "k_n",
        "k_ft" | "k_tn" if linear => "k_t",
        f => f,
    };
    let (id, row) = PARAMETERS
        .iter()
        .enumerate()
        .find(|(_, r)| r.name == field)
        .expect("a field of the parameter table");
    match naming {
        Naming::Lammps | Naming::LammpsLinear => row.name,
        Naming::Liggghts => row.liggghts_name,
        Naming::LiggghtsLinear => liggghts_name(true, id).unwrap_or(row.liggghts_name),
    }
}

/// The warning of one finding; `style` names the deck command.
#[allow(clippy::too_many_arguments)]
pub fn message(
    finding: Finding,
    a: usize,
    b: usize,
    p: &BondParams,
    bodies: &[TypeBodies],
    first_step: i64,
    wall: bool,
    naming: Naming,
    units: &UnitNames,
    style: &str,
) -> String {
    let l = units.length;
    let naming = naming.for_law(BondParams::switch(p.linear));
    let create = parameter_name("create_distance", naming);
    let reach = parameter_name("max_distance", naming);
    let always = parameter_name("create_always", naming);
    let create_step = parameter_name("create_step", naming);
    let contact = contact_distance(bodies, a, b, wall);
    let pair = if wall {
        format!("atom type {a} on the wall")
    } else {
        format!("atom types {a} and {b}")
    };
    match finding {
        Finding::CreatedBroken { touching_breaks } => {
            let how_often = if BondParams::switch(p.create_always) {
                format!("every step ({always} on)")
            } else {
                "in the step it forms".to_string()
            };
            let touching = if touching_breaks {
                format!("; {reach} is below the contact distance {contact:e} {l} of the smallest spheres, so a bond between touching spheres breaks too")
            } else {
                String::new()
            };
            format!(
                "{style} ({pair}): {create} {c:e} {l} > {reach} {r:e} {l}: a pair whose centres are between the two is bonded and broken {how_often}{touching}. Set {create} <= {reach}",
                c = p.create_distance,
                r = p.max_distance,
            )
        }
        Finding::ZeroStiffness => {
            let zero = zero_stiffness(p);
            let list = |names: Vec<&str>| names.join(", ");
            let stiffnesses = list(zero.iter().map(|z| parameter_name(z.1, naming)).collect());
            let laws = list(zero.iter().map(|z| parameter_name(z.0, naming)).collect());
            format!(
                "{style} ({pair}): {stiffnesses} 0 (also the value when left out) while {laws} on: the bonds resist nothing there; set the stiffness, or switch the law off"
            )
        }
        Finding::CreateBelowContact if p.create_distance == 0.0 => format!(
            "{style} ({pair}): {create} is 0 (also its value when left out): no pair bonds; set {create} near the contact distance {contact:e} {l} of the smallest spheres",
        ),
        Finding::CreateBeyondContact => format!(
            "{style} ({pair}): {create} {c:e} {l} is {d:e} {l} beyond the contact distance {contact:e} {l} of the smallest spheres, more than their radius {r:e} {l}: such spheres bond without touching",
            c = p.create_distance,
            d = p.create_distance - contact,
            r = smallest_radius(bodies, a, b, wall),
        ),
        Finding::CreateBelowContact => format!(
            "{style} ({pair}): {create} {c:e} {l} is below the contact distance {contact:e} {l} of the smallest spheres: only pairs overlapping by more than {d:e} {l} bond",
            c = p.create_distance,
            d = contact - p.create_distance,
        ),
        Finding::CreateStepPassed => format!(
            "{style} ({pair}): {create_step} {s} is not after step {first_step}, where the first run started, and {always} is off: no bond forms (bonds that exist are kept)",
            s = p.create_step,
        ),
    }
}

/// The largest neighbour-list reach a bond type may ask of the engines, in
/// diameters of the smallest spheres it joins: the reach the engines'
/// lists hold without their binning failing (LIGGGHTS's own limit).
pub const MAX_REACH_DIAMETERS: f64 = 10.0;

/// Why the neighbour reach a bond type needs cannot be held, as the deck
/// names the parameters (`None` when it can): a bond that never breaks by
/// stretching, or a reach of more than [`MAX_REACH_DIAMETERS`] diameters of
/// the smallest spheres (radius `min_radius`). `pair` names the atom types.
pub fn reach_refusal(
    laws: &BondLaws,
    min_radius: f64,
    naming: Naming,
    pair: &str,
    units: &UnitNames,
) -> Option<ParameterError> {
    let p = &laws.params;
    let l = units.length;
    let naming = naming.for_law(laws.linear);
    let name = |field| parameter_name(field, naming);
    let stress = BondParams::switch(p.stress_break);
    let tension_stiffness = if laws.linear { p.k_n } else { p.k_fn2 };
    let diameters = |x: f64| 1.1 * x / (2.0 * min_radius);
    let factor = laws.contact_distance_factor(min_radius);
    if diameters(p.create_distance) > MAX_REACH_DIAMETERS {
        return refused("create_distance", format!(
            "{pair}: {c} {v:e} {l} reaches {d:.1} diameters of the smallest spheres (radius {min_radius:e} {l}; with a 10% margin), beyond the {MAX_REACH_DIAMETERS} diameters the neighbour lists hold: pairs that far apart do not touch; set {c} near the contact distance {contact:e} {l}",
            c = name("create_distance"),
            v = p.create_distance,
            d = diameters(p.create_distance),
            contact = 2.0 * min_radius,
        ));
    }
    if factor.is_finite() && factor <= MAX_REACH_DIAMETERS {
        return None;
    }
    let (field, cause) = if !stress {
        let r = name("max_distance");
        let cause = if factor.is_finite() {
            format!("{r} {v:e} {l} lets a bond stretch to {factor:.1} diameters of the smallest spheres (radius {min_radius:e} {l}; with a 10% margin), beyond the {MAX_REACH_DIAMETERS} diameters the neighbour lists hold; set a smaller {r}", v = p.max_distance)
        } else {
            let phrases = match naming.base() {
                Naming::Lammps => " ('break distance R', or break by stress: 'break stress S T')",
                _ => "",
            };
            format!("{r} is inf: a bond never breaks by stretching, so no neighbour list can keep it; set a finite {r}{phrases}")
        };
        ("max_distance", cause)
    } else if !BondParams::switch(p.tension) {
        let t = name("tension");
        ("tension", format!("{t} is off in stress mode: a bond never breaks by stretching, so no neighbour list can keep it; switch {t} on or break by distance"))
    } else if !(tension_stiffness > 0.0) {
        let k = name("k_fn2");
        ("k_fn2", format!("{k} is {v}: in stress mode a bond without tension stiffness never reaches its tensile strength, so no neighbour list can keep it; set {k} > 0", v = tension_stiffness))
    } else {
        let ratio = if BondParams::switch(p.use_ratio) {
            format!(
                " x {g} {v}",
                g = name("tension_compression_ratio"),
                v = p.tension_compression_ratio
            )
        } else {
            String::new()
        };
        let stretch = laws.max_bond_distance(p.create_distance) - p.create_distance;
        let what = if factor.is_finite() {
            format!("stretches a bond by {stretch:e} {l} before it breaks, to {factor:.1} diameters of the smallest spheres (radius {min_radius:e} {l}; with a 10% margin), beyond the {MAX_REACH_DIAMETERS} diameters the neighbour lists hold")
        } else {
            "never breaks a bond by stretching, so no neighbour list can keep it".to_string()
        };
        let cause = format!(
            "the tensile strength {s} {sv:e}{ratio} over {k} {kv:e} {what}; lower {s}{or_ratio} or raise {k}",
            s = name("max_sigma"),
            sv = p.max_sigma,
            k = name("k_fn2"),
            kv = tension_stiffness,
            or_ratio = if BondParams::switch(p.use_ratio) {
                format!(" or {}", name("tension_compression_ratio"))
            } else {
                String::new()
            },
        );
        ("max_sigma", cause)
    };
    refused(field, format!("{pair}: {cause}"))
}

/// The refusal of row `field` with `message`.
fn refused(field: &str, message: String) -> Option<ParameterError> {
    let parameter = PARAMETERS
        .iter()
        .position(|r| r.name == field)
        .expect("a field of the parameter table");
    Some(ParameterError { parameter, message })
}

/// Why a bond type of atom types `a`, `b` cannot run with the spheres
/// present (`None` when it can), naming the parameters as the deck spells
/// them: no compression stiffness while the bond, replacing the contact,
/// must hold compression; a linear continuation of the compression law
/// beyond the bond radius, which leaves the bond almost no compression
/// stiffness; a neighbour reach the engines cannot hold
/// ([`reach_refusal`]).
pub fn refusal(
    laws: &BondLaws,
    a: usize,
    b: usize,
    bodies: &[TypeBodies],
    wall: bool,
    naming: Naming,
    units: &UnitNames,
) -> Option<ParameterError> {
    let p = &laws.params;
    let l = units.length;
    let naming = naming.for_law(laws.linear);
    let name = |field| parameter_name(field, naming);
    let pair = if wall {
        format!("atom type {a} on the wall")
    } else {
        format!("atom types {a} and {b}")
    };
    // (the linear bond keeps the contact under it)
    if BondParams::switch(p.compression) && p.k_fn1 == 0.0 && !laws.linear {
        return refused("k_fn1", format!(
            "{pair}: {k} is 0 (also its value when left out) while {c} is on: an intact bond replaces the contact, so bonded spheres pushed together would pass through each other; set {k} > 0",
            k = name("k_fn1"),
            c = name("compression"),
        ));
    }
    let min_radius = if wall {
        bodies[a].radius_min
    } else {
        bodies[a].radius_min.min(bodies[b].radius_min)
    };
    let rb = p.lambda * min_radius;
    if BondParams::switch(p.compression) && p.compression_linear_below > rb {
        return refused("compression_linear_below", format!(
            "{pair}: {e} {v:e} {l} exceeds the bond radius {rb:e} {l} of the smallest spheres ({lambda} {lv} x radius {min_radius:e} {l}): the compression law would be linear, with the slope it has at {e}, over every compression a bond takes, far softer than the law, and bonded spheres pushed together would pass through each other; set {e} well below the bond radius (e.g. 1e-3 of it), or 0 for the law itself",
            e = name("compression_linear_below"),
            v = p.compression_linear_below,
            lambda = name("lambda"),
            lv = p.lambda,
        ));
    }
    reach_refusal(laws, min_radius, naming, &pair, units)
}

/// The first [`refusal`] among the pairs of types `1..=ntypes` present (as
/// in [`findings`]), with `laws(a, b)` the bond type of `a`, `b`.
pub fn first_refusal<'a>(
    ntypes: usize,
    bodies: &[TypeBodies],
    laws: impl Fn(usize, usize) -> Option<&'a BondLaws>,
    wall: bool,
    naming: Naming,
    units: &UnitNames,
) -> Option<ParameterError> {
    for a in 1..=ntypes {
        let first_b = if wall { 1 } else { a };
        for b in first_b..=ntypes {
            if !bodies[a].present() || !(wall || bodies[b].present()) {
                continue;
            }
            if let Some(m) = laws(a, b) {
                if let Some(message) = refusal(m, a, b, bodies, wall, naming, units) {
                    return Some(message);
                }
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spheres(r: f64) -> Vec<TypeBodies> {
        vec![
            TypeBodies::none(),
            TypeBodies {
                radius_min: r,
                radius_max: r,
                mass_min: 1e-5,
            },
        ]
    }

    fn bond(create: f64, reach: f64, step: i64, always: bool) -> BondParams {
        BondParams {
            k_fn2: 1e9,
            ku_fn2: 1e9,
            k_ft: 1e9,
            k_tn: 1e9,
            ku_tn: 1e9,
            k_tt: 1e9,
            ku_tt: 1e9,
            create_distance: create,
            max_distance: reach,
            create_step: step,
            create_always: always as i32,
            ..BondParams::default()
        }
    }

    fn kinds(p: BondParams, step: i64) -> Vec<Finding> {
        findings(1, &spheres(1e-3), |_, _| Some(p), step, false, false)
            .into_iter()
            .map(|f| f.0)
            .collect()
    }

    #[test]
    fn consistent_rules_find_nothing() {
        assert!(kinds(bond(2.05e-3, 2.08e-3, 1, false), 0).is_empty());
        assert!(kinds(bond(2.05e-3, 2.05e-3, 0, true), 10).is_empty());
    }

    #[test]
    fn each_contradiction_is_found() {
        assert_eq!(
            kinds(bond(2.2e-3, 2.08e-3, 1, true), 0),
            [Finding::CreatedBroken {
                touching_breaks: false
            }]
        );
        assert_eq!(
            kinds(bond(2.2e-3, 1.9e-3, 1, false), 0),
            [Finding::CreatedBroken {
                touching_breaks: true
            }]
        );
        assert_eq!(
            kinds(bond(1.5e-3, 2.08e-3, 1, false), 0),
            [Finding::CreateBelowContact]
        );
        assert_eq!(
            kinds(bond(2.05e-3, 2.08e-3, 0, false), 0),
            [Finding::CreateStepPassed]
        );
        assert_eq!(
            kinds(bond(2.05e-3, 2.08e-3, -5, false), 0),
            [Finding::CreateStepPassed]
        );
        assert_eq!(
            kinds(bond(2.05e-3, 2.08e-3, 100, false), 100),
            [Finding::CreateStepPassed]
        );
    }

    #[test]
    fn a_creation_distance_a_radius_beyond_contact_is_found_and_zero_says_no_bond_forms() {
        let far = BondParams {
            stress_break: 1,
            ..bond(3.2e-3, 2.08e-3, 1, false)
        };
        assert_eq!(kinds(far, 0), [Finding::CreateBeyondContact]);
        let near = BondParams {
            stress_break: 1,
            ..bond(2.9e-3, 2.08e-3, 1, false)
        };
        assert!(kinds(near, 0).is_empty());
        let never = bond(0.0, 2.08e-3, 1, false);
        assert_eq!(kinds(never, 0), [Finding::CreateBelowContact]);
        let text = message(
            Finding::CreateBelowContact,
            1,
            1,
            &never,
            &spheres(1e-3),
            0,
            false,
            Naming::Liggghts,
            &UnitNames::SI,
            "x",
        );
        assert!(
            text.contains("createDistanceBondnonlinear is 0") && text.contains("no pair bonds"),
            "{text}"
        );
    }

    #[test]
    fn a_law_switched_on_without_stiffness_is_named_with_its_switch() {
        let p = BondParams {
            k_ft: 0.0,
            k_tt: 0.0,
            ..bond(2.05e-3, 2.08e-3, 1, false)
        };
        assert_eq!(kinds(p, 0), [Finding::ZeroStiffness]);
        let text = message(
            Finding::ZeroStiffness,
            1,
            1,
            &p,
            &spheres(1e-3),
            0,
            false,
            Naming::Lammps,
            &UnitNames::SI,
            "x",
        );
        assert!(
            text.contains("k_ft, k_tt 0") && text.contains("shear, bend on"),
            "{text}"
        );
        let off = BondParams {
            shear: 0,
            bend: 0,
            ..p
        };
        assert!(kinds(off, 0).is_empty());
    }

    #[test]
    fn stress_mode_has_no_break_distance() {
        let p = BondParams {
            stress_break: 1,
            ..bond(2.2e-3, 2.08e-3, 1, true)
        };
        assert!(kinds(p, 0).is_empty());
    }

    #[test]
    fn an_inl_wall_bond_forms_within_half_the_creation_distance() {
        let bodies = spheres(1e-3);
        let inl = BondParams {
            inl_compatible: 1,
            ..bond(2.1e-3, 1.1e-3, 1, false)
        };
        assert!(findings(1, &bodies, |_, _| Some(inl), 0, false, true).is_empty());
        let far = BondParams {
            create_distance: 2.4e-3,
            ..inl
        };
        // it touches the wall at its radius, inside max_distance: touching
        // spheres do not break at once
        assert_eq!(
            findings(1, &bodies, |_, _| Some(far), 0, false, true)[0].0,
            Finding::CreatedBroken {
                touching_breaks: false
            }
        );
    }

    #[test]
    fn a_wall_bond_is_measured_to_the_stand_in_sphere_behind_the_wall() {
        let bodies = spheres(1e-3);
        let p = bond(2.05e-3, 2.08e-3, 1, false);
        assert!(findings(1, &bodies, |_, _| Some(p), 0, false, true).is_empty());
        let near = bond(1.05e-3, 1.1e-3, 1, false);
        assert_eq!(
            findings(1, &bodies, |_, _| Some(near), 0, false, true)[0].0,
            Finding::CreateBelowContact
        );
    }

    #[test]
    fn messages_name_the_parameters_as_each_engine_spells_them() {
        let bodies = spheres(1e-3);
        let p = bond(2.2e-3, 2.08e-3, 1, true);
        let f = Finding::CreatedBroken {
            touching_breaks: false,
        };
        let lig = message(
            f,
            1,
            1,
            &p,
            &bodies,
            0,
            false,
            Naming::Liggghts,
            &UnitNames::SI,
            "cohesion bond/nonlinear",
        );
        assert!(
            lig.contains("createDistanceBondnonlinear") && lig.contains("maxDistanceBondnonlinear"),
            "{lig}"
        );
        assert!(lig.contains("every step (createBondAlways on)"), "{lig}");
        let lmp = message(
            f,
            1,
            1,
            &p,
            &bodies,
            0,
            false,
            Naming::Lammps,
            &UnitNames::SI,
            "pair granbond",
        );
        assert!(
            lmp.contains("create_distance") && lmp.contains("max_distance"),
            "{lmp}"
        );
        let s = message(
            Finding::CreateStepPassed,
            1,
            1,
            &p,
            &bodies,
            7,
            false,
            Naming::Liggghts,
            &UnitNames::of_style("micro"),
            "x",
        );
        assert!(s.contains("tsCreateBondnonlinear 1 is not after step 7,"), "{s}");
        let below = message(
            Finding::CreateBelowContact,
            1,
            1,
            &bond(1.5e3, 2.08e3, 1, false),
            &spheres(1e3),
            0,
            false,
            Naming::Lammps,
            &UnitNames::of_style("micro"),
            "x",
        );
        assert!(
            below.contains("contact distance 2e3 um") && !below.contains(" m "),
            "{below}"
        );
    }

    #[test]
    fn a_continuation_with_bonds_is_not_a_passed_creation_step() {
        let p = bond(2.05e-3, 2.08e-3, 1, false);
        let with_bonds = findings(1, &spheres(1e-3), |_, _| Some(p), 15000, true, false);
        assert!(with_bonds.is_empty(), "{with_bonds:?}");
        let without = findings(1, &spheres(1e-3), |_, _| Some(p), 15000, false, false);
        assert_eq!(without[0].0, Finding::CreateStepPassed);
    }
}
