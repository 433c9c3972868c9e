//! `extern "C"` surface of the bond store (`crate::bond_store`): a rank's
//! bonds, their per-atom events, the link and the pass.

use super::bond::{atom_arrays, AtomArrayPointers};
use super::entry;
use super::error::{Failure, Status};
use super::guard::{reference, reference_mut, slice, slice_mut, time_step, FailedIndex};
use super::results::refused;
use crate::bond::{AtomLoads, BondModel, BondOutput, BOND_STATE_LEN};
use crate::bond_store::{
    creates_here, packed_len_in, BondStore, BrokenBond, EnergySums, Ids, LinkAtoms, LinkReport, ListedAtoms,
    ListedBond, SharesError, StepFailure, StepFailureReason, StoreCounts, CHUNK,
};
use crate::kinematics::PairKinematics;
use crate::pair_source::AtomArrays;

/// Bonds one `granbond_bond_store_step_next` steps at most: the length of
/// its `ends` and `outs` arrays.
pub const GRANBOND_BOND_STORE_CHUNK: usize = CHUNK;

/// A rank's atom ids as the engine keeps them: exactly one of `narrow`
/// (32-bit ids) and `wide` (64-bit) is set, for `count` atoms (local, then
/// ghost).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct AtomIds {
    /// 32-bit ids, or null.
    pub narrow: *const i32,
    /// 64-bit ids, or null.
    pub wide: *const i64,
    /// The number of atoms.
    pub count: usize,
}

/// What the link reads of a rank's atoms.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct StoreAtoms {
    /// The atoms' ids, local then ghost.
    pub ids: AtomIds,
    /// The number of local atoms.
    pub nlocal: usize,
    /// Positions, 3 doubles per atom (`ids.count` atoms).
    pub x: *const f64,
    /// Atom types, one per atom.
    pub types: *const i32,
    /// The farthest a bond's atoms may be apart and still be found (the
    /// ghost atoms' reach); not above 0: no limit.
    pub reach: f64,
}

pub(super) unsafe fn ids<'a>(ids: &AtomIds) -> Result<Ids<'a>, Failure> {
    match (ids.narrow.is_null(), ids.wide.is_null()) {
        (false, true) => Ok(Ids::Narrow(slice(ids.narrow, ids.count, "ids->narrow")?)),
        (true, false) => Ok(Ids::Wide(slice(ids.wide, ids.count, "ids->wide")?)),
        _ => Err(Failure::new(
            Status::InvalidArgument,
            "ids: exactly one of ids->narrow and ids->wide must be set",
        )),
    }
}

/// The models by kind as the store reads them, without a copy: a null
/// entry is a kind without a model.
///
/// # Safety
/// `models` must be null or valid for `nkinds` pointers, each null or a
/// model from `granbond_bond_model_new`.
unsafe fn model_table<'a>(
    models: *const *const BondModel,
    nkinds: usize,
) -> Result<&'a [Option<&'a BondModel>], Failure> {
    let models = slice(models, nkinds, "models")?;
    // SAFETY: `Option<&T>` has the layout of a nullable `*const T`, and
    // each non-null entry is a model (the caller's contract).
    Ok(std::slice::from_raw_parts(
        models.as_ptr() as *const Option<&BondModel>,
        models.len(),
    ))
}

/// A new, empty store, written to `store`. Free it with
/// `granbond_bond_store_free`.
///
/// # Safety
/// `store` must be null or valid for writes.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_new(store: *mut *mut BondStore) -> Status {
    *store = Box::into_raw(Box::new(BondStore::new()));
    Ok(())
}

/// Frees a store from `granbond_bond_store_new` (null is ignored).
///
/// # Safety
/// `store` must come from `granbond_bond_store_new` and not be used again.
#[entry(or = ())]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_free(store: *mut BondStore) {
    if !store.is_null() {
        drop(Box::from_raw(store));
    }
}

/// Rows for atoms `0..nmax` at least. The store's rows follow the atoms it
/// is told of (links, unpacked atoms, seen ids), so an engine need not call
/// it when its per-atom arrays grow.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_grow(store: *mut BondStore, nmax: usize) -> Status {
    store.grow(nmax);
    Ok(())
}

/// Atom `from` was copied over atom `to` (`copy_arrays`): `to` owns
/// `from`'s bonds now; those `to` owned are lost at the next link.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_copy(store: *mut BondStore, from: usize, to: usize) -> Status {
    store.copy(from, to);
    Ok(())
}

