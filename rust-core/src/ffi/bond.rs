//! `extern "C"` surface of `bond/nonlinear`.

use super::entry;
use super::error::{Failure, Status};
use super::guard::{
    array, array_mut, finite_vector3, non_negative, positive, reference, reference_mut, slice, slice_mut,
    time_step, vector3, FailedIndex,
};
use super::results;
use crate::bond::creation::status_and_step_allow;
use crate::bond::creation_check::{parameter_name, Naming};
use crate::bond::output_slots::{load_output, store_output};
use crate::bond::wall::wall_kinematics;
use crate::bond::{
    BondModel, BondOutput, BondParams, BondState, BondStatus, WallBondState, BOND_STATE_LEN, PARAMETERS,
    WALL_BOND_STATE_LEN,
};
use crate::contact::ContactOutput;
pub use crate::kinematics::SphereKinematics;
use crate::kinematics::{bond_centre, separated, KinematicsError, PairKinematics};
use crate::pair_source::{AtomArrays, IndexedPairs};
use crate::under_bond::contact_loads_under_bond;
use std::ffi::{c_char, CStr};

/// Fills `params` with the defaults (switches as in LIGGGHTS-INL, no
/// stiffness, no breakage).
///
/// # Safety
/// `params` must be null or valid for writes.
#[entry(params: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_params_default(params: *mut BondParams) -> Status {
    *params = BondParams::default();
    Ok(())
}

/// Fills `params` with the defaults of a law in the deck units of `units`,
/// the engine's `units` style ("si", "micro", ...): the defaults that carry
/// units converted from SI, or left without a value (NaN) where the style
/// has no physical scale (`BondParams::default_in_units`). `linear`
/// non-zero: those of LIGGGHTS-INL's linear bond, `linear` and
/// `contact_under_bond` on (`BondParams::linear_default_in_units`).
///
/// # Safety
/// `units` must be null or a C string; `params` null or valid for writes.
#[entry(params: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_params_default_in_units(
    units: *const c_char,
    linear: i32,
    params: *mut BondParams,
) -> Status {
    if units.is_null() {
        return Err(Failure::new(Status::NullPointer, "argument `units` is null"));
    }
    let style = CStr::from_ptr(units).to_string_lossy();
    *params = if linear != 0 {
        BondParams::linear_default_in_units(&style)
    } else {
        BondParams::default_in_units(&style)
    };
    Ok(())
}

/// Sets `params->contact_under_bond` for a deck that does not give it: on
/// where the law `params` name keeps some of the contact's loads under an
/// intact bond (`linear`, `inl_compatible`), off where the bond replaces the
/// contact (`BondParams::contact_under_bond_by_law`). Call it once the
/// deck's switches are in `params`.
///
/// # Safety
/// `params` must be null or valid for reads and writes.
#[entry(params: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_params_contact_under_bond_by_law(params: *mut BondParams) -> Status {
    params.contact_under_bond_by_law();
    Ok(())
}

/// Validates `params` and builds a model. On `InvalidParameter` the message
/// names the parameter (LAMMPS keyword and LIGGGHTS name) and its range, and
/// `granbond_last_error_parameter` gives its id.
///
/// # Safety
/// `params` must be null or point to a `GbBondParams`; `model` null or valid
/// for writes. Free the model with `granbond_bond_model_free`.
#[entry(model: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_model_new(
    params: *const BondParams,
    model: *mut *mut BondModel,
) -> Status {
    // cleared before `params` is looked at: no failure leaves a pointer
    *model = std::ptr::null_mut();
    let m = BondModel::new(*reference(params, "params")?)?;
    *model = Box::into_raw(Box::new(m));
    Ok(())
}

/// Frees a model from `granbond_bond_model_new` (null is ignored).
///
/// # Safety
/// `model` must come from `granbond_bond_model_new` and not be used again.
#[entry(or = ())]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_model_free(model: *mut BondModel) {
    if !model.is_null() {
        drop(Box::from_raw(model));
    }
}

/// Number of rows in the bond parameter table (ids of
/// `granbond_last_error_parameter`).
#[entry(or = 0)]
#[no_mangle]
pub extern "C" fn granbond_bond_parameter_count() -> usize {
    PARAMETERS.len()
}

