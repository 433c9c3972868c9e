//! `extern "C"` surface of the checks engines run at every `run`: the time
//! step against the stiffest bond or contact present, and the bond's
//! creation and break rules against each other. Each returns a report whose
//! message the adapter prints as an engine warning.

use super::entry;
use super::error::{Failure, Status};
use super::guard::{positive, reference, reference_mut, slice, time_step};
use crate::bond::creation_check::{findings, first_refusal, message, parameter_name, reach_refusal, Naming};
use crate::bond::section::section;
use crate::bond::{BondModel, BondParams};
use crate::contact::VoigtModel;
use crate::timestep_check::{
    scan, AtRest, CitedNames, Rattle, StepLimits, TimestepLevel, TypeBodies, UnitNames,
};
use std::ffi::{c_char, CStr};

/// Capacity of [`CheckReport::message`], terminating NUL included.
pub const GRANBOND_CHECK_MESSAGE_LEN: usize = 2048;

/// What a check found: a level and the warning the adapter prints; the
/// time-step checks also give the limiting type pair and its steps.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct CheckReport {
    /// 0: nothing to say. Time-step checks: 1 above the recommended step, 2
    /// above the critical step. Creation check: the number of findings.
    pub level: i32,
    /// Time-step checks: the first atom type of the limiting pair (0 when
    /// nothing limits).
    pub type_a: i32,
    /// Time-step checks: the second atom type of the limiting pair.
    pub type_b: i32,
    /// Time-step checks: the critical step of the limiting pair (infinite when
    /// nothing limits).
    pub critical: f64,
    /// Time-step checks: the recommended step of the limiting pair (infinite
    /// when nothing limits).
    pub recommended: f64,
    /// The warning, NUL terminated; several findings are separated by
    /// newlines. Empty at level 0.
    pub message: [c_char; GRANBOND_CHECK_MESSAGE_LEN],
}

impl CheckReport {
    pub(super) fn write(&mut self, level: i32, text: &str) {
        self.level = level;
        // cut at a character boundary so the message stays UTF-8
        let mut end = text.len().min(GRANBOND_CHECK_MESSAGE_LEN - 1);
        while !text.is_char_boundary(end) {
            end -= 1;
        }
        for (d, s) in self.message.iter_mut().zip(text[..end].bytes()) {
            *d = s as c_char;
        }
        self.message[end] = 0;
    }

    fn clear(&mut self) {
        self.type_a = 0;
        self.type_b = 0;
        self.critical = f64::INFINITY;
        self.recommended = f64::INFINITY;
        self.write(0, "");
    }
}

/// The per-type table arguments: `ntypes >= 0`, `bodies[ntypes + 1]`,
/// `models[(ntypes + 1)^2]` (entry `a * (ntypes + 1) + b`, null = no model),
/// every model pointer checked before any is used.
#[allow(clippy::type_complexity)]
unsafe fn tables<'a, M>(
    ntypes: i32,
    models: *const *const M,
    bodies: *const TypeBodies,
) -> Result<(usize, Vec<Option<&'a M>>, &'a [TypeBodies]), Failure> {
    let n = usize::try_from(ntypes)
        .ok()
        .filter(|&n| n < 1 << 15)
        .ok_or_else(|| {
            Failure::new(
                Status::InvalidArgument,
                format!("ntypes must be 0..32767; got {ntypes}"),
            )
        })?;
    let mut table = Vec::with_capacity((n + 1) * (n + 1));
    for &p in slice(models, (n + 1) * (n + 1), "models")? {
        table.push(if p.is_null() {
            None
        } else {
            Some(reference(p, "models[a * (ntypes + 1) + b]")?)
        });
    }
    let bodies = slice(bodies, n + 1, "bodies")?;
    Ok((n, table, bodies))
}