/// Atom `i` was created (`set_arrays`): it owns no bond, and no link has
/// seen it.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_clear(store: *mut BondStore, i: usize) -> Status {
    store.clear(i);
    Ok(())
}

/// Atom `i`'s id as the latest link saw it (0: never), for its ghost images
/// (border communication); 0 for a null store.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(or = 0, store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_seen(store: *const BondStore, i: usize) -> i64 {
    store.seen(i)
}

/// Sets the seen id of ghost atom `i`, as its owner rank sent it.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_set_seen(store: *mut BondStore, i: usize, id: i64) -> Status {
    store.set_seen(i, id);
    Ok(())
}

/// Doubles `granbond_bond_store_pack` writes for atom `i`; 0 for a null
/// store.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(or = 0, store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_packed_len(store: *const BondStore, i: usize) -> usize {
    store.packed_len(i)
}

/// The most doubles `granbond_bond_store_pack` writes for one local atom
/// (a bound for exchange and restart buffers); 0 for a null store.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(or = 0, store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_most_packed_len(store: *const BondStore) -> usize {
    store.most_packed_len()
}

/// Packs atom `i`'s bonds into `buf` (`capacity` doubles), writing the
/// doubles used to `written`. With `leaving` non-zero (the atom migrates)
/// the bonds leave this store; otherwise (a restart file) they stay.
///
/// # Safety
/// Pointers must be null or valid; `buf` for `capacity` doubles.
#[entry(store: reference_mut, written: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_pack(
    store: *mut BondStore,
    i: usize,
    leaving: i32,
    buf: *mut f64,
    capacity: usize,
    written: *mut usize,
) -> Status {
    let buf = slice_mut(buf, capacity, "buf")?;
    *written = store.pack(i, leaving != 0, buf).ok_or_else(|| {
        Failure::new(
            Status::InvalidArgument,
            format!(
                "buf: atom {i}'s bonds need {} doubles, capacity is {capacity}",
                store.packed_len(i)
            ),
        )
    })?;
    Ok(())
}

/// Unpacks into atom `i` the bonds `granbond_bond_store_pack` wrote to
/// `buf` (`len` doubles), writing the doubles read to `read`.
///
/// # Safety
/// Pointers must be null or valid; `buf` for `len` doubles.
#[entry(store: reference_mut, read: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_unpack(
    store: *mut BondStore,
    i: usize,
    buf: *const f64,
    len: usize,
    read: *mut usize,
) -> Status {
    let buf = slice(buf, len, "buf")?;
    *read = store
        .unpack(i, buf)
        .map_err(|e| Failure::new(Status::InvalidArgument, format!("buf: {e}")))?;
    Ok(())
}

/// The doubles one atom's bonds packed by `granbond_bond_store_pack` take,
/// read from the head of `buf` (`head` doubles there: at least 2, and 3
/// where the second is negative), written to `len`: where the next atom
/// starts in an engine's buffer of several.
///
/// # Safety
/// Pointers must be null or valid; `buf` for `head` doubles.
#[entry(len: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_packed_len_in(
    buf: *const f64,
    head: usize,
    len: *mut usize,
) -> Status {
    let buf = slice(buf, head.min(3), "buf")?;
    *len = packed_len_in(buf).map_err(|e| Failure::new(Status::InvalidArgument, format!("buf: {e}")))?;
    Ok(())
}

/// Finds every bond's atoms again after a neighbour-list build (see
/// `crate::bond_store`'s link): owners among the local atoms, partners as
/// their images closest to the owners. `kinds[ti * (ntypes + 1) + tj]` is
/// the bond kind of a pair of types, negative where it has no bond model.
/// Bonds whose atoms are not found are dropped and counted by cause in
/// `report`.
///
/// # Safety
/// Pointers must be null or valid; `kinds` for `(ntypes + 1)^2` ints, the
/// arrays of `atoms` for `atoms->ids.count` atoms.
#[entry(store: reference_mut, atoms: reference, report: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_link(
    store: *mut BondStore,
    atoms: *const StoreAtoms,
    kinds: *const i32,
    ntypes: usize,
    report: *mut LinkReport,
) -> Status {
    let n = atoms.ids.count;
    let nt1 = ntypes
        .checked_add(1)
        .and_then(|t| t.checked_mul(ntypes + 1))
        .ok_or_else(|| Failure::new(Status::InvalidArgument, format!("ntypes {ntypes} is too large")))?;
    let view = LinkAtoms {
        ids: ids(&atoms.ids)?,
        nlocal: atoms.nlocal,
        x: slice(atoms.x, n.saturating_mul(3), "atoms->x")?,
        types: slice(atoms.types, n, "atoms->types")?,
        kinds: slice(kinds, nt1, "kinds")?,
        ntypes,
        reach: atoms.reach,
    };
    *report = store
        .link(&view)
        .map_err(|e| Failure::new(Status::InvalidArgument, e.0))?;
    Ok(())
}