/// The bond state as a struct view of a caller's `double[GRANBOND_BOND_STATE_LEN]`.
unsafe fn bond_state<'a>(state: *mut f64, name: &str) -> Result<&'a mut BondState, Failure> {
    let slots = reference_mut(state as *mut [f64; BOND_STATE_LEN], name)?;
    Ok(BondState::from_slots_mut(slots))
}

unsafe fn wall_state<'a>(state: *mut f64, name: &str) -> Result<&'a mut WallBondState, Failure> {
    let slots = reference_mut(state as *mut [f64; WALL_BOND_STATE_LEN], name)?;
    // SAFETY: WallBondState is repr(C) of exactly WALL_BOND_STATE_LEN f64.
    Ok(&mut *(slots as *mut [f64; WALL_BOND_STATE_LEN] as *mut WallBondState))
}

/// Creates the bond in `state` (`double[GRANBOND_BOND_STATE_LEN]`, all zero
/// for a pair never bonded) if the creation rules allow it at `step`;
/// `*created` tells whether it did.
///
/// # Safety
/// Pointers must be null or valid for the sizes above.
#[entry(model: reference, kinematics: reference, state: bond_state, created: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_try_create(
    model: *const BondModel,
    kinematics: *const PairKinematics,
    step: i64,
    state: *mut f64,
    created: *mut i32,
) -> Status {
    *created = model.try_create(kinematics, step, state)? as i32;
    Ok(())
}

/// Whether `granbond_bond_try_create` could create a bond at `step` for a
/// pair whose state is `state` (`double[GRANBOND_BOND_STATE_LEN]`; only its
/// first slot, the rest length whose sign is the status, is read, not the
/// distance): 1 or 0. For engines that apply
/// the creation rules to every pair every step: where this says 0 they need
/// not gather the pair's kinematics for `granbond_bond_try_create`, which
/// would create nothing. 0 for a null or misaligned `model` or `state`.
///
/// # Safety
/// Pointers must be null or valid (`model` from `granbond_bond_model_new`).
// a query, not a call that fails: no error record
#[entry(or = 0, model: reference, state: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_may_create(
    model: *const BondModel,
    state: *const f64,
    step: i64,
) -> i32 {
    status_and_step_allow(&model.params, BondStatus::from_rest(*state), step) as i32
}

/// Whether any pair could be bonded at `step` (`granbond_bond_try_create`
/// creates bonds only at `create_step`, unless `create_always`): 1 or 0.
/// Where this says 0, `granbond_bond_may_create` says 0 for every state at
/// `step`, so an engine asks once per pass and skips the creation rules for
/// every pair. 0 for a null or misaligned `model`.
///
/// # Safety
/// `model` must be null or from `granbond_bond_model_new`.
// a query, not a call that fails: no error record
#[entry(or = 0, model: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_creates_at(model: *const BondModel, step: i64) -> i32 {
    model.creates_at(step) as i32
}

/// The line a run's opening output gives for `model`: which law it steps
/// (the write-up's, naming the switch for LIGGGHTS-INL's code, or that
/// code), in `naming`'s words (0 LAMMPS, 1 LIGGGHTS), written to `out`
/// (at most `capacity` bytes with the terminating NUL; a longer line is
/// cut).
///
/// # Safety
/// Pointers must be null or valid (`model` from `granbond_bond_model_new`,
/// `out` writable for `capacity` bytes).
#[entry(model: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_law_line(
    model: *const BondModel,
    naming: i32,
    out: *mut std::ffi::c_char,
    capacity: usize,
) -> Status {
    let naming = match naming {
        0 => Naming::Lammps,
        1 => Naming::Liggghts,
        _ => {
            return Err(Failure::new(
                Status::InvalidArgument,
                format!("naming must be 0 (LAMMPS) or 1 (LIGGGHTS); got {naming}"),
            ))
        }
    };
    if out.is_null() || capacity == 0 {
        return Err(Failure::new(
            Status::InvalidArgument,
            "out must be a buffer of at least one byte",
        ));
    }
    let switch = parameter_name("inl_compatible", naming);
    let line = model.law_line(switch);
    let n = line.len().min(capacity - 1);
    // SAFETY: the caller gives `capacity` writable bytes at `out`.
    unsafe {
        std::ptr::copy_nonoverlapping(line.as_ptr(), out as *mut u8, n);
        *out.add(n) = 0;
    }
    Ok(())
}

