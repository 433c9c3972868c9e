//! ABI version and the layout check adapters run at start-up.

use super::entry;
use super::error::{Failure, Status};
use super::guard::reference;
use crate::bond::{BondOutput, BondParams, BOND_STATE_LEN, WALL_BOND_STATE_LEN};
use crate::bond_store::{BrokenBond, LinkReport, StoreCounts};
use crate::contact::{ContactFrame, ContactOutput, VoigtParams, CONTACT_STATE_LEN};
use crate::ffi::bond::{AtomArrayPointers, SphereKinematics};
use crate::ffi::checks::CheckReport;
use crate::ffi::contact::TangentialOutput;
use crate::ffi::store::StoreAtoms;
use crate::kinematics::PairKinematics;
use crate::timestep_check::TypeBodies;
use std::mem::size_of;

/// Bumped whenever a struct, a function or a meaning changes.
pub const GRANBOND_ABI_VERSION: u32 = 24;

/// The meaning of the state slots (`granbond_state_slot`): bumped whenever a
/// slot is added, removed or changes meaning, so that engines can refuse
/// restart files written with another layout instead of misreading them.
pub const GRANBOND_STATE_LAYOUT_VERSION: u32 = 4;

/// What the caller was compiled against: fill it with the header's version
/// and `sizeof` of each struct, and pass it to `granbond_check_layout`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Layout {
    /// `GRANBOND_ABI_VERSION` of the header the caller was compiled with.
    pub abi_version: u32,
    /// `sizeof(GbLayout)`: read before anything else, so a caller with a
    /// shorter or longer struct is refused without reading past its end.
    pub layout_size: usize,
    /// `sizeof(GbBondParams)`.
    pub bond_params: usize,
    /// `sizeof(GbVoigtParams)`.
    pub voigt_params: usize,
    /// `sizeof(GbPairKinematics)`.
    pub pair_kinematics: usize,
    /// `sizeof(GbSphereKinematics)`.
    pub sphere_kinematics: usize,
    /// `sizeof(GbBondOutput)`.
    pub bond_output: usize,
    /// `sizeof(GbAtomArrays)`.
    pub atom_arrays: usize,
    /// `sizeof(GbContactOutput)`.
    pub contact_output: usize,
    /// `sizeof(GbContactFrame)`.
    pub contact_frame: usize,
    /// `sizeof(GbTangentialOutput)`.
    pub tangential_output: usize,
    /// `sizeof(GbTypeBodies)`.
    pub type_bodies: usize,
    /// `sizeof(GbCheckReport)`.
    pub check_report: usize,
    /// `sizeof(GbStoreAtoms)`.
    pub store_atoms: usize,
    /// `sizeof(GbLinkReport)`.
    pub link_report: usize,
    /// `sizeof(GbStoreCounts)`.
    pub store_counts: usize,
    /// `sizeof(GbBrokenBond)`.
    pub broken_bond: usize,
    /// `GRANBOND_BOND_STATE_LEN`.
    pub bond_state_len: usize,
    /// `GRANBOND_WALL_BOND_STATE_LEN`.
    pub wall_bond_state_len: usize,
    /// `GRANBOND_CONTACT_STATE_LEN`.
    pub contact_state_len: usize,
}

/// The first two fields of every version of [`Layout`].
#[repr(C)]
struct LayoutHead {
    abi_version: u32,
    layout_size: usize,
}

/// The layout of this library.
pub fn library_layout() -> Layout {
    Layout {
        abi_version: GRANBOND_ABI_VERSION,
        layout_size: size_of::<Layout>(),
        bond_params: size_of::<BondParams>(),
        voigt_params: size_of::<VoigtParams>(),
        pair_kinematics: size_of::<PairKinematics>(),
        sphere_kinematics: size_of::<SphereKinematics>(),
        bond_output: size_of::<BondOutput>(),
        atom_arrays: size_of::<AtomArrayPointers>(),
        contact_output: size_of::<ContactOutput>(),
        contact_frame: size_of::<ContactFrame>(),
        tangential_output: size_of::<TangentialOutput>(),
        type_bodies: size_of::<TypeBodies>(),
        check_report: size_of::<CheckReport>(),
        store_atoms: size_of::<StoreAtoms>(),
        link_report: size_of::<LinkReport>(),
        store_counts: size_of::<StoreCounts>(),
        broken_bond: size_of::<BrokenBond>(),
        bond_state_len: BOND_STATE_LEN,
        wall_bond_state_len: WALL_BOND_STATE_LEN,
        contact_state_len: CONTACT_STATE_LEN,
    }
}

/// ABI version of the loaded library.
#[entry(or = 0)]
#[no_mangle]
pub extern "C" fn granbond_abi_version() -> u32 {
    GRANBOND_ABI_VERSION
}

/// Compares the caller's view of the ABI with the library's; on mismatch the
/// message names the first differing item.
///
/// # Safety
/// `expected` must be null or point to a `GbLayout`.
#[entry]
#[no_mangle]
pub unsafe extern "C" fn granbond_check_layout(expected: *const Layout) -> Status {
    let l = library_layout();
    let head = reference(expected as *const LayoutHead, "expected")?;
    if head.abi_version != l.abi_version || head.layout_size != l.layout_size {
        return Err(Failure::new(
            Status::LayoutMismatch,
            format!(
                "abi_version {} / sizeof(GbLayout) {} in the caller but {} / {} in the library: rebuild the adapter against this header",
                head.abi_version, head.layout_size, l.abi_version, l.layout_size
            ),
        ));
    }
    let e = reference(expected, "expected")?;
    let items: [(&str, usize, usize); 18] = [
        ("sizeof(GbBondParams)", e.bond_params, l.bond_params),
        ("sizeof(GbVoigtParams)", e.voigt_params, l.voigt_params),
        ("sizeof(GbPairKinematics)", e.pair_kinematics, l.pair_kinematics),
        (
            "sizeof(GbSphereKinematics)",
            e.sphere_kinematics,
            l.sphere_kinematics,
        ),
        ("sizeof(GbBondOutput)", e.bond_output, l.bond_output),
        ("sizeof(GbAtomArrays)", e.atom_arrays, l.atom_arrays),
        ("sizeof(GbContactOutput)", e.contact_output, l.contact_output),
        ("sizeof(GbContactFrame)", e.contact_frame, l.contact_frame),
        (
            "sizeof(GbTangentialOutput)",
            e.tangential_output,
            l.tangential_output,
        ),
        ("sizeof(GbTypeBodies)", e.type_bodies, l.type_bodies),
        ("sizeof(GbCheckReport)", e.check_report, l.check_report),
        ("sizeof(GbStoreAtoms)", e.store_atoms, l.store_atoms),
        ("sizeof(GbLinkReport)", e.link_report, l.link_report),
        ("sizeof(GbStoreCounts)", e.store_counts, l.store_counts),
        ("sizeof(GbBrokenBond)", e.broken_bond, l.broken_bond),
        ("bond state length", e.bond_state_len, l.bond_state_len),
        (
            "wall bond state length",
            e.wall_bond_state_len,
            l.wall_bond_state_len,
        ),
        ("contact state length", e.contact_state_len, l.contact_state_len),
    ];
    for (name, caller, library) in items {
        if caller != library {
            return Err(Failure::new(
                Status::LayoutMismatch,
                format!("{name} is {caller} in the caller but {library} in the library: rebuild the adapter against this header"),
            ));
        }
    }
    Ok(())
}