/// Links a store whose bonds the engine's topology names (`bond_style
/// granbond`): the store holds exactly the `nlisted` bonds of `listed`
/// after it (owner local, partner the topology's image, kind the bond
/// type), keeping the state of those it held, creating the others at rest
/// at their present length, and counting in `report` those it held that
/// the list does not name (lost). `ids` and `x` (3 doubles an atom) hold
/// the local atoms first, `nlocal` of them, then the ghosts.
///
/// # Safety
/// Pointers must be null or valid: `listed` for `nlisted` bonds, `x` for
/// `3 * ids->count` doubles.
#[allow(clippy::too_many_arguments)]
#[entry(store: reference_mut, ids: reference, report: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_link_listed(
    store: *mut BondStore,
    ids: *const AtomIds,
    nlocal: usize,
    x: *const f64,
    listed: *const ListedBond,
    nlisted: usize,
    report: *mut LinkReport,
) -> Status {
    let n = ids.count;
    let atoms = ListedAtoms {
        ids: self::ids(ids)?,
        nlocal,
        x: slice(x, n.saturating_mul(3), "x")?,
    };
    let listed = slice(listed, nlisted, "listed")?;
    *report = store
        .link_listed(&atoms, listed)
        .map_err(|e| Failure::new(Status::InvalidArgument, format!("listed: {}", e.0)))?;
    Ok(())
}

/// Starts a pass: a force pass over `dt` (`advance` non-zero) or a setup
/// pass. With `remember_breaks` non-zero, pairs whose bonds break are kept
/// from bonding again at a later creation step.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(store: reference_mut, dt: time_step)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_begin_pass(
    store: *mut BondStore,
    dt: f64,
    advance: i32,
    remember_breaks: i32,
) -> Status {
    store.begin_pass(dt, advance != 0, remember_breaks != 0);
    Ok(())
}

/// The engine's per-atom sums a pass adds the bonds' loads to
/// (`granbond_bond_store_step_rest`, `granbond_bond_store_step_next`): for
/// each bond in turn the owner's force and torque, then the partner's.
/// No array may overlap another, nor the atoms' arrays.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct AtomLoadPointers {
    /// Forces, 3 doubles per atom (local, then ghost).
    pub force: *mut f64,
    /// Torques, 3 doubles per atom.
    pub torque: *mut f64,
    /// The number of atoms both arrays hold at least (at least the atoms'
    /// arrays' count).
    pub count: usize,
    /// The number of local atoms: a partner at or beyond it is a ghost.
    pub nlocal: usize,
    /// Null, or 6 doubles per ghost atom (force, then torque; ghost `j` at
    /// row `j - nlocal`, `count - nlocal` rows): where a ghost partner's
    /// loads go instead of its own rows, for an engine that does not sum
    /// ghosts' loads to their owners (`newton off`).
    pub ghost_rows: *mut f64,
    /// Null (every factor 1), or each atom's factor on the loads it
    /// receives (LIGGGHTS's relaxation factor), `count` doubles.
    pub relax: *const f64,
}