/// 1 if the contact's tangential and rolling loads act on an overlapping
/// pair while its bond is intact (LIGGGHTS-INL's code, `inl_compatible`),
/// so an engine drops only the contact's normal load under the bond; 0 if
/// the bond replaces every contact load. 0 for a null or misaligned `model`.
///
/// # Safety
/// `model` must be null or from `granbond_bond_model_new`.
// a query, not a call that fails: no error record
#[entry(or = 0, model: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_keeps_contact_tangential(model: *const BondModel) -> i32 {
    model.keeps_contact_tangential() as i32
}

/// 1 if every load of the contact acts on an overlapping pair while its
/// bond is intact, the bond's added to them (LIGGGHTS-INL's linear bond),
/// so an engine drops none of the contact's loads under the bond; 0
/// otherwise, and for a null or misaligned `model`.
///
/// # Safety
/// `model` must be null or from `granbond_bond_model_new`.
// a query, not a call that fails: no error record
#[entry(or = 0, model: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_keeps_contact_loads(model: *const BondModel) -> i32 {
    model.keeps_contact_loads() as i32
}

/// Leaves in `out`, the output of a contact step between the spheres of an
/// intact bond of `model`'s law, the loads that act under the bond: all of
/// them (LIGGGHTS-INL's linear bond), the tangential and rolling ones, the
/// normal force taken out (LIGGGHTS-INL's code), or none (the bond replaces
/// the contact). `del = x_i - x_j` (3 doubles) and `rsq = |del|^2` are the
/// separation the contact was stepped at. For an engine whose own loop
/// steps the contact under the bond.
///
/// # Safety
/// Pointers must be null or valid (`model` from `granbond_bond_model_new`,
/// `del` three doubles, `out` valid for reads and writes).
#[entry(model: reference, del: vector3, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_contact_loads_under_bond(
    model: *const BondModel,
    del: *const f64,
    rsq: f64,
    out: *mut ContactOutput,
) -> Status {
    if !separated(rsq) {
        return Err(KinematicsError::CoincidentCentres.into());
    }
    contact_loads_under_bond(model, del, rsq, out);
    Ok(())
}

/// The centre distance within which `granbond_bond_try_create` may create
/// a bond at `from_step` or any later step, written to `reach`:
/// `create_distance` while a creation step lies ahead (or bonds are created
/// every step), 0 after it. An engine that searches its neighbour list for
/// pairs to bond needs to search no farther (plus what atoms may move
/// before the list is built again).
///
/// # Safety
/// Pointers must be null or valid (`model` from `granbond_bond_model_new`).
#[entry(model: reference, reach: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_creation_reach(
    model: *const BondModel,
    from_step: i64,
    reach: *mut f64,
) -> Status {
    *reach = model.creation_reach(from_step);
    Ok(())
}

/// Creates the bond now, skipping the step rule (for bonds an engine forms
/// by its own rule, such as the spheres of a `bonded yes` clump): only if
/// the pair is not bonded and closer than `create_distance`.
///
/// # Safety
/// Pointers must be null or valid; `state` holds `GRANBOND_BOND_STATE_LEN` doubles.
#[entry(model: reference, kinematics: reference, state: bond_state, created: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_create_now(
    model: *const BondModel,
    kinematics: *const PairKinematics,
    state: *mut f64,
    created: *mut i32,
) -> Status {
    *created = model.create_now(kinematics, state)? as i32;
    Ok(())
}

/// Advances one bond by `dt`, updating `state` in place and writing the
/// loads, stresses and status to `out`. A bond that is not intact exerts
/// nothing; `out->break_mode` is non-zero in the one step a bond breaks.
///
/// # Safety
/// Pointers must be null or valid; `state` holds `GRANBOND_BOND_STATE_LEN` doubles.
#[entry(model: reference, kinematics: reference, state: bond_state, out: reference_mut, dt: time_step)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_compute(
    model: *const BondModel,
    kinematics: *const PairKinematics,
    dt: f64,
    state: *mut f64,
    out: *mut BondOutput,
) -> Status {
    model.step(kinematics, dt, state, out)?;
    results::bond(state, out)
}