unsafe fn style_name(style: *const c_char) -> Result<String, Failure> {
    if style.is_null() {
        return Err(Failure::new(Status::NullPointer, "argument `style` is null"));
    }
    Ok(CStr::from_ptr(style).to_string_lossy().into_owned())
}

/// The names of the engine's `units` style (`units`: its name, e.g. "si").
unsafe fn unit_names(units: *const c_char) -> Result<UnitNames, Failure> {
    if units.is_null() {
        return Err(Failure::new(Status::NullPointer, "argument `units` is null"));
    }
    Ok(UnitNames::of_style(&CStr::from_ptr(units).to_string_lossy()))
}

fn naming_of(naming: i32) -> Result<Naming, Failure> {
    match naming {
        0 => Ok(Naming::Lammps),
        1 => Ok(Naming::Liggghts),
        _ => Err(Failure::new(
            Status::InvalidArgument,
            format!("naming must be 0 (LAMMPS) or 1 (LIGGGHTS); got {naming}"),
        )),
    }
}

fn cited_names(naming: Naming) -> CitedNames {
    let naming = naming.base();
    CitedNames {
        max_sigma: parameter_name("max_sigma", naming),
        k_fn1: parameter_name("k_fn1", naming),
        compression_linear_below: parameter_name("compression_linear_below", naming),
        ku_fn1: parameter_name("ku_fn1", naming),
        k_fn2: parameter_name("k_fn2", naming),
        eta_fn: parameter_name("eta_fn", naming),
        k_ft: parameter_name("k_ft", naming),
        k_tn: parameter_name("k_tn", naming),
        k_tt: parameter_name("k_tt", naming),
    }
}

/// The estimates the bond time-step check reports for a bond type between
/// spheres of these radii and masses, at step `dt`.
fn bond_step_limits(
    model: &BondModel,
    radius_i: f64,
    radius_j: f64,
    mass_i: f64,
    mass_j: f64,
    dt: f64,
) -> StepLimits {
    let rattle_step = model.rattle_timestep(radius_i, radius_j, mass_i, mass_j);
    let rattle = rattle_step.is_finite().then(|| Rattle {
        threshold: model.compression_break_threshold(),
        floor: model.compression_noise_floor(dt, radius_i, radius_j, mass_i, mass_j),
        step: rattle_step,
        max_sigma: model.params.max_sigma,
        k_fn1: model.params.k_fn1,
        rb: section(model.params.lambda, radius_i, radius_j).rb,
    });
    let recommended = model.recommended_timestep(radius_i, radius_j, mass_i, mass_j);
    let rest_step = model.rest_timestep(radius_i, radius_j, mass_i, mass_j);
    let at_rest = rest_step.is_finite().then(|| {
        let rb = section(model.params.lambda, radius_i, radius_j).rb;
        let p = &model.params;
        let regularisation = model.rest_regularisation(rb);
        let regularised = BondModel::new(BondParams {
            compression_linear_below: regularisation,
            ..*p
        })
        .map_or(recommended, |m| {
            m.recommended_timestep(radius_i, radius_j, mass_i, mass_j)
        });
        AtRest {
            step: rest_step,
            fraction: model.rest_stable_fraction(),
            recommended,
            ratio: p.ku_fn1 / p.k_fn1,
            eta_fn: model.rest_damping(),
            regularisation,
            matched: regularisation != 1e-3 * rb,
            regularised,
        }
    });
    StepLimits {
        critical: model.critical_timestep(radius_i, radius_j, mass_i, mass_j),
        // The check warns above the step at which the run is stable.
        recommended: recommended.min(rest_step),
        modes: Some(model.mode_limits(radius_i, radius_j, mass_i, mass_j)),
        rattle,
        at_rest,
    }
}

