//! Whether the creation and break rules of a bond type contradict each other
//! or the spheres present: checked by the engines at every `run`.
//! LIGGGHTS-INL runs a deck with any such combination, so each
//! finding is a warning that names the parameters as the deck spells them.

use super::params::{BondParams, PARAMETERS};
use crate::timestep_check::{TypeBodies, UnitNames};

/// Which spelling of the parameter names the messages use.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Naming {
    /// `pair_coeff ... bond/nonlinear` keywords (LAMMPS).
    Lammps = 0,
    /// `fix property/global` names and switches (LIGGGHTS).
    Liggghts = 1,
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
            let reach = if wall && BondParams::switch(p.inl_compatible) {
                0.5 * p.create_distance
            } else {
                p.create_distance
            };
            if !BondParams::switch(p.stress_break) && reach > p.max_distance {
                note(
                    Finding::CreatedBroken {
                        touching_breaks: p.max_distance < contact,
                    },
                    a,
                    b,
                );
            }
            if p.create_distance < contact {
                note(Finding::CreateBelowContact, a, b);
            }
            if !BondParams::switch(p.create_always) && p.create_step <= first_step && !bonds_exist {
                note(Finding::CreateStepPassed, a, b);
            }
        }
    }
    found
}

/// Centre distance of the smallest touching spheres of types `a` and `b`
/// (centre to surface for a wall).
fn contact_distance(bodies: &[TypeBodies], a: usize, b: usize, wall: bool) -> f64 {
    bodies[a].radius_min + if wall { 0.0 } else { bodies[b].radius_min }
}

/// A parameter's name as the engine's decks spell it.
pub fn parameter_name(field: &str, naming: Naming) -> &'static str {
    let row = PARAMETERS
        .iter()
        .find(|r| r.name == field)
        .expect("a field of the parameter table");
    match naming {
        Naming::Lammps => row.name,
        Naming::Liggghts => row.liggghts_name,
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
        assert!(matches!(
            findings(1, &bodies, |_, _| Some(far), 0, false, true)[0].0,
            Finding::CreatedBroken { .. }
        ));
    }

    #[test]
    fn a_wall_counts_only_the_sphere() {
        let bodies = spheres(1e-3);
        let p = bond(1.05e-3, 1.1e-3, 1, false);
        assert!(findings(1, &bodies, |_, _| Some(p), 0, false, true).is_empty());
        assert_eq!(
            findings(1, &bodies, |_, _| Some(p), 0, false, false)[0].0,
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