/// The loads a run's setup pass applies for one bond where its law computes
/// them afresh (LIGGGHTS-INL's code, `inl_compatible`: a trial step that
/// moves only the history extremes and breaks nothing): written to `out`,
/// and `recomputed` set to 1. For a law that applies the loads of the
/// latest force pass, `recomputed` is 0 and nothing is written (the engine
/// applies the kept loads).
///
/// # Safety
/// Pointers must be null or valid; `state` holds `GRANBOND_BOND_STATE_LEN` doubles.
#[entry(
    model: reference,
    dt: time_step,
    kinematics: reference,
    state: bond_state,
    recomputed: reference_mut,
    out: reference_mut,
)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_setup_compute(
    model: *const BondModel,
    kinematics: *const PairKinematics,
    dt: f64,
    state: *mut f64,
    recomputed: *mut i32,
    out: *mut BondOutput,
) -> Status {
    let done = model.setup_step(kinematics, dt, state, out, false)?;
    *recomputed = done as i32;
    if done {
        results::bond(state, out)?;
    }
    Ok(())
}

/// The per-atom arrays of an engine (local and ghost atoms), as
/// `granbond_bond_compute_indexed` reads them: vectors as one block of 3
/// doubles per atom (LAMMPS/LIGGGHTS: `atom->x[0]`).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct AtomArrayPointers {
    /// Positions, 3 doubles per atom.
    pub x: *const f64,
    /// Velocities, 3 doubles per atom.
    pub v: *const f64,
    /// Angular velocities, 3 doubles per atom.
    pub omega: *const f64,
    /// Radii, one double per atom.
    pub radius: *const f64,
    /// The number of atoms each array holds at least.
    pub count: usize,
}

/// The engine's per-atom arrays as slices of `atoms->count` atoms.
///
/// # Safety
/// The pointers of `atoms` must be null or valid for that many atoms.
pub(super) unsafe fn atom_arrays<'a>(atoms: &AtomArrayPointers) -> Result<AtomArrays<'a>, Failure> {
    let n = atoms.count;
    // the arrays' sizes in bytes must fit an isize (slices)
    let n3 = n
        .checked_mul(3)
        .filter(|&m| m <= isize::MAX as usize / std::mem::size_of::<f64>())
        .ok_or_else(|| Failure::new(Status::InvalidArgument, format!("atoms->count {n} is too large")))?;
    Ok(AtomArrays {
        x: slice(atoms.x, n3, "atoms->x")?,
        v: slice(atoms.v, n3, "atoms->v")?,
        omega: slice(atoms.omega, n3, "atoms->omega")?,
        radius: slice(atoms.radius, n, "atoms->radius")?,
    })
}

/// `pairs` as bonds of `arrays`, each index checked; a bad one is
/// reported as bond `first + k` of the caller's.
pub(super) fn indexed_pairs<'a>(
    arrays: AtomArrays<'a>,
    pairs: &'a [[i32; 2]],
    first: usize,
    failed_index: FailedIndex,
) -> Result<IndexedPairs<'a>, Failure> {
    IndexedPairs::new(arrays, pairs).map_err(|e| {
        let bond = first + e.bond;
        failed_index.report(bond);
        Failure::new(
            Status::InvalidArgument,
            format!(
                "bond {bond}: atom index {} outside the {} atoms of the arrays",
                e.index, e.atoms
            ),
        )
    })
}