/// Body of both time-step checks.
#[allow(clippy::too_many_arguments)]
unsafe fn timestep_check<M>(
    what: &str,
    models: *const *const M,
    ntypes: i32,
    bodies: *const TypeBodies,
    dt: f64,
    names: impl Fn(&M) -> CitedNames,
    units: *const c_char,
    style: *const c_char,
    report: &mut CheckReport,
    limits: fn(&M, f64, f64, f64, f64, f64) -> StepLimits,
) -> Result<(), Failure> {
    report.clear();
    let dt = time_step(dt, "dt")?;
    if dt == 0.0 {
        return Err(Failure::new(
            Status::InvalidArgument,
            "the time step (timestep) is 0: nothing would move and no bond or contact would be stepped; set timestep > 0",
        ));
    }
    let style = style_name(style)?;
    let units = unit_names(units)?;
    let (n, table, bodies) = tables(ntypes, models, bodies)?;
    let verdict = scan(
        n,
        bodies,
        |a, b| table[a * (n + 1) + b],
        |m: &&M, ri, rj, mi, mj| limits(m, ri, rj, mi, mj, dt),
        dt,
    )
    .map_err(|(a, b, c)| {
        Failure::new(
            Status::InvalidArgument,
            format!("atom types {a} and {b}: the critical time step cannot be estimated (it gives {c}): a stiffness or damping parameter of this type pair, or the spheres' radii and masses, lies outside the range the estimate can evaluate"),
        )
    })?;
    if let Some(v) = verdict {
        report.type_a = v.type_a as i32;
        report.type_b = v.type_b as i32;
        report.critical = v.critical;
        report.recommended = v.recommended;
        // the limiting pair's model names its parameters
        let model = table[v.type_a * (n + 1) + v.type_b].or_else(|| table.iter().flatten().next().copied());
        if let Some(m) = model {
            report.write(
                v.level as i32,
                &v.message(&style, what, bodies, &names(m), &units),
            );
        }
        debug_assert_eq!(report.level != 0, v.level != TimestepLevel::Safe);
    }
    Ok(())
}

/// Checks the time step `dt` against the bonds of every pair of atom types
/// present: `models[a * (ntypes + 1) + b]` the bond model of types `a`, `b`
/// (null: none), `bodies[t]` the smallest and largest radius and the
/// lightest mass of type `t` over all ranks (index 0 unused; a type without
/// atoms has infinite `radius_min`). `naming`: 0 LAMMPS keywords, 1
/// LIGGGHTS names in the message; `units`: the engine's `units` style (the
/// names of units in the message); `style` names the deck command. The pair
/// with the shortest recommended step limits; `out` says how `dt` compares
/// with it and holds the warning to print.
///
/// # Safety
/// Pointers must be null or valid for the sizes above; `units` and `style`
/// NUL terminated strings.
#[entry(out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_timestep_check(
    models: *const *const BondModel,
    ntypes: i32,
    bodies: *const TypeBodies,
    dt: f64,
    naming: i32,
    units: *const c_char,
    style: *const c_char,
    out: *mut CheckReport,
) -> Status {
    let naming = naming_of(naming)?;
    timestep_check(
        "bond",
        models,
        ntypes,
        bodies,
        dt,
        |m: &BondModel| cited_names(naming.for_law(m.linear)),
        units,
        style,
        out,
        bond_step_limits,
    )
}

/// `granbond_bond_timestep_check` for the Voigt contact (no parameter is
/// cited, so no naming).
///
/// # Safety
/// As `granbond_bond_timestep_check`.
#[entry(out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_timestep_check(
    models: *const *const VoigtModel,
    ntypes: i32,
    bodies: *const TypeBodies,
    dt: f64,
    units: *const c_char,
    style: *const c_char,
    out: *mut CheckReport,
) -> Status {
    timestep_check(
        "contact",
        models,
        ntypes,
        bodies,
        dt,
        |_: &VoigtModel| cited_names(Naming::Lammps),
        units,
        style,
        out,
        |m: &VoigtModel, ri, rj, mi, mj, _dt| StepLimits::plain(m.critical_timestep(ri, rj, mi, mj)),
    )
}

