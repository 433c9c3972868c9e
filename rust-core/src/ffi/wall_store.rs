//! `extern "C"` surface of the wall bonds' store
//! (`crate::bond_store::WallStore`): a rank's wall bonds, one per sphere and
//! wall, their per-atom events, the link and the visit of each contact.

use super::entry;
use super::error::{Failure, Status};
use super::guard::{reference, reference_mut, slice, slice_mut, time_step};
use super::results::refused;
use super::store::{ids, AtomIds};
use crate::bond::BondModel;
use crate::bond_store::{StoreCounts, WallContact, WallError, WallStore, WallVisit};

fn failure(e: WallError, what: &str) -> Failure {
    match e {
        WallError::Kinematics(k) => k.into(),
        WallError::NonFinite => refused("force, torque, stress or wall bond state"),
        other => Failure::new(Status::InvalidArgument, format!("{what}: {other}")),
    }
}

/// A new, empty store, written to `store`. Free it with
/// `granbond_wall_store_free`.
///
/// # Safety
/// `store` must be null or valid for writes.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_new(store: *mut *mut WallStore) -> Status {
    *store = Box::into_raw(Box::new(WallStore::new()));
    Ok(())
}

/// Frees a store from `granbond_wall_store_new` (null is ignored).
///
/// # Safety
/// `store` must come from `granbond_wall_store_new` and not be used again.
#[entry(or = ())]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_free(store: *mut WallStore) {
    if !store.is_null() {
        drop(Box::from_raw(store));
    }
}

/// The engine's per-atom arrays hold `nmax` atoms now (`grow_arrays`).
///
/// # Safety
/// `store` must be null or from `granbond_wall_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_grow(store: *mut WallStore, nmax: usize) -> Status {
    store.grow(nmax);
    Ok(())
}

/// Atom `from` was copied over atom `to` (`copy_arrays`).
///
/// # Safety
/// `store` must be null or from `granbond_wall_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_copy(store: *mut WallStore, from: usize, to: usize) -> Status {
    store.copy(from, to);
    Ok(())
}

/// Atom `i` was created (`set_arrays`): it holds no wall bond, whatever
/// id it is given.
///
/// # Safety
/// `store` must be null or from `granbond_wall_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_clear(store: *mut WallStore, i: usize) -> Status {
    store.clear(i);
    Ok(())
}

/// Doubles `granbond_wall_store_pack` writes for the sphere of id `id`; 0
/// for a null store.
///
/// # Safety
/// `store` must be null or from `granbond_wall_store_new`.
#[entry(or = 0, store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_packed_len(store: *const WallStore, id: i64) -> usize {
    store.packed_len(id)
}

/// The most doubles `granbond_wall_store_pack` writes for one sphere (a
/// bound for exchange and restart buffers); 0 for a null store.
///
/// # Safety
/// `store` must be null or from `granbond_wall_store_new`.
#[entry(or = 0, store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_most_packed_len(store: *const WallStore) -> usize {
    store.most_packed_len()
}

/// Packs the wall bonds of the sphere of id `id` (atom `i`) into `buf`
/// (`capacity` doubles), writing the doubles used to `written`. With
/// `leaving` non-zero (the sphere migrates) they leave this store;
/// otherwise (a restart file) they stay.
///
/// # Safety
/// Pointers must be null or valid; `buf` for `capacity` doubles.
#[entry(store: reference_mut, written: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_pack(
    store: *mut WallStore,
    i: usize,
    id: i64,
    leaving: i32,
    buf: *mut f64,
    capacity: usize,
    written: *mut usize,
) -> Status {
    let buf = slice_mut(buf, capacity, "buf")?;
    *written = store.pack(i, id, leaving != 0, buf).ok_or_else(|| {
        Failure::new(
            Status::InvalidArgument,
            format!(
                "buf: the wall bonds of sphere {id} need {} doubles, capacity is {capacity}",
                store.packed_len(id)
            ),
        )
    })?;
    Ok(())
}

/// The doubles one sphere's wall bonds packed by `granbond_wall_store_pack`
/// take, read from the head of `buf` (`head` doubles there, at least 2),
/// written to `len`.
///
/// # Safety
/// Pointers must be null or valid; `buf` for `head` doubles.
#[entry(len: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_packed_len_in(
    buf: *const f64,
    head: usize,
    len: *mut usize,
) -> Status {
    let buf = slice(buf, head, "buf")?;
    *len = WallStore::packed_len_in(buf).map_err(|e| failure(e, "buf"))?;
    Ok(())
}