/// The sums of `loads` as slices, none overlapping another or the atoms'
/// arrays `atoms`.
///
/// # Safety
/// The pointers of `loads` must be null or valid for the lengths it gives.
unsafe fn atom_loads<'a>(loads: &AtomLoadPointers, atoms: &AtomArrays<'_>) -> Result<AtomLoads<'a>, Failure> {
    let n = loads.count;
    let too_large = || Failure::new(Status::InvalidArgument, format!("loads->count {n} is too large"));
    let n3 = n
        .checked_mul(3)
        .filter(|&m| m <= isize::MAX as usize / (2 * std::mem::size_of::<f64>()))
        .ok_or_else(too_large)?;
    if loads.nlocal > n {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!("loads->nlocal {} exceeds loads->count {n}", loads.nlocal),
        ));
    }
    let ghosts = 6 * (n - loads.nlocal);
    let force = slice_mut(loads.force, n3, "loads->force")?;
    let torque = slice_mut(loads.torque, n3, "loads->torque")?;
    let ghost_rows = match loads.ghost_rows.is_null() {
        true => None,
        false => Some(slice_mut(loads.ghost_rows, ghosts, "loads->ghost_rows")?),
    };
    let relax = match loads.relax.is_null() {
        true => None,
        false => Some(slice(loads.relax, n, "loads->relax")?),
    };
    let written = [
        ("loads->force", force.as_ptr_range()),
        ("loads->torque", torque.as_ptr_range()),
        (
            "loads->ghost_rows",
            ghost_rows.as_deref().unwrap_or(&[]).as_ptr_range(),
        ),
    ];
    let read = [
        ("loads->relax", relax.unwrap_or(&[]).as_ptr_range()),
        ("atoms->x", atoms.x.as_ptr_range()),
        ("atoms->v", atoms.v.as_ptr_range()),
        ("atoms->omega", atoms.omega.as_ptr_range()),
        ("atoms->radius", atoms.radius.as_ptr_range()),
    ];
    for (k, (name, range)) in written.iter().enumerate() {
        let others = written[k + 1..].iter().chain(&read);
        if let Some((other, _)) = others
            .into_iter()
            .find(|(_, o)| range.start < o.end && o.start < range.end)
        {
            return Err(Failure::new(
                Status::InvalidArgument,
                format!("{name} overlaps {other}"),
            ));
        }
    }
    Ok(AtomLoads {
        force,
        torque,
        nlocal: loads.nlocal,
        ghost_rows,
        relax,
    })
}

/// A failure of a step of the store's bonds as a message naming the bond's
/// atoms and the parameter at fault.
fn step_failure(f: StepFailure, failed_index: FailedIndex) -> Failure {
    let [i, j] = f.ends;
    let failure = match f.reason {
        StepFailureReason::NotLinked => Failure::new(
            Status::InvalidArgument,
            "the store was not linked since atoms moved (granbond_bond_store_link)",
        ),
        StepFailureReason::NoModel(kind) => Failure::new(
            Status::InvalidArgument,
            format!("models: no model for bond kind {kind}"),
        ),
        StepFailureReason::IndexOutOfRange => {
            Failure::new(Status::InvalidArgument, "an atom index beyond the atoms' arrays")
        }
        StepFailureReason::Kinematics(e) => e.into(),
        StepFailureReason::NonFinite => refused("force, torque, stress or bond state"),
        StepFailureReason::LoadsTooShort(what) => {
            return Failure::new(
                Status::InvalidArgument,
                format!("loads->{what}: holds fewer atoms than atoms->count"),
            )
        }
    };
    let failure = Failure {
        message: format!("the bond of local atoms {i} and {j}: {}", failure.message),
        ..failure
    };
    failed_index.fail("bond", f.bond, failure)
}

/// Steps the next chunk of the pass: up to `GRANBOND_BOND_STORE_CHUNK`
/// bonds of one kind (`models[kind]`, null where a kind has no model), their
/// atoms' local indices written to `ends` (2 ints a bond) and outputs to
/// `outs`, the number to `count` (0: the pass has stepped every bond), and
/// their loads added to `loads` unless it is null (then the caller adds
/// them from `outs`). A bond that breaks carries no load;
/// `granbond_bond_store_broken` reports it. On failure nothing of the
/// chunk is kept, and `failed_index` (if not null) gets the bond's place in
/// the store.
///
/// # Safety
/// Pointers must be null or valid: `models` for `nkinds` entries, `ends` for
/// `2 * GRANBOND_BOND_STORE_CHUNK` ints, `outs` for
/// `GRANBOND_BOND_STORE_CHUNK` outputs, the atoms' and loads' arrays as they
/// say.
#[allow(clippy::too_many_arguments)]
#[entry(failed_index: FailedIndex::new, store: reference_mut, atoms: reference, ids: reference, count: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_step_next(
    store: *mut BondStore,
    models: *const *const BondModel,
    nkinds: usize,
    atoms: *const AtomArrayPointers,
    ids: *const AtomIds,
    loads: *const AtomLoadPointers,
    ends: *mut i32,
    outs: *mut BondOutput,
    count: *mut usize,
    failed_index: *mut usize,
) -> Status {
    *count = 0;
    let models = model_table(models, nkinds)?;
    let arrays = atom_arrays(atoms)?;
    let ids = self::ids(ids)?;
    let mut loads = match loads.is_null() {
        true => None,
        false => Some(atom_loads(reference(loads, "loads")?, &arrays)?),
    };
    let ends = &mut *(slice_mut(ends, 2 * CHUNK, "ends")?.as_mut_ptr() as *mut [[i32; 2]; CHUNK]);
    let outs = &mut *(slice_mut(outs, CHUNK, "outs")?.as_mut_ptr() as *mut [BondOutput; CHUNK]);
    *count = match &mut loads {
        Some(loads) => store.step_next_adding(models, arrays, ids, loads, ends, outs),
        None => store.step_next(models, arrays, ids, ends, outs),
    }
    .map_err(|f| step_failure(f, failed_index))?;
    Ok(())
}