/// Checks the creation and break rules of the bond models (tables as in
/// `granbond_bond_timestep_check`) against each other and the spheres
/// present: a creation distance beyond the break distance, a creation
/// distance below contact, a creation step that has passed (`first_step`:
/// the step the model's first run started from, while no bond exists:
/// `bonds_exist` non-zero when intact bonds of these models exist over all
/// ranks, as in a run continued from a restart file). `wall` non-zero: wall
/// bonds (measured to the stand-in sphere of the particle's radius behind
/// the wall, so twice the radius is the contact distance; the wall's type
/// needs no atoms). `naming`: 0 LAMMPS keywords, 1 LIGGGHTS names in the
/// message; `units`: the engine's `units` style. `out->level` is the number
/// of findings. A bond type that cannot run with the spheres present (no
/// compression stiffness while compression is on, a linear continuation of
/// the compression law beyond the bond radius, a neighbour reach beyond
/// what the lists hold) is refused (`GB_STATUS_INVALID_PARAMETER`) with a
/// message naming the parameters.
///
/// # Safety
/// As `granbond_bond_timestep_check`.
#[entry(out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_creation_check(
    models: *const *const BondModel,
    ntypes: i32,
    bodies: *const TypeBodies,
    first_step: i64,
    bonds_exist: i32,
    wall: i32,
    naming: i32,
    units: *const c_char,
    style: *const c_char,
    out: *mut CheckReport,
) -> Status {
    out.clear();
    let naming = naming_of(naming)?;
    let style = style_name(style)?;
    let units = unit_names(units)?;
    let (n, models, bodies) = tables(ntypes, models, bodies)?;
    let wall = wall != 0;
    if let Some(refused) = first_refusal(
        n,
        bodies,
        |a, b| models[a * (n + 1) + b].map(|m| &**m),
        wall,
        naming,
        &units,
    ) {
        return Err(refused.into());
    }
    let table: Vec<Option<BondParams>> = models.iter().map(|m| m.map(|m| m.params)).collect();
    let found = findings(
        n,
        bodies,
        |a, b| table[a * (n + 1) + b],
        first_step,
        bonds_exist != 0,
        wall,
    );
    let text: Vec<String> = found
        .iter()
        .map(|&(f, a, b)| {
            let p = table[a * (n + 1) + b].expect("a finding has a model");
            message(f, a, b, &p, bodies, first_step, wall, naming, &units, &style)
        })
        .collect();
    out.write(found.len() as i32, &text.join("\n"));
    Ok(())
}

/// The neighbour-list reach, as a multiple of the contact distance
/// `2 min_radius` of the smallest spheres, that keeps every intact bond of
/// `model` (atom types `type_a`, `type_b`, for the message) in the engine's
/// lists, written to `out`. A bond that never breaks by stretching, or a
/// reach (or creation distance) of more than ten diameters, is refused
/// (`GB_STATUS_INVALID_PARAMETER`) with a message naming the parameters
/// that set it (`naming`: 0 LAMMPS keywords, 1 LIGGGHTS names; `units`: the
/// engine's `units` style).
///
/// # Safety
/// `model` must be null or a model; `units` a NUL-terminated string; `out`
/// null or valid for writes.
#[entry(model: reference, out: reference_mut, min_radius: positive)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_neighbour_reach(
    model: *const BondModel,
    min_radius: f64,
    type_a: i32,
    type_b: i32,
    naming: i32,
    units: *const c_char,
    out: *mut f64,
) -> Status {
    let naming = naming_of(naming)?;
    let units = unit_names(units)?;
    let pair = format!("atom types {type_a} and {type_b}");
    if let Some(refused) = reach_refusal(model, min_radius, naming, &pair, &units) {
        return Err(refused.into());
    }
    *out = model.contact_distance_factor(min_radius);
    Ok(())
}