/// Unpacks into atom `i`, the sphere of id `id`, the wall bonds
/// `granbond_wall_store_pack` wrote to `buf` (`len` doubles), reached at
/// step `step` (the current one); writes the doubles read to `read`.
///
/// # Safety
/// Pointers must be null or valid; `buf` for `len` doubles.
#[entry(store: reference_mut, read: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_unpack(
    store: *mut WallStore,
    i: usize,
    id: i64,
    step: i64,
    buf: *const f64,
    len: usize,
    read: *mut usize,
) -> Status {
    let buf = slice(buf, len, "buf")?;
    *read = store.unpack(i, id, step, buf).map_err(|e| failure(e, "buf"))?;
    Ok(())
}

/// Renumbers the walls (`map`, `len` entries): a bond on wall `w` moves to
/// wall `map[w]`, as when a restart deck lists the engine's walls in
/// another order. A bond on a wall without a place (`w` beyond `len`, or
/// `map[w]` negative), or two walls given one number, is refused with
/// nothing changed.
///
/// # Safety
/// Pointers must be null or valid; `map` for `len` entries.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_renumber(
    store: *mut WallStore,
    map: *const i64,
    len: usize,
) -> Status {
    let map = slice(map, len, "map")?;
    store.renumber(map).map_err(|e| failure(e, "map"))?;
    Ok(())
}

/// The wall bonds held, intact or broken; 0 for a null store.
///
/// # Safety
/// `store` must be null or from `granbond_wall_store_new`.
#[entry(or = 0, store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_len(store: *const WallStore) -> usize {
    store.len()
}

/// Finds each bond's sphere among the local atoms (`ids`, `ids->count` of
/// them) after atoms moved: a bond whose sphere left the system, or whose
/// id a new atom took over, leaves the store, counted lost with that cause.
///
/// # Safety
/// Pointers must be null or valid; the ids for `ids->count` atoms.
#[entry(store: reference_mut, ids: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_link(store: *mut WallStore, ids: *const AtomIds) -> Status {
    store.link(self::ids(ids)?);
    Ok(())
}

/// One contact of a sphere with a wall (`contact`), the store's answer in
/// `visit`: whether the bond of the sphere and the wall acts here (its
/// loads in `visit->out`), holds the sphere here (the contact's loads
/// replaced by nothing), or is absent or broke (its break mode in
/// `visit->out`), and whether it formed here.
///
/// # Safety
/// Pointers must be null or valid (`model` from `granbond_bond_model_new`).
#[entry(store: reference_mut, model: reference, contact: reference, visit: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_visit(
    store: *mut WallStore,
    model: *const BondModel,
    contact: *const WallContact,
    visit: *mut WallVisit,
) -> Status {
    time_step(contact.dt, "contact->dt")?;
    *visit = store.visit(model, contact).map_err(|e| failure(e, "contact"))?;
    Ok(())
}

/// The store's counts on this rank (created, broken by mode, lost by
/// cause: `lost_partner_unreached` counts the bonds whose sphere left the
/// wall's reach; intact), written to `counts`.
///
/// # Safety
/// Pointers must be null or valid.
#[entry(store: reference, counts: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_counts(
    store: *const WallStore,
    counts: *mut StoreCounts,
) -> Status {
    *counts = store.counts();
    Ok(())
}

/// Restores counts read from a restart file (`intact` is ignored: the
/// bonds held say it).
///
/// # Safety
/// Pointers must be null or valid.
#[entry(store: reference_mut, counts: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_restore_counts(
    store: *mut WallStore,
    counts: *const StoreCounts,
) -> Status {
    store.restore_counts(counts);
    Ok(())
}

/// Drops every bond and zeroes the counts: the wall is gone, and its
/// engine has taken the counts.
///
/// # Safety
/// `store` must be null or from `granbond_wall_store_new`.
#[entry(store: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_clear_all(store: *mut WallStore) -> Status {
    store.clear_all();
    Ok(())
}

/// The bytes the store holds on the heap; 0 for a null store.
///
/// # Safety
/// `store` must be null or from `granbond_wall_store_new`.
#[entry(or = 0, store: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_bytes(store: *const WallStore) -> usize {
    store.bytes()
}