/// Steps every bond of the pass not stepped yet (`models[kind]` for each,
/// null where a kind has no model) and adds their loads to `loads`, as
/// `granbond_bond_store_step_next` would chunk by chunk, but without
/// handing back outputs: for a pass that wants none (no virial, no
/// per-bond output). The number stepped goes to `count`. A bond that breaks
/// carries no load; `granbond_bond_store_broken` reports it. On failure,
/// `failed_index` (if not null) gets the bond's place in the store.
///
/// # Safety
/// Pointers must be null or valid: `models` for `nkinds` entries, the
/// atoms' and loads' arrays as they say.
#[allow(clippy::too_many_arguments)]
#[entry(failed_index: FailedIndex::new, store: reference_mut, atoms: reference, ids: reference, loads: reference, count: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_step_rest(
    store: *mut BondStore,
    models: *const *const BondModel,
    nkinds: usize,
    atoms: *const AtomArrayPointers,
    ids: *const AtomIds,
    loads: *const AtomLoadPointers,
    count: *mut usize,
    failed_index: *mut usize,
) -> Status {
    *count = 0;
    let models = model_table(models, nkinds)?;
    let arrays = atom_arrays(atoms)?;
    let ids = self::ids(ids)?;
    let mut loads = atom_loads(loads, &arrays)?;
    *count = store
        .step_rest(models, arrays, ids, &mut loads)
        .map_err(|f| step_failure(f, failed_index))?;
    Ok(())
}

/// The number of bonds broken so far in the pass; 0 for a null store.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(or = 0, store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_broken_count(store: *const BondStore) -> usize {
    store.broken().len()
}

/// Bond `k` of those broken so far in the pass, written to `bond`.
///
/// # Safety
/// Pointers must be null or valid.
#[entry(store: reference, bond: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_broken(
    store: *const BondStore,
    k: usize,
    bond: *mut BrokenBond,
) -> Status {
    *bond = *store.broken().get(k).ok_or_else(|| {
        Failure::new(
            Status::InvalidArgument,
            format!(
                "k: {k} beyond the {} bonds broken in the pass",
                store.broken().len()
            ),
        )
    })?;
    Ok(())
}

/// Creates a bond of kind `kind` between local atom `owner` (id
/// `owner_id`) and atom `partner` (local or ghost, id `partner_id`) if
/// `model`'s creation rules allow it at `step` for the pair's kinematics
/// (`i` the owner); `created` says whether it did. For pairs the engine
/// knows unbonded and created on this rank (`granbond_bond_store_creates_here`).
///
/// # Safety
/// Pointers must be null or valid.
#[allow(clippy::too_many_arguments)]
#[entry(store: reference_mut, model: reference, kinematics: reference, created: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_try_create(
    store: *mut BondStore,
    model: *const BondModel,
    kind: u16,
    owner: usize,
    partner: usize,
    owner_id: i64,
    partner_id: i64,
    kinematics: *const PairKinematics,
    step: i64,
    created: *mut i32,
) -> Status {
    *created = 0;
    *created = store.try_create(
        model,
        kind,
        owner,
        partner,
        [owner_id, partner_id],
        kinematics,
        step,
    )? as i32;
    Ok(())
}