/// `granbond_bond_compute` over `count` bonds whose states lie apart in
/// memory, as in an engine's contact history, and whose kinematics are read from
/// the engine's per-atom arrays: bond `k` joins atoms `pairs[2k]` (`i`) and
/// `pairs[2k + 1]` (`j`), so the engine copies nothing per bond, and
/// `states[k]` points to the `GRANBOND_BOND_STATE_LEN` doubles of bond `k`
/// (no two the same). Results are those of one `granbond_bond_compute` per
/// bond, bit for bit; an engine collects the bonds of a pass and makes one
/// call, so the core can process several bonds per instruction. Stops at
/// the first bad input and writes its index to `failed_index` (if not
/// null). A misaligned `failed_index`, a null or misaligned `states[k]`
/// and an index outside `0 .. atoms->count` are reported (with its bond in
/// `failed_index`) before any bond is advanced.
///
/// # Safety
/// Pointers must be null or valid for the sizes above (`atoms->x`, `v`,
/// `omega`: `3 count` doubles; `radius`: `count`; `pairs`: `2 count` ints).
#[entry(failed_index: FailedIndex::new, atoms: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_compute_indexed(
    model: *const BondModel,
    count: usize,
    atoms: *const AtomArrayPointers,
    pairs: *const i32,
    dt: f64,
    states: *mut *mut f64,
    out: *mut BondOutput,
    failed_index: *mut usize,
) -> Status {
    let arrays = atom_arrays(atoms)?;
    let p = slice(pairs as *const [i32; 2], count, "pairs")?;
    let kinematics = indexed_pairs(arrays, p, 0, failed_index)?;
    let model = reference(model, "model")?;
    let pointers = slice(states as *const *mut f64, count, "states")?;
    for (index, &p) in pointers.iter().enumerate() {
        bond_state(p, "states[k]").map_err(|f| failed_index.fail("bond", index, f))?;
    }
    // Every pointer is non-null and aligned, and `&mut BondState` has the
    // layout of `*mut f64` to a `BondState` (the array of pointers is
    // read, never written). Through `slice_mut`: `states` may be null
    // when `count` is 0.
    let states = slice_mut(states as *mut &mut BondState, count, "states")?;
    let out = slice_mut(out, count, "out")?;
    let dt = time_step(dt, "dt")?;
    let stepped = model.step_indexed(&kinematics, dt, states, out);
    results::bonds(stepped, failed_index)
}

/// Bonds a sphere to a wall it touches at `contact_point` (`double[3]`)
/// under the pair rules; `state` holds `GRANBOND_WALL_BOND_STATE_LEN` doubles.
///
/// # Safety
/// Pointers must be null or valid for the sizes above.
#[entry(
    model: reference,
    sphere: reference,
    contact_point: vector3,
    state: wall_state,
    created: reference_mut,
)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_bond_try_create(
    model: *const BondModel,
    sphere: *const SphereKinematics,
    contact_point: *const f64,
    step: i64,
    state: *mut f64,
    created: *mut i32,
) -> Status {
    *created = model.try_create_wall(sphere, contact_point, step, state)? as i32;
    Ok(())
}

/// Advances a wall bond; the wall moves with `wall_velocity` (`double[3]`).
///
/// # Safety
/// Pointers must be null or valid; `state` holds `GRANBOND_WALL_BOND_STATE_LEN` doubles.
#[entry(
    model: reference,
    sphere: reference,
    wall_velocity: vector3,
    state: wall_state,
    out: reference_mut,
    dt: time_step,
)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_bond_compute(
    model: *const BondModel,
    sphere: *const SphereKinematics,
    wall_velocity: *const f64,
    dt: f64,
    state: *mut f64,
    out: *mut BondOutput,
) -> Status {
    model.step_wall(sphere, wall_velocity, dt, state, out)?;
    results::bond(&state.bond, out)?;
    results::vector("wall bond state", &state.partner)
}

/// `granbond_bond_setup_compute` for a wall bond: the wall's stand-in does
/// not move.
///
/// # Safety
/// Pointers must be null or valid; `state` holds `GRANBOND_WALL_BOND_STATE_LEN` doubles.
#[entry(
    model: reference,
    dt: time_step,
    sphere: reference,
    wall_velocity: vector3,
    state: wall_state,
    recomputed: reference_mut,
    out: reference_mut,
)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_bond_setup_compute(
    model: *const BondModel,
    sphere: *const SphereKinematics,
    wall_velocity: *const f64,
    dt: f64,
    state: *mut f64,
    recomputed: *mut i32,
    out: *mut BondOutput,
) -> Status {
    let kin = wall_kinematics(sphere, state.partner, wall_velocity);
    let done = model.setup_step(&kin, dt, &mut state.bond, out, true)?;
    *recomputed = done as i32;
    if done {
        results::bond(&state.bond, out)?;
    }
    Ok(())
}