/// As `granbond_bond_store_try_create`, whatever the step: creates the
/// bond if the pair is closer than `model`'s creation distance (LIGGGHTS
/// `bonded yes` clumps in their first force pass).
///
/// # Safety
/// Pointers must be null or valid.
#[allow(clippy::too_many_arguments)]
#[entry(store: reference_mut, model: reference, kinematics: reference, created: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_create_now(
    store: *mut BondStore,
    model: *const BondModel,
    kind: u16,
    owner: usize,
    partner: usize,
    owner_id: i64,
    partner_id: i64,
    kinematics: *const PairKinematics,
    created: *mut i32,
) -> Status {
    *created = 0;
    *created = store.create_now(model, kind, owner, partner, [owner_id, partner_id], kinematics)? as i32;
    Ok(())
}

/// Ends the pass: the bonds broken in it leave the store.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_finish_pass(store: *mut BondStore) -> Status {
    store.finish_pass();
    Ok(())
}

/// Which atom of a pair found to bond owns the bond on this rank: 0 atom
/// `i`, 1 atom `j`, -1 if another rank creates it. Local atoms own bonds,
/// the smaller id where both are local; a pair listed on two ranks
/// (`newton off`, one atom a ghost) is created where the smaller id is
/// local.
#[entry(or = -1)]
#[no_mangle]
pub extern "C" fn granbond_bond_store_creates_here(
    i_local: i32,
    j_local: i32,
    id_i: i64,
    id_j: i64,
    listed_on_both: i32,
) -> i32 {
    match creates_here(i_local != 0, j_local != 0, id_i, id_j, listed_on_both != 0) {
        Some(false) => 0,
        Some(true) => 1,
        None => -1,
    }
}

/// The store's counts on this rank (created, broken by mode, lost by
/// cause, intact), written to `counts`.
///
/// # Safety
/// Pointers must be null or valid.
#[entry(store: reference, counts: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_counts(
    store: *const BondStore,
    counts: *mut StoreCounts,
) -> Status {
    *counts = store.counts();
    Ok(())
}

/// Restores counts read from a restart file (`intact` is ignored: the
/// store holds its bonds).
///
/// # Safety
/// Pointers must be null or valid.
#[entry(store: reference_mut, counts: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_restore_counts(
    store: *mut BondStore,
    counts: *const StoreCounts,
) -> Status {
    store.restore_counts(counts);
    Ok(())
}

/// The bonds the store holds; 0 for a null store.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(or = 0, store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_len(store: *const BondStore) -> usize {
    store.len()
}

/// The bytes the store holds on the heap; 0 for a null store.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(or = 0, store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_bytes(store: *const BondStore) -> usize {
    store.bytes()
}

/// Bond `k` as of the latest link: its atoms' local indices (owner first)
/// to `ends` (2 ints), the partner's id to `partner_id`, its state to
/// `state` (`GRANBOND_BOND_STATE_LEN` doubles).
///
/// # Safety
/// Pointers must be null or valid for those sizes.
#[entry(store: reference, partner_id: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_bond(
    store: *const BondStore,
    k: usize,
    ends: *mut i32,
    partner_id: *mut i64,
    state: *mut f64,
) -> Status {
    let ends = slice_mut(ends, 2, "ends")?;
    let state = slice_mut(state, BOND_STATE_LEN, "state")?;
    let (bond, e) = store.bond(k).ok_or_else(|| {
        Failure::new(
            Status::InvalidArgument,
            format!(
                "k: {k} beyond the {} bonds held, or the store is not linked",
                store.len()
            ),
        )
    })?;
    ends.copy_from_slice(&e);
    *partner_id = bond.partner;
    state.copy_from_slice(bond.state.as_slots());
    Ok(())
}

/// Doubles one atom's view row takes on this rank (the count and the most
/// partner ids one local atom owns); a forward communication sends rows of
/// the largest width over all ranks. 0 for a null store.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(or = 0, store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_view_width(store: *const BondStore) -> usize {
    store.view_width()
}

/// Packs local atom `i`'s view row (the count and the partner ids of the
/// bonds it owns) into `row` (`width` doubles), for its ghost images.
///
/// # Safety
/// Pointers must be null or valid; `row` for `width` doubles.
#[entry(store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_pack_view(
    store: *const BondStore,
    i: usize,
    row: *mut f64,
    width: usize,
) -> Status {
    let row = slice_mut(row, width, "row")?;
    store
        .pack_view(i, row)
        .map_err(|e| Failure::new(Status::InvalidArgument, format!("width: {}", e.0)))
}

/// Starts the view over, before the ghosts' rows are unpacked.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_clear_view(store: *mut BondStore) -> Status {
    store.clear_view();
    Ok(())
}