/// Packs a bond step's output into the `GRANBOND_BOND_OUTPUT_LEN` doubles
/// at `slots`, for an engine that keeps it in the pair's history:
/// `force_i`, `torque_i + torque_j`, `torque_i - torque_j`, `sigma`, `tau`,
/// as `granbond_state_slot(GB_STATE_KIND_BOND_OUTPUT, ..)` names them. With
/// the engine's swap rule applied (the slots with `flips_on_swap` negated)
/// they are the output seen from the other sphere. An output with a
/// non-finite (or overflowing) load or stress is refused
/// (`GB_STATUS_NON_FINITE_INPUT`), `slots` left alone.
///
/// # Safety
/// `out` must be null or point to a `GbBondOutput`; `slots` null or valid
/// for `GRANBOND_BOND_OUTPUT_LEN` doubles.
#[entry(out: reference, slots: array_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_output_store(out: *const BondOutput, slots: *mut f64) -> Status {
    let stored = store_output(out);
    kept_finite(Status::NonFiniteInput, "a load or stress of `out`", &stored)?;
    *slots = stored;
    Ok(())
}

/// Unpacks the output `granbond_bond_output_store` packed into `slots`
/// (`GRANBOND_BOND_OUTPUT_LEN` doubles): `force_i`, `torque_i =
/// (sum + diff) / 2`, `torque_j = (sum - diff) / 2`, `sigma`, `tau`; the
/// status intact and no break mode; `normal_force` and `delta`, which the
/// slots do not keep, 0. Refused, `out` left alone: a non-finite slot
/// (`GB_STATUS_NON_FINITE_INPUT`), and slots whose torques overflow
/// (`GB_STATUS_NON_FINITE_RESULT`).
///
/// # Safety
/// `slots` must be null or point to `GRANBOND_BOND_OUTPUT_LEN` doubles;
/// `out` null or valid for writes.
#[entry(slots: array, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_output_load(slots: *const f64, out: *mut BondOutput) -> Status {
    let loaded = load_output(slots);
    let what = "a load or stress of `slots`";
    kept_finite(Status::NonFiniteInput, what, slots)?;
    let torques = "a torque from `slots` (the sum and difference overflow)";
    kept_finite(
        Status::NonFiniteResult,
        torques,
        [loaded.torque_i, loaded.torque_j].as_flattened(),
    )?;
    *out = loaded;
    Ok(())
}

/// Centre of a bond, for engines' logs of bonds: the point of the centre
/// line from `x_j` to `x_i` (`double[3]` each) that divides it in the
/// ratio `radius_i : radius_j`, `x_j + radius_j / (radius_i + radius_j)
/// (x_i - x_j)`, written to `centre` (`double[3]`). A wall bond passes the
/// wall point as `x_j` and `radius_j = 0`: the centre is that point.
/// Refused: non-finite positions (`GB_STATUS_NON_FINITE_INPUT`),
/// `radius_i <= 0`, `radius_j < 0` or not finite
/// (`GB_STATUS_INVALID_ARGUMENT`), each naming the argument, and positions
/// so far apart that the centre overflows (`GB_STATUS_NON_FINITE_RESULT`).
///
/// # Safety
/// Pointers must be null or valid for three doubles.
#[entry(
    x_i: finite_vector3,
    x_j: finite_vector3,
    radius_i: positive,
    radius_j: non_negative,
    centre: array_mut,
)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_centre(
    x_i: *const f64,
    x_j: *const f64,
    radius_i: f64,
    radius_j: f64,
    centre: *mut f64,
) -> Status {
    positive(radius_i + radius_j, "radius_i + radius_j")?;
    let c = bond_centre(x_i, x_j, radius_i, radius_j);
    kept_finite(
        Status::NonFiniteResult,
        "the centre of `x_i` and `x_j` (too far apart)",
        &c,
    )?;
    *centre = c;
    Ok(())
}

/// The numbers an output or position entry takes or gives: finite, else
/// refused as `status` (input or result) naming `what` (a NaN or infinity,
/// or a sum beyond 1e308).
fn kept_finite(status: Status, what: &str, values: &[f64]) -> Result<(), Failure> {
    if values.iter().sum::<f64>().is_finite() {
        return Ok(());
    }
    Err(Failure::new(
        status,
        format!("{what} is not finite or overflows: {values:?}"),
    ))
}

/// Largest centre distance an intact bond of rest length `r0` reaches
/// before it breaks (infinite if it never does): the neighbour-list range
/// the engine must keep.
///
/// # Safety
/// Pointers must be null or valid.
#[entry(model: reference, r0: positive, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_max_distance(
    model: *const BondModel,
    r0: f64,
    out: *mut f64,
) -> Status {
    *out = model.max_bond_distance(r0);
    Ok(())
}

/// Neighbour-list reach, as a multiple of `2 min_radius`, that keeps every
/// intact bond of this type in the engine's lists (infinite if a bond can
/// stretch without limit; the adapter must then refuse the setup).
///
/// # Safety
/// Pointers must be null or valid.
#[entry(model: reference, out: reference_mut, min_radius: positive)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_contact_distance_factor(
    model: *const BondModel,
    min_radius: f64,
    out: *mut f64,
) -> Status {
    *out = model.contact_distance_factor(min_radius);
    Ok(())
}

/// Critical time step of a bond of this type between spheres of the given
/// radii and masses (see the crate docs for the modes considered).
/// Infinite without stiffness; radii and masses whose estimate underflows
/// to zero or gives NaN are refused (`GB_STATUS_INVALID_ARGUMENT`).
///
/// # Safety
/// Pointers must be null or valid.
#[entry(model: reference, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_critical_timestep(
    model: *const BondModel,
    radius_i: f64,
    radius_j: f64,
    mass_i: f64,
    mass_j: f64,
    out: *mut f64,
) -> Status {
    *out = pair_estimate(
        model,
        [radius_i, radius_j, mass_i, mass_j],
        BondModel::critical_timestep,
    )?;
    Ok(())
}

/// Recommended time step of a bond of this type between spheres of the
/// given radii and masses: the core's safety fraction
/// (`RECOMMENDED_FRACTION`, chosen in docs/speed-accuracy.md) of `granbond_bond_critical_timestep`. Engines warn
/// above it.
///
/// # Safety
/// Pointers must be null or valid.
#[entry(model: reference, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_recommended_timestep(
    model: *const BondModel,
    radius_i: f64,
    radius_j: f64,
    mass_i: f64,
    mass_j: f64,
    out: *mut f64,
) -> Status {
    *out = pair_estimate(
        model,
        [radius_i, radius_j, mass_i, mass_j],
        BondModel::recommended_timestep,
    )?;
    Ok(())
}

/// Body of every per-pair estimate call (critical and recommended time
/// steps of bonds and contacts): checks the radii and masses
/// `[R_i, R_j, m_i, m_j]`, then evaluates `estimate`.
pub(crate) fn pair_estimate<M>(
    model: &M,
    bodies: [f64; 4],
    estimate: fn(&M, f64, f64, f64, f64) -> f64,
) -> Result<f64, Failure> {
    let [radius_i, radius_j, mass_i, mass_j] = bodies;
    check_bodies(radius_i, radius_j, mass_i, mass_j)?;
    let dt = estimate(model, radius_i, radius_j, mass_i, mass_j);
    // infinite is an answer (no stiffness: no limit); zero or NaN are
    // the underflow or overflow of radii and masses far outside any
    // physical range, not a limit
    if !(dt > 0.0) {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!(
                "radius_i {radius_i}, radius_j {radius_j}, mass_i {mass_i}, mass_j {mass_j}: outside the range the estimate can evaluate (it gives {dt})"
            ),
        ));
    }
    Ok(dt)
}

pub(crate) fn check_bodies(radius_i: f64, radius_j: f64, mass_i: f64, mass_j: f64) -> Result<(), Failure> {
    for (name, x) in [
        ("radius_i", radius_i),
        ("radius_j", radius_j),
        ("mass_i", mass_i),
        ("mass_j", mass_j),
    ] {
        positive(x, name)?;
    }
    Ok(())
}