/// Unpacks ghost atom `g`'s view row (`width` doubles, as its owner rank
/// packed it): its bonds to local atoms join the view. `ids` and `nlocal`
/// are the rank's atoms as the latest link saw them.
///
/// # Safety
/// Pointers must be null or valid; `row` for `width` doubles.
#[entry(store: reference_mut, ids: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_unpack_view(
    store: *mut BondStore,
    g: usize,
    row: *const f64,
    width: usize,
    ids: *const AtomIds,
    nlocal: usize,
) -> Status {
    let row = slice(row, width, "row")?;
    let ids = self::ids(ids)?;
    store
        .unpack_view(g, row, ids, nlocal)
        .map_err(|e| Failure::new(Status::InvalidArgument, format!("row: {}", e.0)))
}

/// Ends the view after the ghosts' rows: it can be asked now.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_finish_view(store: *mut BondStore) -> Status {
    store.finish_view();
    Ok(())
}

/// Whether local atom `i` and atom `j` (local or ghost) are bonded as far
/// as this rank knows (its own bonds and the view): 1 or 0; 0 for null
/// arguments.
///
/// # Safety
/// Pointers must be null or valid.
#[entry(or = 0, store: reference, ids: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_bonded(
    store: *const BondStore,
    i: usize,
    j: usize,
    ids: *const AtomIds,
) -> i32 {
    match self::ids(ids) {
        Ok(ids) => store.bonded(i, j, ids) as i32,
        Err(_) => 0,
    }
}

/// For a rank that lists a pair another rank bonds (`newton off`): whether
/// that rank creates the bond between local atom `local` and ghost atom
/// `ghost` in this pass, by `model`'s creation rules for `kinematics`
/// (`i` the local atom) at `step`, and unless the pair's bond broke in this
/// pass. Written to `creates` (1 or 0).
///
/// # Safety
/// Pointers must be null or valid.
#[entry(store: reference, model: reference, kinematics: reference, creates: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_would_create(
    store: *const BondStore,
    model: *const BondModel,
    local: usize,
    ghost: usize,
    kinematics: *const PairKinematics,
    step: i64,
    creates: *mut i32,
) -> Status {
    *creates = 0;
    *creates = store.would_create(model, local, ghost, kinematics, step)? as i32;
    Ok(())
}

/// The bonds of each local atom, wherever they are stored (owned here,
/// partner here, or owned on another rank as the view says), each bond
/// once per atom, written to `counts` (`nlocal` entries, the local atoms of
/// the latest link).
///
/// # Safety
/// Pointers must be null or valid; `counts` for `nlocal` entries.
#[entry(store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_count_atoms(
    store: *const BondStore,
    counts: *mut u32,
    nlocal: usize,
    ids: *const AtomIds,
) -> Status {
    let counts = slice_mut(counts, nlocal, "counts")?;
    let ids = self::ids(reference(ids, "ids")?)?;
    store.count_atoms(counts, ids);
    Ok(())
}

/// The energy the bonds of this rank store now (J), each with its kind's
/// model (`models[kind]`, null where a kind has none) at its atoms'
/// positions, written to `energy`: what the engine adds to its potential
/// energy.
///
/// # Safety
/// Pointers must be null or valid: `models` for `nkinds` entries, the
/// atoms' arrays as they say.
#[entry(store: reference, atoms: reference, energy: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_stored_energy(
    store: *const BondStore,
    models: *const *const BondModel,
    nkinds: usize,
    atoms: *const AtomArrayPointers,
    energy: *mut f64,
) -> Status {
    let models = model_table(models, nkinds)?;
    let arrays = atom_arrays(atoms)?;
    *energy = store.stored_energy(models, arrays).ok_or_else(|| {
        Failure::new(
            Status::InvalidArgument,
            "the store was not linked since atoms moved, or a bond's atom lies beyond the atoms' arrays",
        )
    })?;
    Ok(())
}

/// Keeps the bonds' energy budget (`on` non-zero) or stops keeping it: the
/// energy the damping and the hysteresis dissipate and breaks release,
/// summed in every force pass (`granbond_bond_store_energy_sums`); with
/// `per_bond` non-zero, each bond's dissipated energies too
/// (`granbond_bond_store_bond_energy`). While kept, a bond costs
/// `BUDGET_BYTES_PER_BOND` more (`DISSIPATED_BYTES_PER_BOND` more again
/// with `per_bond`) and a pass steps each damped bond twice; turned off,
/// nothing. The same on every rank.
///
/// # Safety
/// `store` must be null or from `granbond_bond_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_keep_energy_budget(
    store: *mut BondStore,
    on: i32,
    per_bond: i32,
) -> Status {
    store.keep_energy_budget(on != 0, per_bond != 0);
    Ok(())
}

/// The energy this rank's bonds dissipated by damping and by hysteresis and
/// released by breaking since the budget was first kept (J), written to
/// `sums`; zero while it never was.
///
/// # Safety
/// Pointers must be null or valid.
#[entry(store: reference, sums: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_energy_sums(
    store: *const BondStore,
    sums: *mut EnergySums,
) -> Status {
    *sums = store.energy_sums();
    Ok(())
}

/// Restores energy sums read from a restart file.
///
/// # Safety
/// Pointers must be null or valid.
#[entry(store: reference_mut, sums: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_restore_energy_sums(
    store: *mut BondStore,
    sums: *const EnergySums,
) -> Status {
    store.restore_energy_sums(sums);
    Ok(())
}

/// Adds each intact bond's shares of its damping loads of the latest force
/// pass to a per-atom table, as LIGGGHTS-INL's `computeDissipatedEnergy`
/// files them (minus the damping force, then minus the damping torque, on
/// each of the bond's atoms; `crate::bond::dissipated_shares`): `table`
/// holds `rows` atoms (the engine's local atoms, in its order) of `width`
/// doubles, the 6 doubles of a share from column `column`. Bonds of a kind
/// without a model (`models[kind]` null) or whose law files none add
/// nothing. Needs the energy budget kept (`granbond_bond_store_keep_energy_budget`),
/// which holds the loads, and the store linked.
///
/// # Safety
/// Pointers must be null or valid: `models` for `nkinds` entries, `table`
/// for `rows * width` doubles.
#[entry(store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_add_dissipated_shares(
    store: *const BondStore,
    models: *const *const BondModel,
    nkinds: usize,
    table: *mut f64,
    rows: usize,
    width: usize,
    column: usize,
) -> Status {
    let models = model_table(models, nkinds)?;
    let len = rows
        .checked_mul(width)
        .ok_or_else(|| Failure::new(Status::InvalidArgument, "rows, width: their product overflows"))?;
    let table = slice_mut(table, len, "table")?;
    store
        .add_dissipated_shares(models, table, width, column, rows)
        .map_err(|e| {
            Failure::new(
                Status::InvalidArgument,
                match e {
                    SharesError::NotKept => {
                        "store: the energy budget, which holds the damping loads, is not kept"
                    }
                    SharesError::NotLinked => "store: not linked since atoms moved",
                    SharesError::Width => {
                        "column, width: a share of 6 doubles from column does not fit width"
                    }
                },
            )
        })
}

/// Bond `k`'s energies as of the latest link (J), written to `energy`
/// (`granbond_bond_energy_field_count()` doubles, the energy fields'
/// order): what it stores now, with its kind's model (`models[kind]`) at
/// its atoms' positions, and what it dissipated by damping and by
/// hysteresis since the store kept them (`granbond_bond_store_keep_energy_budget`
/// with `per_bond`; refused while not kept).
///
/// # Safety
/// Pointers must be null or valid: `models` for `nkinds` entries, the
/// atoms' arrays as they say, `energy` for 3 doubles.
#[entry(store: reference, atoms: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_bond_energy(
    store: *const BondStore,
    models: *const *const BondModel,
    nkinds: usize,
    atoms: *const AtomArrayPointers,
    k: usize,
    energy: *mut f64,
) -> Status {
    let models = model_table(models, nkinds)?;
    let arrays = atom_arrays(atoms)?;
    let energy = slice_mut(energy, 3, "energy")?;
    let dissipated = store.dissipated(k).ok_or_else(|| {
        Failure::new(
            Status::InvalidArgument,
            format!(
                "k: bond {k} of {}, or the bonds' dissipated energies are not kept",
                store.len()
            ),
        )
    })?;
    let stored = store.bond_stored_energy(k, models, arrays).ok_or_else(|| {
        Failure::new(
            Status::InvalidArgument,
            format!("k: bond {k} has no model, the store is not linked, or its atoms lie beyond the atoms' arrays"),
        )
    })?;
    energy.copy_from_slice(&[stored, dissipated[0], dissipated[1]]);
    Ok(())
}
