//! Turns arbitrary bytes into a sequence of calls of the C ABI and checks
//! every answer. Shared by the fuzz target (`fuzz/fuzz_targets/abi.rs`) and
//! the corpus replay in the normal suite (`tests/fuzz_corpus.rs`), so a
//! corpus file means the same calls in both.
//!
//! What an answer must be:
//! - never `GB_STATUS_PANIC`, and no panic escaping an `extern "C"` function
//!   (that aborts, which the fuzzer reports as a crash);
//! - after a checked call: OK with a clear error record, or an error code
//!   with a message that starts with the function's name and a parameter id
//!   exactly for `GB_STATUS_INVALID_PARAMETER`;
//! - after OK: outputs in their documented ranges (status and break-mode
//!   values, 0/1 flags, the length queries, positive time steps, frames
//!   with a unit normal); never a non-finite number computed from finite
//!   input (docs/fuzzing.md);
//! - the `*_unchecked` entries: OK or `GB_STATUS_NON_FINITE_INPUT`.
//!
//! The driver keeps to the callers' side of every `# Safety` contract (a
//! pointer is null, misaligned or valid for its documented size; counts
//! never exceed the buffers; no two scattered states alias; models are
//! never used after free): what the ABI cannot check is not fuzzed.
//! Everything it can check is: parameter structs, states (of any model,
//! also another model's or a written-over one), kinematics, frames,
//! planes, layouts, counts, indices, ids and kinds.
#![allow(dead_code)]

use granbond::bond::fields::{BOND_ENERGY_FIELDS, BOND_ENERGY_FIELD_COUNT, BOND_FIELDS, BOND_FIELD_COUNT};
use granbond::bond::output_slots::{store_output, BOND_OUTPUT_LEN};
use granbond::bond::{
    BondModel, BondOutput, BondParams, BondState, BOND_STATE_LEN, PARAMETERS, WALL_BOND_STATE_LEN,
};
use granbond::bond_store::{
    BrokenBond, EnergySums, LinkReport, ListedBond, StoreCounts, WallContact, WallVisit,
};
use granbond::contact::{
    ContactFrame, ContactOutput, Plane, VoigtModel, VoigtParams, CONTACT_STATE_LEN, VOIGT_PARAMETERS,
};
use granbond::ffi::abi::{self, library_layout, Layout};
use granbond::ffi::bond::{self as fb, AtomArrayPointers};
use granbond::ffi::checks::{self as fk, CheckReport};
use granbond::ffi::contact::{self as fc, TangentialOutput};
use granbond::ffi::contact_geometry as fcg;
use granbond::ffi::deck::{self as fd, PhraseRow};
use granbond::ffi::error::{granbond_last_error_message, granbond_last_error_parameter};
use granbond::ffi::fields::{
    granbond_bond_energy_field_count, granbond_bond_energy_field_info, granbond_bond_field_count,
    granbond_bond_field_info, granbond_bond_fields, granbond_bond_stress_limits,
};
use granbond::ffi::layout::{granbond_state_len, granbond_state_slot};
use granbond::ffi::ledger as fl;
use granbond::ffi::parameters::{self as fp, ParameterRow};
use granbond::ffi::store::{self as fs, AtomIds, AtomLoadPointers, StoreAtoms, GRANBOND_BOND_STORE_CHUNK};
use granbond::ffi::wall_store as fw;
use granbond::ffi::Status;
use granbond::kinematics::{PairKinematics, SphereKinematics};
use granbond::ledger::break_log::BreakEvent;
use granbond::timestep_check::TypeBodies;
use std::collections::BTreeMap;
use std::ffi::{c_char, CStr};
use std::marker::PhantomData;
use std::mem::{align_of, size_of};
use std::ptr::{null, null_mut};

/// Every `extern "C"` function of `include/granbond.h` (the header's
/// `static inline` helper is compiled into the caller, not the library).
pub const ENTRY_POINTS: [&str; 158] = [
    "granbond_abi_version",
    "granbond_check_layout",
    "granbond_bond_params_default",
    "granbond_bond_params_default_in_units",
    "granbond_bond_params_contact_under_bond_by_law",
    "granbond_bond_model_new",
    "granbond_bond_model_free",
    "granbond_bond_parameter_count",
    "granbond_bond_try_create",
    "granbond_bond_may_create",
    "granbond_bond_creates_at",
    "granbond_bond_creation_reach",
    "granbond_bond_create_now",
    "granbond_bond_compute",
    "granbond_bond_compute_indexed",
    "granbond_wall_bond_try_create",
    "granbond_wall_bond_compute",
    "granbond_bond_setup_compute",
    "granbond_wall_bond_setup_compute",
    "granbond_bond_keeps_contact_tangential",
    "granbond_bond_keeps_contact_loads",
    "granbond_bond_contact_loads_under_bond",
    "granbond_bond_parameter_liggghts_name",
    "granbond_bond_law_line",
    "granbond_bond_output_store",
    "granbond_bond_output_load",
    "granbond_bond_centre",
    "granbond_bond_max_distance",
    "granbond_bond_contact_distance_factor",
    "granbond_bond_neighbour_reach",
    "granbond_bond_critical_timestep",
    "granbond_bond_recommended_timestep",
    "granbond_bond_timestep_check",
    "granbond_voigt_timestep_check",
    "granbond_bond_creation_check",
    "granbond_voigt_params_default",
    "granbond_voigt_model_new",
    "granbond_voigt_model_free",
    "granbond_voigt_compute",
    "granbond_voigt_compute_separation_unchecked",
    "granbond_voigt_compute_normal_unchecked",
    "granbond_contact_frame_separation",
    "granbond_contact_frame_normal",
    "granbond_voigt_normal_force",
    "granbond_voigt_tangential",
    "granbond_voigt_rolling",
    "granbond_voigt_evaluate_frame",
    "granbond_voigt_tangential_evaluate",
    "granbond_voigt_rolling_evaluate",
    "granbond_voigt_critical_timestep",
    "granbond_voigt_parameter_count",
    "granbond_bond_parameter_info",
    "granbond_voigt_parameter_info",
    "granbond_bond_params_set",
    "granbond_bond_params_get",
    "granbond_voigt_params_get",
    "granbond_voigt_params_set",
    "granbond_bond_parameter_needed",
    "granbond_bond_parameter_sets_creation",
    "granbond_voigt_parameter_needed",
    "granbond_bond_phrase_info",
    "granbond_voigt_phrase_info",
    "granbond_voigt_parameter_part",
    "granbond_voigt_sub_model",
    "granbond_pair_coeff_read",
    "granbond_bond_coeff_read",
    "granbond_bond_params_rows",
    "granbond_liggghts_property_line_check",
    "granbond_liggghts_settings_check",
    "granbond_voigt_params_rows",
    "granbond_bond_params_from_rows",
    "granbond_voigt_params_from_rows",
    "granbond_last_error_message",
    "granbond_last_error_parameter",
    "granbond_state_len",
    "granbond_state_slot",
    "granbond_bond_field_count",
    "granbond_bond_field_info",
    "granbond_bond_energy_field_count",
    "granbond_bond_energy_field_info",
    "granbond_bond_fields",
    "granbond_bond_stress_limits",
    "granbond_store_counts_row",
    "granbond_ledger_notice",
    "granbond_break_event",
    "granbond_break_log_text",
    "granbond_break_log_words",
    "granbond_bond_columns_new",
    "granbond_bond_columns_free",
    "granbond_bond_columns_info",
    "granbond_bond_columns_row",
    "granbond_thin_periodic_box_check",
    "granbond_store_check_findings",
    "granbond_bond_store_check_keys",
    "granbond_bond_store_check_flag",
    "granbond_wall_store_check_keys",
    "granbond_store_record_write",
    "granbond_store_record_read",
    "granbond_bond_store_new",
    "granbond_bond_store_free",
    "granbond_bond_store_grow",
    "granbond_bond_store_copy",
    "granbond_bond_store_clear",
    "granbond_bond_store_seen",
    "granbond_bond_store_set_seen",
    "granbond_bond_store_packed_len",
    "granbond_bond_store_most_packed_len",
    "granbond_bond_store_pack",
    "granbond_bond_store_unpack",
    "granbond_bond_store_link",
    "granbond_bond_store_link_listed",
    "granbond_bond_store_begin_pass",
    "granbond_bond_store_step_next",
    "granbond_bond_store_step_rest",
    "granbond_bond_store_broken_count",
    "granbond_bond_store_broken",
    "granbond_bond_store_try_create",
    "granbond_bond_store_create_now",
    "granbond_bond_store_finish_pass",
    "granbond_bond_store_creates_here",
    "granbond_bond_store_counts",
    "granbond_bond_store_restore_counts",
    "granbond_bond_store_len",
    "granbond_bond_store_bytes",
    "granbond_bond_store_bond",
    "granbond_bond_store_view_width",
    "granbond_bond_store_pack_view",
    "granbond_bond_store_clear_view",
    "granbond_bond_store_unpack_view",
    "granbond_bond_store_finish_view",
    "granbond_bond_store_bonded",
    "granbond_bond_store_would_create",
    "granbond_bond_store_count_atoms",
    "granbond_bond_store_stored_energy",
    "granbond_bond_store_keep_energy_budget",
    "granbond_bond_store_energy_sums",
    "granbond_bond_store_restore_energy_sums",
    "granbond_bond_store_bond_energy",
    "granbond_bond_store_add_dissipated_shares",
    "granbond_bond_store_packed_len_in",
    "granbond_wall_store_new",
    "granbond_wall_store_free",
    "granbond_wall_store_grow",
    "granbond_wall_store_copy",
    "granbond_wall_store_clear",
    "granbond_wall_store_packed_len",
    "granbond_wall_store_most_packed_len",
    "granbond_wall_store_pack",
    "granbond_wall_store_packed_len_in",
    "granbond_wall_store_unpack",
    "granbond_wall_store_link",
    "granbond_wall_store_renumber",
    "granbond_wall_store_len",
    "granbond_wall_store_visit",
    "granbond_wall_store_counts",
    "granbond_wall_store_restore_counts",
    "granbond_wall_store_clear_all",
    "granbond_wall_store_bytes",
];

/// The set-by-name and need entries of one parameter table.
struct TableEntries<T: 'static> {
    model: &'static str,
    table: &'static [granbond::parameters::ParameterInfo<T>],
    set_name: &'static str,
    set: unsafe extern "C" fn(*mut T, *const c_char, f64) -> Status,
    get_name: &'static str,
    get: unsafe extern "C" fn(*const T, usize, *mut f64) -> Status,
    needed_name: &'static str,
    needed: unsafe extern "C" fn(*const T, usize, *mut i32) -> Status,
}

const BOND_TABLE: TableEntries<BondParams> = TableEntries {
    model: "bond/nonlinear",
    table: PARAMETERS,
    set_name: "granbond_bond_params_set",
    set: fp::granbond_bond_params_set,
    get_name: "granbond_bond_params_get",
    get: fp::granbond_bond_params_get,
    needed_name: "granbond_bond_parameter_needed",
    needed: fp::granbond_bond_parameter_needed,
};

const VOIGT_TABLE: TableEntries<VoigtParams> = TableEntries {
    model: "voigt",
    table: VOIGT_PARAMETERS,
    set_name: "granbond_voigt_params_set",
    set: fp::granbond_voigt_params_set,
    get_name: "granbond_voigt_params_get",
    get: fp::granbond_voigt_params_get,
    needed_name: "granbond_voigt_parameter_needed",
    needed: fp::granbond_voigt_parameter_needed,
};

/// Entries that return no `GbStatus`: their answers are counted as OK when
/// they are in range (a wrong one fails an assertion).
const NOT_STATUS: i32 = 0;

/// Status values, in `GbStatus` order, for the summary.
pub const STATUS_NAMES: [&str; STATUSES] = [
    "OK",
    "NULL_POINTER",
    "INVALID_PARAMETER",
    "NON_FINITE_INPUT",
    "COINCIDENT_CENTRES",
    "NON_POSITIVE_RADIUS",
    "LAYOUT_MISMATCH",
    "INVALID_ARGUMENT",
    "PANIC",
    "MISALIGNED",
    "NON_FINITE_RESULT",
];

/// How many `GbStatus` values there are.
pub const STATUSES: usize = 11;

/// How often each entry answered with each status.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    pub answers: BTreeMap<&'static str, [u64; STATUSES]>,
    pub inputs: u64,
}

impl Tally {
    fn count(&mut self, function: &'static str, code: i32) {
        self.answers.entry(function).or_default()[code as usize] += 1;
    }

    pub fn merge(&mut self, other: &Tally) {
        self.inputs += other.inputs;
        for (f, counts) in &other.answers {
            let mine = self.answers.entry(f).or_default();
            for (m, c) in mine.iter_mut().zip(counts) {
                *m += c;
            }
        }
    }

    /// Total answers per status over all entries.
    pub fn by_status(&self) -> [u64; STATUSES] {
        let mut total = [0; STATUSES];
        for counts in self.answers.values() {
            for (t, c) in total.iter_mut().zip(counts) {
                *t += c;
            }
        }
        total
    }
}

impl std::fmt::Display for Tally {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "{} inputs; answers per entry point and status:", self.inputs)?;
        for (function, counts) in &self.answers {
            let seen: Vec<String> = counts
                .iter()
                .zip(STATUS_NAMES)
                .filter(|(c, _)| **c > 0)
                .map(|(c, name)| format!("{name} {c}"))
                .collect();
            writeln!(f, "  {function}: {}", seen.join(", "))?;
        }
        let total = self.by_status();
        let seen: Vec<String> = total
            .iter()
            .zip(STATUS_NAMES)
            .map(|(c, name)| format!("{name} {c}"))
            .collect();
        write!(f, "  all entries: {}", seen.join(", "))
    }
}

/// The fuzzer's bytes, read front to back; past the end every byte is 0.
pub struct Input<'a> {
    data: &'a [u8],
    pos: usize,
}

/// Numbers where code tends to break: NaN, infinities, signed zeros,
/// subnormals, the extremes of the range, and the scales of the models.
const SPECIAL: [f64; 32] = [
    f64::NAN,
    -f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    0.0,
    -0.0,
    f64::MIN_POSITIVE,
    5e-324,
    -5e-324,
    1e-300,
    -1e-300,
    1e300,
    -1e300,
    f64::MAX,
    f64::MIN,
    f64::EPSILON,
    1.0,
    -1.0,
    0.5,
    2.0,
    1e-3,
    -1e-3,
    2e-3,
    1.1e-3,
    2.2e-3,
    1e-6,
    1e-7,
    1e-160,
    1e154,
    1e9,
    1e13,
    -1e-7,
];

impl<'a> Input<'a> {
    pub fn new(data: &'a [u8]) -> Self {
        Self { data, pos: 0 }
    }

    fn done(&self) -> bool {
        self.pos >= self.data.len()
    }

    fn byte(&mut self) -> u8 {
        let b = self.data.get(self.pos).copied().unwrap_or(0);
        self.pos += 1;
        b
    }

    fn below(&mut self, n: usize) -> usize {
        self.byte() as usize % n
    }

    fn u64(&mut self) -> u64 {
        (0..8).fold(0, |acc, _| (acc << 8) | self.byte() as u64)
    }

    /// Any double, biased towards [`SPECIAL`] and the models' scales.
    fn f64(&mut self) -> f64 {
        let tag = self.byte() as usize;
        match tag {
            t if t < SPECIAL.len() => SPECIAL[t],
            // lengths around a millimetre sphere: -5e-3 ..= 5e-3
            t if t < 128 => (t as f64 - 80.0) * 1e-4,
            // velocities: -1.6 ..= 1.55
            t if t < 192 => (t as f64 - 160.0) * 0.05,
            // magnitudes 1e-16 ..= 1e15
            t if t < 224 => 10f64.powi(t as i32 - 208),
            _ => f64::from_bits(self.u64()),
        }
    }

    /// An `i32` for switches, kinds and indices: mostly small.
    fn i32(&mut self) -> i32 {
        match self.byte() {
            b if b < 240 => (b % 8) as i32 - 2,
            240..=243 => i32::MIN,
            244..=247 => i32::MAX,
            _ => self.u64() as i32,
        }
    }

    /// A count or id: mostly small, sometimes huge.
    fn usize(&mut self) -> usize {
        match self.byte() {
            b if b < 248 => (b % 24) as usize,
            248 | 249 => usize::MAX,
            250 | 251 => usize::MAX / 8,
            _ => self.u64() as usize,
        }
    }

    fn step(&mut self) -> i64 {
        match self.byte() {
            b if b < 240 => (b % 12) as i64 - 2,
            240..=243 => i64::MIN,
            244..=247 => i64::MAX,
            _ => self.u64() as i64,
        }
    }

    fn vec3(&mut self) -> [f64; 3] {
        [self.f64(), self.f64(), self.f64()]
    }

    fn pointer(&mut self) -> Pointer {
        match self.byte() % 16 {
            0 => Pointer::Null,
            1 => Pointer::Misaligned,
            _ => Pointer::Valid,
        }
    }

    /// A pointer argument drawn after the older ones of its operation: a
    /// zero byte, as past the end of the input, passes it valid, so inputs
    /// made before it was drawn still get past its check.
    fn late_pointer(&mut self) -> Pointer {
        match self.byte() % 16 {
            1 => Pointer::Null,
            2 => Pointer::Misaligned,
            _ => Pointer::Valid,
        }
    }

    /// Overwrites a few 8-byte words of `value` with fuzzed bits: a double,
    /// or two small `i32` (the switches and counts of the structs).
    fn mutate<T: Copy>(&mut self, value: &mut T) {
        let words = size_of::<T>() / 8;
        for _ in 0..self.below(5) {
            let w = self.below(words);
            let bits = if self.byte().is_multiple_of(3) {
                let (a, b) = (self.i32() as u32 as u64, self.i32() as u32 as u64);
                a | (b << 32)
            } else {
                self.f64().to_bits()
            };
            // SAFETY: every struct fuzzed here is plain data (f64, integers,
            // padding): any bits are a valid value.
            unsafe { (value as *mut T as *mut u64).add(w).write_unaligned(bits) };
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Pointer {
    Null,
    Misaligned,
    Valid,
}

/// Storage for one `T` with a word of room behind it, so a misaligned
/// pointer (one byte in) still lies inside the allocation.
struct Place<T> {
    words: Vec<u64>,
    _t: PhantomData<T>,
}

impl<T: Copy> Place<T> {
    fn new(value: T) -> Self {
        assert!(align_of::<T>() <= 8);
        let mut words = vec![0u64; size_of::<T>().div_ceil(8) + 1];
        // SAFETY: the words are 8-aligned and hold at least size_of::<T>() bytes.
        unsafe { (words.as_mut_ptr() as *mut T).write(value) };
        Self {
            words,
            _t: PhantomData,
        }
    }

    fn get(&self) -> T {
        // SAFETY: written by `new` (or by the ABI through a valid pointer).
        unsafe { (self.words.as_ptr() as *const T).read() }
    }

    fn ptr(&mut self, how: Pointer) -> *mut T {
        match how {
            Pointer::Null => null_mut(),
            Pointer::Misaligned => (self.words.as_mut_ptr() as *mut u8).wrapping_add(1) as *mut T,
            Pointer::Valid => self.words.as_mut_ptr() as *mut T,
        }
    }
}

const fn max(a: usize, b: usize) -> usize {
    if a > b {
        a
    } else {
        b
    }
}

/// Slots of the largest state of a model.
const MAX_STATE: usize = max(max(BOND_STATE_LEN, WALL_BOND_STATE_LEN), CONTACT_STATE_LEN);
/// A pool entry holds the largest state, and one slot more (a misaligned
/// pointer stays inside): every entry can be handed to any model.
const ENTRY: usize = MAX_STATE + 1;
type Entry = [f64; ENTRY];
const POOL: usize = 8;
const MAX_BATCH: usize = 8;
const MAX_ATOMS: usize = 8;

/// A bond parameter set that makes forces: a hysteretic fixture in
/// distance mode (`stress` off) or stress mode with finite strengths.
fn bond_params(stress: bool) -> BondParams {
    BondParams {
        lambda: 0.5,
        k_fn1: 2e9,
        ku_fn1: 4e9,
        kc_fn1: 1e8,
        k_fn2: 1e10,
        ku_fn2: 1e10,
        kc_fn2: 1e9,
        k_ft: 5e9,
        k_tn: 1e9,
        ku_tn: 2e9,
        kc_tn: 1e8,
        k_tt: 1e9,
        ku_tt: 2e9,
        kc_tt: 1e8,
        eta_fn: 0.1,
        eta_ft: 0.1,
        eta_tn: 0.1,
        eta_tt: 0.1,
        max_distance: 2.2e-3,
        max_sigma: if stress { 1e5 } else { f64::INFINITY },
        max_tau: if stress { 1e5 } else { f64::INFINITY },
        create_distance: 2.1e-3,
        stress_break: stress as i32,
        use_ratio: stress as i32,
        tension_compression_ratio: 0.5,
        compression_linear_below: if stress { 1e-7 } else { 0.0 },
        damping_smooth: stress as i32,
        ..BondParams::default()
    }
}

/// Two millimetre spheres about a diameter apart, moving slowly.
fn realistic_pair(input: &mut Input) -> PairKinematics {
    let gap = (input.byte() as f64 - 128.0) * 2e-6;
    PairKinematics {
        x_i: [2e-3 + gap, 1e-5 * input.below(3) as f64, 0.0],
        x_j: [0.0; 3],
        v_i: [(input.byte() as f64 - 128.0) * 1e-3, 0.0, 0.0],
        v_j: [0.0, (input.byte() as f64 - 128.0) * 1e-3, 0.0],
        w_i: [0.0, 0.0, (input.byte() as f64 - 128.0) * 0.1],
        w_j: [(input.byte() as f64 - 128.0) * 0.1, 0.0, 0.0],
        radius_i: 1e-3,
        radius_j: 1e-3 * (1.0 + input.below(3) as f64 * 0.25),
    }
}

/// What `Session::indexed_bonds` draws: the engine's arrays and index of
/// bonds, the pool entries of the bonds' states, and how the
/// pointer arguments are passed (atoms, pairs, states, out, failed_index).
struct IndexedBonds {
    model: *const BondModel,
    count: usize,
    /// What `atoms` points into.
    _arrays: [Vec<f64>; 4],
    atoms: Place<AtomArrayPointers>,
    /// `2 count` indices and one more, so a misaligned pointer stays inside.
    pairs: Vec<i32>,
    dt: f64,
    entries: Vec<usize>,
    states: Vec<*mut f64>,
    how: [Pointer; 5],
}

impl IndexedBonds {
    /// Whether the arrays of `atoms` pass the ABI's checks.
    fn arrays_pass(&self) -> bool {
        let a = self.atoms.get();
        a.count == 0
            || [a.x, a.v, a.omega, a.radius]
                .iter()
                .all(|p| !p.is_null() && (*p as usize).is_multiple_of(align_of::<f64>()))
    }

    /// The first bond with an atom index outside `atoms->count`.
    fn first_bad_pair(&self) -> Option<usize> {
        let atoms = self.atoms.get().count;
        (0..self.count).find(|&k| {
            self.pairs[2 * k..2 * k + 2]
                .iter()
                .any(|&i| usize::try_from(i).map_or(true, |i| i >= atoms))
        })
    }
}

fn bits(values: &[f64]) -> Vec<u64> {
    values.iter().map(|x| x.to_bits()).collect()
}

fn same_pool(a: &[Entry], b: &[Entry]) -> bool {
    a.iter().zip(b).all(|(x, y)| bits(x) == bits(y))
}

fn bond_output_bits(o: &BondOutput) -> (Vec<u64>, i32, i32) {
    (bits(&bond_output_numbers(o)), o.status, o.break_mode)
}

fn message() -> String {
    let p = granbond_last_error_message();
    assert!(!p.is_null(), "granbond_last_error_message returned NULL");
    // SAFETY: the library returns a NUL-terminated string it owns.
    unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned()
}

fn all_finite(values: &[f64]) -> bool {
    values.iter().all(|x| x.is_finite())
}

fn bond_output_numbers(o: &BondOutput) -> Vec<f64> {
    let mut v: Vec<f64> = o
        .force_i
        .iter()
        .chain(&o.torque_i)
        .chain(&o.torque_j)
        .copied()
        .collect();
    v.extend([o.normal_force, o.sigma, o.tau, o.delta]);
    v
}

fn contact_output_numbers(o: &ContactOutput) -> Vec<f64> {
    let mut v: Vec<f64> = o
        .force_i
        .iter()
        .chain(&o.torque_i)
        .chain(&o.torque_j)
        .copied()
        .collect();
    v.extend([o.normal_force, o.overlap]);
    v
}

/// The calls one input makes, with the models and states they share.
struct Session<'t> {
    tally: &'t mut Tally,
    bond_models: Vec<*mut BondModel>,
    voigt_models: Vec<*mut VoigtModel>,
    /// States of every kind, in one pool: any entry may be handed to any
    /// model, so a state written by one model is read by another.
    pool: Vec<Entry>,
    pair: PairKinematics,
    frame: ContactFrame,
}

impl Drop for Session<'_> {
    fn drop(&mut self) {
        for &m in &self.bond_models {
            // SAFETY: from granbond_bond_model_new, freed once.
            unsafe { fb::granbond_bond_model_free(m) };
        }
        for &m in &self.voigt_models {
            // SAFETY: from granbond_voigt_model_new, freed once.
            unsafe { fc::granbond_voigt_model_free(m) };
        }
    }
}

impl<'t> Session<'t> {
    fn new(tally: &'t mut Tally) -> Self {
        let mut s = Self {
            tally,
            bond_models: Vec::new(),
            voigt_models: Vec::new(),
            pool: vec![[0.0; ENTRY]; POOL],
            pair: realistic_pair(&mut Input::new(&[])),
            frame: ContactFrame {
                n: [1.0, 0.0, 0.0],
                overlap: 1e-6,
                lever_i: 1e-3,
                lever_j: 1e-3,
                r_eff: 5e-4,
                v_i: [0.0, 1e-2, 0.0],
                w_j: [0.0, 0.0, 1.0],
                ..ContactFrame::default()
            },
        };
        // one working model of each kind from the start, so short inputs
        // reach past the model checks
        s.new_bond_model(bond_params(false));
        s.new_voigt_model(VoigtParams::default());
        s
    }

    /// Checks a checked call's answer (see the module docs) and counts it.
    fn answer(&mut self, function: &'static str, status: Status) -> bool {
        let code = status as i32;
        let text = message();
        let parameter = granbond_last_error_parameter();
        self.tally.count(function, code);
        assert!(status != Status::Panic, "{function} panicked: {text}");
        if status == Status::Ok {
            assert!(
                text.is_empty() && parameter == -1,
                "{function} succeeded but left an error record: \"{text}\", parameter {parameter}"
            );
            return true;
        }
        assert!(
            text.starts_with(function) && text.len() > function.len() + 2,
            "{function} answered {status:?} with the message \"{text}\""
        );
        if status == Status::InvalidParameter {
            assert!(
                parameter >= 0,
                "{function}: InvalidParameter without a parameter id"
            );
        } else {
            assert_eq!(
                parameter, -1,
                "{function}: {status:?} with parameter id {parameter}"
            );
        }
        false
    }

    /// The answer of an `*_unchecked` entry.
    fn answer_unchecked(&mut self, function: &'static str, status: Status) -> bool {
        self.tally.count(function, status as i32);
        match status {
            Status::Ok => true,
            Status::NonFiniteResult => {
                let text = message();
                assert!(text.starts_with(function), "{function}: message \"{text}\"");
                false
            }
            other => panic!("{function} answered {other:?}: {}", message()),
        }
    }

    fn answer_value(&mut self, function: &'static str) {
        self.tally.count(function, NOT_STATUS);
    }

    fn new_bond_model(&mut self, params: BondParams) {
        let mut model: *mut BondModel = null_mut();
        // SAFETY: valid pointers.
        let status = unsafe { fb::granbond_bond_model_new(&params, &mut model) };
        if self.answer("granbond_bond_model_new", status) {
            assert!(!model.is_null(), "granbond_bond_model_new: OK without a model");
            self.bond_models.push(model);
        } else {
            assert!(model.is_null(), "granbond_bond_model_new: {status:?} but a model");
        }
    }

    fn new_voigt_model(&mut self, params: VoigtParams) {
        let mut model: *mut VoigtModel = null_mut();
        // SAFETY: valid pointers.
        let status = unsafe { fc::granbond_voigt_model_new(&params, &mut model) };
        if self.answer("granbond_voigt_model_new", status) {
            assert!(!model.is_null(), "granbond_voigt_model_new: OK without a model");
            self.voigt_models.push(model);
        } else {
            assert!(
                model.is_null(),
                "granbond_voigt_model_new: {status:?} but a model"
            );
        }
    }

    /// A live model, or null.
    fn bond_model(&mut self, input: &mut Input) -> *const BondModel {
        let n = self.bond_models.len();
        match input.below(n + 1) {
            i if i < n => self.bond_models[i],
            _ => null(),
        }
    }

    fn voigt_model(&mut self, input: &mut Input) -> *const VoigtModel {
        let n = self.voigt_models.len();
        match input.below(n + 1) {
            i if i < n => self.voigt_models[i],
            _ => null(),
        }
    }

    /// A live model for the unchecked entries (which must get one), if any.
    fn live_voigt_model(&mut self, input: &mut Input) -> Option<*const VoigtModel> {
        let n = self.voigt_models.len();
        (n > 0).then(|| self.voigt_models[input.below(n)] as *const VoigtModel)
    }

    /// The pair of the last call, moved or mutated, or a new one.
    fn kinematics(&mut self, input: &mut Input) -> PairKinematics {
        match input.below(6) {
            0 | 1 => {}
            2 => input.mutate(&mut self.pair),
            3 => self.pair = realistic_pair(input),
            4 => {
                self.pair = realistic_pair(input);
                input.mutate(&mut self.pair);
            }
            _ => {
                // coincident or nearly coincident centres
                self.pair = realistic_pair(input);
                let offset = [0.0, 1e-300, 1e-160, 5e-324][input.below(4)];
                self.pair.x_i = self.pair.x_j.map(|x| x + offset);
            }
        }
        self.pair
    }

    fn sphere(&mut self, input: &mut Input) -> SphereKinematics {
        let k = self.kinematics(input);
        let mut s = SphereKinematics {
            x: k.x_i,
            v: k.v_i,
            w: k.w_i,
            radius: k.radius_i,
        };
        if input.below(4) == 0 {
            input.mutate(&mut s);
        }
        s
    }

    fn plane(&mut self, input: &mut Input) -> Plane {
        let mut normal = [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.6, 0.8]][input.below(3)];
        match input.below(8) {
            0 => normal = input.vec3(),
            1 => normal = [0.0; 3],
            2 => normal[0] *= 1.0 + 1e-12 * input.f64(),
            _ => {}
        }
        let mut p = Plane {
            point: [self.pair.x_j[0] + 1e-3, 0.0, 0.0],
            normal,
            velocity: [0.0; 3],
        };
        if input.below(4) == 0 {
            input.mutate(&mut p);
        }
        p
    }

    fn frame(&mut self, input: &mut Input) -> ContactFrame {
        let mut f = self.frame;
        if input.below(3) == 0 {
            input.mutate(&mut f);
        }
        f
    }

    fn dt(&mut self, input: &mut Input) -> f64 {
        match input.below(4) {
            0 => input.f64(),
            _ => 1e-7,
        }
    }

    fn state(&mut self, input: &mut Input) -> usize {
        input.below(POOL)
    }

    /// A pool entry as the ABI sees it: null, misaligned or valid.
    fn state_ptr(&mut self, index: usize, how: Pointer) -> *mut f64 {
        let p = self.pool[index].as_mut_ptr();
        match how {
            Pointer::Null => null_mut(),
            Pointer::Misaligned => (p as *mut u8).wrapping_add(1) as *mut f64,
            Pointer::Valid => p,
        }
    }

    /// An OK answer with a non-finite number computed from finite input
    /// (overflow or underflow of values far outside the physical range)
    /// is wrong: the checked entries refuse it (`ffi::results`).
    fn note_finite(&mut self, function: &'static str, finite: bool) {
        assert!(
            finite,
            "{function}: OK with a non-finite output from finite input"
        );
    }

    fn check_state_finite(&mut self, function: &'static str, index: usize, len: usize, before: &[f64]) {
        if all_finite(&before[..len]) {
            let finite = all_finite(&self.pool[index][..len]);
            self.note_finite(function, finite);
        }
    }

    fn check_bond_output(&mut self, function: &'static str, o: &BondOutput) {
        assert!(
            (0..=2).contains(&o.status),
            "{function}: status {} in the output",
            o.status
        );
        assert!(
            (0..=4).contains(&o.break_mode),
            "{function}: break mode {}",
            o.break_mode
        );
        self.note_finite(function, all_finite(&bond_output_numbers(o)));
    }

    fn check_contact_output(&mut self, function: &'static str, o: &ContactOutput) {
        for flag in [o.touching, o.sliding, o.rolling_slip] {
            assert!(flag == 0 || flag == 1, "{function}: flag {flag} in {o:?}");
        }
        self.note_finite(function, all_finite(&contact_output_numbers(o)));
    }

    /// One call, chosen by the next byte.
    fn op(&mut self, input: &mut Input) {
        match input.below(36) {
            0 => self.bond_params_default(input),
            1 => {
                let mut p = match input.below(3) {
                    0 => BondParams::default(),
                    1 => bond_params(false),
                    _ => bond_params(true),
                };
                input.mutate(&mut p);
                self.bond_model_new(input, p);
            }
            2 => {
                if !self.bond_models.is_empty() {
                    let m = self.bond_models.remove(input.below(self.bond_models.len()));
                    // SAFETY: from granbond_bond_model_new, not used again.
                    unsafe { fb::granbond_bond_model_free(m) };
                    self.answer_value("granbond_bond_model_free");
                }
                // SAFETY: null is allowed.
                unsafe { fb::granbond_bond_model_free(null_mut()) };
            }
            3 => self.parameter_count(input, true),
            4 => self.bond_create(input, false),
            5 => self.bond_may_create(input),
            6 => self.bond_create(input, true),
            7 => self.bond_compute(input),
            8..=10 => self.bond_indexed(input),
            11 => self.wall_try_create(input),
            12 => self.wall_compute(input),
            13 | 14 => self.bond_reach(input),
            15 | 16 => self.timestep(input),
            17 => self.voigt_params_default(input),
            18 => {
                let mut p = VoigtParams::default();
                if input.below(2) == 0 {
                    p.no_attraction = 0;
                    p.rolling = input.below(2) as i32;
                }
                input.mutate(&mut p);
                self.voigt_model_new(input, p);
            }
            19 => {
                if !self.voigt_models.is_empty() {
                    let m = self.voigt_models.remove(input.below(self.voigt_models.len()));
                    // SAFETY: from granbond_voigt_model_new, not used again.
                    unsafe { fc::granbond_voigt_model_free(m) };
                    self.answer_value("granbond_voigt_model_free");
                }
                // SAFETY: null is allowed.
                unsafe { fc::granbond_voigt_model_free(null_mut()) };
            }
            20 | 21 => self.voigt_compute(input),
            22 => self.voigt_evaluate_then_step(input),
            23 => self.bond_store(input),
            24 => self.voigt_unchecked(input),
            25 | 26 => self.frames(input),
            27 => self.voigt_normal_force(input),
            28 => self.voigt_tangential(input),
            29 => self.voigt_rolling(input),
            30 => self.timestep(input),
            31 => self.parameter_count(input, false),
            32 => self.layout(input),
            33 => self.state_layout(input),
            34 => {
                // write over a state: another model's, or garbage
                let i = self.state(input);
                for _ in 0..input.below(6) {
                    let slot = input.below(MAX_STATE);
                    self.pool[i][slot] = match input.below(3) {
                        0 => [0.0, 1.0, 2.0, 3.0, -1.0][input.below(5)],
                        _ => input.f64(),
                    };
                }
            }
            _ => self.march(input),
        }
    }

    fn bond_params_default(&mut self, input: &mut Input) {
        let mut p = Place::new(bond_params(true));
        let how = input.pointer();
        // SAFETY: null, misaligned (checked) or valid.
        let status = unsafe { fb::granbond_bond_params_default(p.ptr(how)) };
        if self.answer("granbond_bond_params_default", status) {
            assert_eq!(p.get(), BondParams::default());
        }
        // the same in a unit style (or none)
        let drawn = input.below(6);
        let style = ["si", "cgs", "micro", "nano", "lj", ""][drawn];
        let units = std::ffi::CString::new(style).expect("no NUL");
        let units_ptr = if style.is_empty() { null() } else { units.as_ptr() };
        // the linear bond's defaults with every other style (no byte more
        // drawn, so the corpus's inputs keep their meaning)
        let linear = drawn % 2 == 1;
        let how = input.pointer();
        // SAFETY: a C string or null; the params pointer null, misaligned or valid.
        let status =
            unsafe { fb::granbond_bond_params_default_in_units(units_ptr, linear as i32, p.ptr(how)) };
        if self.answer("granbond_bond_params_default_in_units", status) {
            let want = if linear {
                BondParams::linear_default_in_units(style)
            } else {
                BondParams::default_in_units(style)
            };
            let got = p.get();
            assert_eq!(
                (got.linear, got.contact_under_bond),
                (want.linear, want.contact_under_bond)
            );
            assert_eq!(got.smooth_velocity.to_bits(), want.smooth_velocity.to_bits());
            assert_eq!(
                got.smooth_angular_velocity.to_bits(),
                want.smooth_angular_velocity.to_bits()
            );
            assert_eq!(got.lambda, want.lambda);
        }
        // contact_under_bond by the law of those defaults, through the same
        // kind of pointer (no byte more drawn)
        // SAFETY: the params pointer null, misaligned or valid.
        let status = unsafe { fb::granbond_bond_params_contact_under_bond_by_law(p.ptr(how)) };
        if self.answer("granbond_bond_params_contact_under_bond_by_law", status) {
            // the defaults written above, or those of the first call where
            // this style had none
            let got = p.get();
            let keeps = got.linear != 0 || got.inl_compatible != 0;
            assert_eq!(got.contact_under_bond, i32::from(keeps));
        }
    }

    fn bond_model_new(&mut self, input: &mut Input, params: BondParams) {
        let mut p = Place::new(params);
        let mut m = Place::new(null_mut::<BondModel>());
        let (hp, hm) = (input.pointer(), input.pointer());
        // SAFETY: null, misaligned or valid pointers.
        let status = unsafe { fb::granbond_bond_model_new(p.ptr(hp), m.ptr(hm)) };
        if self.answer("granbond_bond_model_new", status) {
            assert!(!m.get().is_null(), "granbond_bond_model_new: OK without a model");
            self.bond_models.push(m.get());
        } else {
            assert!(
                m.get().is_null(),
                "granbond_bond_model_new: {status:?} left a model"
            );
        }
    }

    fn voigt_params_default(&mut self, input: &mut Input) {
        let mut p = Place::new(VoigtParams {
            k_n: f64::NAN,
            ..VoigtParams::default()
        });
        let how = input.pointer();
        // SAFETY: null, misaligned or valid.
        let status = unsafe { fc::granbond_voigt_params_default(p.ptr(how)) };
        if self.answer("granbond_voigt_params_default", status) {
            assert_eq!(p.get(), VoigtParams::default());
        }
    }

    fn voigt_model_new(&mut self, input: &mut Input, params: VoigtParams) {
        let mut p = Place::new(params);
        let mut m = Place::new(null_mut::<VoigtModel>());
        let (hp, hm) = (input.pointer(), input.pointer());
        // SAFETY: null, misaligned or valid pointers.
        let status = unsafe { fc::granbond_voigt_model_new(p.ptr(hp), m.ptr(hm)) };
        if self.answer("granbond_voigt_model_new", status) {
            assert!(!m.get().is_null(), "granbond_voigt_model_new: OK without a model");
            self.voigt_models.push(m.get());
        } else {
            assert!(
                m.get().is_null(),
                "granbond_voigt_model_new: {status:?} left a model"
            );
        }
    }

    fn parameter_count(&mut self, input: &mut Input, bond: bool) {
        let (count, rows, function) = if bond {
            (
                fb::granbond_bond_parameter_count(),
                PARAMETERS.len(),
                "granbond_bond_parameter_count",
            )
        } else {
            (
                fc::granbond_voigt_parameter_count(),
                VOIGT_PARAMETERS.len(),
                "granbond_voigt_parameter_count",
            )
        };
        assert_eq!(count, rows, "parameter count");
        self.answer_value(function);
        self.parameter_rows(input, bond, count);
    }

    /// Row info, set-by-name and the need of a row, with null, misaligned
    /// and valid pointers, ids in and out of range, and names from the
    /// table or not.
    fn parameter_rows(&mut self, input: &mut Input, bond: bool, count: usize) {
        let id = input.usize();
        let mut row = Place::new(ParameterRow {
            keyword: null(),
            liggghts_name: null(),
            kind: granbond::parameters::ParameterKind::Real,
            liggghts_source: granbond::parameters::LiggghtsSource::Fixed,
            unit: null(),
            range: null(),
            needed_when: null(),
            default_value: 0.0,
        });
        let h = input.pointer();
        let (function, status) = if bond {
            ("granbond_bond_parameter_info", unsafe {
                fp::granbond_bond_parameter_info(id, row.ptr(h))
            })
        } else {
            ("granbond_voigt_parameter_info", unsafe {
                fp::granbond_voigt_parameter_info(id, row.ptr(h))
            })
        };
        let known = self.answer(function, status);
        if known {
            assert!(id < count, "{function}: OK for id {id} of {count}");
        }
        self.deck(id, h, bond);
        let name: &[u8] = match input.below(3) {
            0 if known => unsafe { CStr::from_ptr(row.get().keyword) }.to_bytes_with_nul(),
            1 if known => unsafe { CStr::from_ptr(row.get().liggghts_name) }.to_bytes_with_nul(),
            _ => b"no_such_parameter\0",
        };
        let value = input.f64();
        let (hp, hn, hd) = (input.pointer(), input.pointer(), input.pointer());
        let name_ptr = if input.below(8) == 0 {
            null()
        } else {
            name.as_ptr() as *const c_char
        };
        if bond {
            self.set_and_need(&BOND_TABLE, id, name_ptr, value, [hp, hn, hd]);
        } else {
            self.set_and_need(&VOIGT_TABLE, id, name_ptr, value, [hp, hn, hd]);
        }
    }

    /// The deck's phrase and part of the same id through the same pointer:
    /// no input of its own, so the corpus reads as before.
    fn deck(&mut self, id: usize, h: Pointer, bond: bool) {
        let mut phrase = Place::new(PhraseRow {
            words: null(),
            follows: null(),
            reads: null(),
            sets: null(),
        });
        let (function, status) = if bond {
            ("granbond_bond_phrase_info", unsafe {
                fd::granbond_bond_phrase_info(id % 8, phrase.ptr(h))
            })
        } else {
            ("granbond_voigt_phrase_info", unsafe {
                fd::granbond_voigt_phrase_info(id % 8, phrase.ptr(h))
            })
        };
        if self.answer(function, status) {
            assert!(!phrase.get().words.is_null() && !phrase.get().reads.is_null());
        }
        if bond {
            // both laws' names of the row, through the same pointer
            for linear in [0, 1, id as i32 % 3] {
                let mut name = Place::new(c"unset".as_ptr());
                // SAFETY: null, misaligned or valid pointer.
                let status = unsafe { fp::granbond_bond_parameter_liggghts_name(linear, id, name.ptr(h)) };
                if self.answer("granbond_bond_parameter_liggghts_name", status) {
                    assert!(id < PARAMETERS.len() && linear < 2);
                    assert_eq!(
                        name.get().is_null(),
                        granbond::bond::liggghts_name(linear == 1, id).is_none()
                    );
                }
            }
            let creation = fp::granbond_bond_parameter_sets_creation(id);
            assert!((-1..=2).contains(&creation), "sets_creation {creation}");
            self.answer_value("granbond_bond_parameter_sets_creation");
        }
        self.coeff_lines(id, h, bond);
        if !bond {
            let mut part = Place::new(granbond::contact::ContactPart::Rolling);
            // SAFETY: null, misaligned or valid pointer.
            let status = unsafe { fd::granbond_voigt_parameter_part(id, part.ptr(h)) };
            if self.answer("granbond_voigt_parameter_part", status) {
                assert!(id < VOIGT_PARAMETERS.len());
            }
            let mut sub = Place::new(fd::SubModelRow {
                words: null(),
                reads: 0,
            });
            // SAFETY: null, misaligned or valid pointer.
            let status = unsafe { fd::granbond_voigt_sub_model(id, sub.ptr(h)) };
            if self.answer("granbond_voigt_sub_model", status) {
                assert!(id < 3 && !sub.get().words.is_null() && sub.get().reads & 1 << id != 0);
            }
        }
    }

    /// A `pair_coeff` line setting row `id` of the table after the contact's
    /// values, and (bond) a `bond_coeff` line setting it, read whole with
    /// the results through the same pointer: no input of its own either.
    fn coeff_lines(&mut self, id: usize, h: Pointer, bond: bool) {
        let row = if bond {
            PARAMETERS.get(id).map(|r| (r.name, r.kind()))
        } else {
            VOIGT_PARAMETERS.get(id).map(|r| (r.name, r.kind()))
        };
        let (keyword, kind) = row.unwrap_or(("no_such_keyword", granbond::parameters::ParameterKind::Real));
        let value = if kind == granbond::parameters::ParameterKind::Switch {
            "on"
        } else {
            "1"
        };
        let mut line: Vec<&str> = vec!["voigt", "1e5", "0", "1e5", "0", "0.5"];
        if bond {
            line.push("bond/nonlinear");
        }
        line.extend([keyword, value]);
        let strings: Vec<std::ffi::CString> =
            line.iter().map(|w| std::ffi::CString::new(*w).unwrap()).collect();
        let words: Vec<*const c_char> = strings.iter().map(|w| w.as_ptr()).collect();
        let mut voigt = Place::new(VoigtParams::default());
        let mut params = Place::new(BondParams::default());
        let mut has_bond = Place::new(-1i32);
        // SAFETY: valid words; null, misaligned or valid outputs.
        let status = unsafe {
            fd::granbond_pair_coeff_read(
                c"pair_coeff 1 1".as_ptr(),
                words.as_ptr(),
                words.len(),
                c"si".as_ptr(),
                voigt.ptr(h),
                params.ptr(h),
                has_bond.ptr(h),
            )
        };
        if self.answer("granbond_pair_coeff_read", status) {
            assert_eq!(has_bond.get(), i32::from(bond));
            assert!(voigt.get().validate().is_ok());
        }
        self.restart_rows(id, h, bond, &params.get(), &voigt.get());
        self.liggghts_lines(id, h, bond);
        if bond {
            // SAFETY: as above.
            let status = unsafe {
                fd::granbond_bond_coeff_read(c"bond_coeff 1".as_ptr(), words[7..].as_ptr(), 2, params.ptr(h))
            };
            if self.answer("granbond_bond_coeff_read", status) {
                assert!(
                    granbond::parameters::check_ranges("bond/nonlinear", PARAMETERS, &params.get()).is_ok()
                );
            }
        }
    }

    /// A LIGGGHTS property line of row `id`'s name and a settings line,
    /// the outputs through pointer `h`.
    fn liggghts_lines(&mut self, id: usize, h: Pointer, bond: bool) {
        let name = if bond {
            PARAMETERS.get(id).map(|r| r.liggghts_name)
        } else {
            VOIGT_PARAMETERS.get(id).map(|r| r.liggghts_name)
        };
        let line = [
            "p",
            "all",
            "property/global",
            name.unwrap_or("k_n"),
            "peratomtypepair",
            "1",
            "inf",
        ];
        let strings: Vec<std::ffi::CString> =
            line.iter().map(|w| std::ffi::CString::new(*w).unwrap()).collect();
        let words: Vec<*const c_char> = strings.iter().map(|w| w.as_ptr()).collect();
        let mut infinite = Place::new([0i32; 7]);
        let mut ours = Place::new(-1i32);
        // SAFETY: valid words; null, misaligned or valid outputs of 7.
        let status = unsafe {
            fd::granbond_liggghts_property_line_check(
                words.as_ptr(),
                7,
                infinite.ptr(h) as *mut i32,
                ours.ptr(h),
            )
        };
        if self.answer("granbond_liggghts_property_line_check", status) {
            assert!(
                ours.get() == 0 || infinite.get()[6] == 1,
                "an infinity accepted is flagged"
            );
        }
        let settings = if bond { &words[3..] } else { &words[2..] };
        // SAFETY: valid words and command.
        let status = unsafe {
            fd::granbond_liggghts_settings_check(
                c"pair_style gran".as_ptr(),
                settings.as_ptr(),
                settings.len(),
            )
        };
        self.answer("granbond_liggghts_settings_check", status);
    }

    /// The parameters as restart rows and back through pointer `h`, the
    /// rows cut at `id` bytes where `id` is shorter (a damaged file).
    fn restart_rows(&mut self, id: usize, h: Pointer, bond: bool, b: &BondParams, v: &VoigtParams) {
        let mut len = Place::new(0usize);
        let mut buf = vec![0u8; 4096];
        // SAFETY: valid parameters and buffer; null, misaligned or valid `len`.
        let status = unsafe {
            if bond {
                fp::granbond_bond_params_rows(b, buf.as_mut_ptr(), buf.len(), len.ptr(h))
            } else {
                fp::granbond_voigt_params_rows(v, buf.as_mut_ptr(), buf.len(), len.ptr(h))
            }
        };
        let name = if bond {
            "granbond_bond_params_rows"
        } else {
            "granbond_voigt_params_rows"
        };
        if !self.answer(name, status) {
            return;
        }
        let n = len.get().min(if id > 0 { id } else { usize::MAX });
        let mut back_b = Place::new(BondParams::default());
        let mut back_v = Place::new(VoigtParams::default());
        // SAFETY: `n` readable bytes; null, misaligned or valid outputs.
        let (name, status) = unsafe {
            if bond {
                let s = fp::granbond_bond_params_from_rows(
                    buf.as_ptr(),
                    n,
                    c"atom types 1 1".as_ptr(),
                    back_b.ptr(h),
                );
                ("granbond_bond_params_from_rows", s)
            } else {
                let s = fp::granbond_voigt_params_from_rows(
                    buf.as_ptr(),
                    n,
                    c"atom types 1 1".as_ptr(),
                    back_v.ptr(h),
                );
                ("granbond_voigt_params_from_rows", s)
            }
        };
        if self.answer(name, status) {
            assert_eq!(n, len.get(), "{name}: OK from rows cut short");
            if bond {
                assert_eq!(
                    format!("{:?}", back_b.get()),
                    format!("{b:?}"),
                    "the bond's rows read back"
                );
            } else {
                assert_eq!(
                    format!("{:?}", back_v.get()),
                    format!("{v:?}"),
                    "the contact's rows read back"
                );
            }
        }
    }

    /// `*_params_set` on the defaults, then `*_parameter_needed` of row `id`.
    fn set_and_need<T: Copy + Default + std::fmt::Debug>(
        &mut self,
        t: &TableEntries<T>,
        id: usize,
        name: *const c_char,
        value: f64,
        [hp, hn, hd]: [Pointer; 3],
    ) {
        let mut p = Place::new(T::default());
        let mut needed = Place::new(-1i32);
        // SAFETY: null, misaligned or valid pointers; the name is null or NUL-terminated.
        let status = unsafe { (t.set)(p.ptr(hp), name, value) };
        if self.answer(t.set_name, status) {
            let ranges = granbond::parameters::check_ranges(t.model, t.table, &p.get());
            assert!(
                ranges.is_ok(),
                "{} stored a value out of range: {ranges:?}",
                t.set_name
            );
        }
        // row `id` read back (the pointers of the need's call)
        let mut value_back = Place::new(f64::NAN);
        // SAFETY: as above.
        let status = unsafe { (t.get)(p.ptr(hd), id, value_back.ptr(hn)) };
        if self.answer(t.get_name, status) {
            assert!(id < t.table.len(), "{}: row {id} answered", t.get_name);
        }
        // SAFETY: as above.
        let status = unsafe { (t.needed)(p.ptr(hd), id, needed.ptr(hn)) };
        if self.answer(t.needed_name, status) {
            assert!(needed.get() == 0 || needed.get() == 1);
        }
    }

    fn bond_create(&mut self, input: &mut Input, now: bool) {
        let m = self.bond_model(input);
        let mut k = Place::new(self.kinematics(input));
        let step = input.step();
        let i = self.state(input);
        let mut created = Place::new(-7i32);
        let (hk, hs, hc) = (input.pointer(), input.pointer(), input.pointer());
        let before = self.pool[i];
        let s = self.state_ptr(i, hs);
        // SAFETY: pointers null, misaligned or valid; the state holds
        // BOND_STATE_LEN doubles.
        let (function, status) = unsafe {
            if now {
                let st = fb::granbond_bond_create_now(m, k.ptr(hk), s, created.ptr(hc));
                ("granbond_bond_create_now", st)
            } else {
                let st = fb::granbond_bond_try_create(m, k.ptr(hk), step, s, created.ptr(hc));
                ("granbond_bond_try_create", st)
            }
        };
        if self.answer(function, status) {
            let c = created.get();
            assert!(c == 0 || c == 1, "{function}: created = {c}");
            if c == 1 {
                assert!(
                    self.pool[i][0] > 0.0,
                    "{function}: created, but the rest slot {} is not intact (positive)",
                    self.pool[i][0]
                );
            }
            self.check_state_finite(function, i, BOND_STATE_LEN, &before);
        }
    }

    fn bond_may_create(&mut self, input: &mut Input) {
        let m = self.bond_model(input);
        let i = self.state(input);
        let how = input.pointer();
        let step = input.step();
        let s = self.state_ptr(i, how);
        // SAFETY: null, misaligned or valid.
        let answer = unsafe { fb::granbond_bond_may_create(m, s, step) };
        assert!(
            answer == 0 || answer == 1,
            "granbond_bond_may_create answered {answer}"
        );
        if m.is_null() || how != Pointer::Valid {
            assert_eq!(
                answer, 0,
                "granbond_bond_may_create: 1 for a null or misaligned pointer"
            );
        }
        self.answer_value("granbond_bond_may_create");

        // SAFETY: null or from granbond_bond_model_new.
        let any = unsafe { fb::granbond_bond_creates_at(m, step) };
        assert!(any == 0 || any == 1, "granbond_bond_creates_at answered {any}");
        if m.is_null() {
            assert_eq!(any, 0, "granbond_bond_creates_at: 1 for a null model");
        }
        // engines skip every pair's rules where it says 0
        if any == 0 {
            assert_eq!(
                answer, 0,
                "granbond_bond_creates_at said 0 at step {step}, granbond_bond_may_create 1"
            );
        }
        self.answer_value("granbond_bond_creates_at");

        // the same model and step, read no further from the input so the
        // corpus keeps its meaning
        let mut reach = f64::NAN;
        // SAFETY: null or from granbond_bond_model_new; `reach` is valid.
        let status = unsafe { fb::granbond_bond_creation_reach(m, step, &mut reach) };
        if self.answer("granbond_bond_creation_reach", status) {
            assert!(
                reach >= 0.0,
                "granbond_bond_creation_reach at step {step}: {reach}"
            );
        } else {
            assert!(
                m.is_null(),
                "granbond_bond_creation_reach refused a valid model: {status:?}"
            );
        }
    }

    fn bond_compute(&mut self, input: &mut Input) {
        let m = self.bond_model(input);
        let mut k = Place::new(self.kinematics(input));
        let dt = self.dt(input);
        let i = self.state(input);
        let mut out = Place::new(BondOutput::default());
        let (hk, hs, ho) = (input.pointer(), input.pointer(), input.pointer());
        let before = self.pool[i];
        let s = self.state_ptr(i, hs);
        // SAFETY: pointers null, misaligned or valid for their sizes.
        let status = unsafe { fb::granbond_bond_compute(m, k.ptr(hk), dt, s, out.ptr(ho)) };
        let function = "granbond_bond_compute";
        if self.answer(function, status) {
            if all_finite(&before[..BOND_STATE_LEN]) {
                self.check_bond_output(function, &out.get());
            }
            self.check_state_finite(function, i, BOND_STATE_LEN, &before);
        }
        // a run's setup pass on the same arguments, and what the model
        // says of its law
        let mut recomputed = Place::new(-1i32);
        // SAFETY: as above; `recomputed` valid.
        let status = unsafe {
            fb::granbond_bond_setup_compute(
                m,
                k.ptr(hk),
                dt,
                self.state_ptr(i, hs),
                recomputed.ptr(Pointer::Valid),
                out.ptr(ho),
            )
        };
        if self.answer("granbond_bond_setup_compute", status) && recomputed.get() == 1 {
            self.check_bond_output("granbond_bond_setup_compute", &out.get());
        }
        self.law_of(m);
        // what an engine keeps and logs of the step
        self.bond_output_slots(input, out.get());
        self.bond_centre(input, &k.get());
    }

    /// `granbond_bond_keeps_contact_tangential` and `granbond_bond_law_line`
    /// of `m` (which may be null or misaligned).
    fn law_of(&mut self, m: *const BondModel) {
        // SAFETY: null, misaligned or from granbond_bond_model_new.
        let keeps = unsafe { fb::granbond_bond_keeps_contact_tangential(m) };
        assert!(
            keeps == 0 || keeps == 1,
            "granbond_bond_keeps_contact_tangential answered {keeps}"
        );
        self.answer_value("granbond_bond_keeps_contact_tangential");
        // SAFETY: as above.
        let keeps = unsafe { fb::granbond_bond_keeps_contact_loads(m) };
        assert!(
            keeps == 0 || keeps == 1,
            "granbond_bond_keeps_contact_loads answered {keeps}"
        );
        self.answer_value("granbond_bond_keeps_contact_loads");
        // a touching contact's loads under the bond, on fixed numbers so the
        // corpus keeps its meaning: finite, and untouched where all are kept
        let del = [1e-3, 2e-4, -3e-4];
        let rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
        let given = ContactOutput {
            force_i: [2.0, -1.0, 0.5],
            torque_i: [1e-3, 2e-3, -1e-3],
            torque_j: [-1e-3, 1e-3, 3e-3],
            normal_force: 1.5,
            overlap: 1e-6,
            touching: 1,
            ..ContactOutput::default()
        };
        let mut o = given;
        // SAFETY: as above; `del` three doubles, `o` valid.
        let status = unsafe { fb::granbond_bond_contact_loads_under_bond(m, del.as_ptr(), rsq, &mut o) };
        if self.answer("granbond_bond_contact_loads_under_bond", status) {
            assert!(
                contact_output_numbers(&o).iter().all(|x| x.is_finite()),
                "granbond_bond_contact_loads_under_bond: loads not finite"
            );
            if keeps == 1 {
                assert!(
                    o == given,
                    "granbond_bond_contact_loads_under_bond changed loads it keeps"
                );
            }
        }
        let mut line = [0 as c_char; 512];
        // SAFETY: `line` holds 512 bytes.
        let status = unsafe { fb::granbond_bond_law_line(m, 1, line.as_mut_ptr(), line.len()) };
        if self.answer("granbond_bond_law_line", status) {
            // SAFETY: the entry ends the line with a NUL within the buffer.
            let text = unsafe { CStr::from_ptr(line.as_ptr()) };
            assert!(text.to_bytes().len() < 512 && !text.to_bytes().is_empty());
        }
    }

    /// Stores `o` in history slots and loads it back.
    fn bond_output_slots(&mut self, input: &mut Input, mut o: BondOutput) {
        if input.below(4) == 0 {
            input.mutate(&mut o);
        }
        let mut out = Place::new(o);
        let mut slots = Place::new([0.0f64; BOND_OUTPUT_LEN]);
        let (ho, hs) = (input.pointer(), input.pointer());
        // SAFETY: null, misaligned or valid for their sizes.
        let status = unsafe { fb::granbond_bond_output_store(out.ptr(ho), slots.ptr(hs) as *mut f64) };
        if self.answer("granbond_bond_output_store", status) {
            let stored = slots.get();
            let want = store_output(&o);
            assert!(
                stored.iter().zip(&want).all(|(a, b)| a.to_bits() == b.to_bits()),
                "granbond_bond_output_store: {stored:?} for {o:?}"
            );
            self.note_finite("granbond_bond_output_store", all_finite(&stored));
        }
        if input.below(4) == 0 {
            let mut s = slots.get();
            input.mutate(&mut s);
            slots = Place::new(s);
        }
        let mut back = Place::new(BondOutput::default());
        let (hs, hb) = (input.pointer(), input.pointer());
        // SAFETY: null, misaligned or valid for their sizes.
        let status = unsafe { fb::granbond_bond_output_load(slots.ptr(hs) as *const f64, back.ptr(hb)) };
        if self.answer("granbond_bond_output_load", status) {
            let b = back.get();
            assert!(
                b.status == 1 && b.break_mode == 0,
                "granbond_bond_output_load: {b:?}"
            );
            self.check_bond_output("granbond_bond_output_load", &b);
        }
    }

    /// The centre of the pair `k`, or of its sphere `i` and a wall point.
    fn bond_centre(&mut self, input: &mut Input, k: &PairKinematics) {
        let radius_j = if input.below(4) == 0 { 0.0 } else { k.radius_j };
        let (mut x_i, mut x_j) = (Place::new(k.x_i), Place::new(k.x_j));
        let mut centre = Place::new([f64::NAN; 3]);
        let (h1, h2, h3) = (input.pointer(), input.pointer(), input.pointer());
        // SAFETY: null, misaligned or valid for three doubles.
        let status = unsafe {
            fb::granbond_bond_centre(
                x_i.ptr(h1) as *const f64,
                x_j.ptr(h2) as *const f64,
                k.radius_i,
                radius_j,
                centre.ptr(h3) as *mut f64,
            )
        };
        if self.answer("granbond_bond_centre", status) {
            let c = centre.get();
            self.note_finite("granbond_bond_centre", all_finite(&c));
            if radius_j == 0.0 {
                assert_eq!(c, k.x_j, "granbond_bond_centre: a wall's centre is its point");
            }
        }
    }

    /// Several steps of one pair moving with its velocities: reaches the
    /// hysteresis, damping and breakage paths that one step does not.
    fn march(&mut self, input: &mut Input) {
        let bond = input.below(2) == 0;
        let i = self.state(input);
        let mut k = self.kinematics(input);
        let dt = [1e-7, 1e-6, 1e-5][input.below(3)];
        let scale = [1.0, 10.0, 100.0, 1000.0][input.below(4)];
        for _ in 0..input.below(32) {
            for c in 0..3 {
                k.x_i[c] += scale * k.v_i[c] * dt;
                k.x_j[c] += scale * k.v_j[c] * dt;
            }
            let before = self.pool[i];
            let s = self.pool[i].as_mut_ptr();
            if bond {
                let Some(&m) = self.bond_models.first() else {
                    return;
                };
                let mut o = BondOutput::default();
                let mut created = 0;
                // SAFETY: valid pointers; the state holds BOND_STATE_LEN doubles.
                let st = unsafe { fb::granbond_bond_try_create(m, &k, 0, s, &mut created) };
                self.answer("granbond_bond_try_create", st);
                // SAFETY: as above.
                let st = unsafe { fb::granbond_bond_compute(m, &k, dt, s, &mut o) };
                if self.answer("granbond_bond_compute", st) && all_finite(&before[..BOND_STATE_LEN]) {
                    self.check_bond_output("granbond_bond_compute", &o);
                }
            } else {
                let Some(&m) = self.voigt_models.first() else {
                    return;
                };
                let mut o = ContactOutput::default();
                // SAFETY: valid pointers; the state holds CONTACT_STATE_LEN doubles.
                let st = unsafe { fc::granbond_voigt_compute(m, &k, dt, s, &mut o) };
                if self.answer("granbond_voigt_compute", st) && all_finite(&before[..CONTACT_STATE_LEN]) {
                    self.check_contact_output("granbond_voigt_compute", &o);
                }
            }
        }
        self.pair = k;
    }

    /// A count for a batch: at most the buffers' size.
    fn count(&mut self, input: &mut Input) -> usize {
        input.below(MAX_BATCH + 1)
    }

    fn pairs(&mut self, input: &mut Input, count: usize) -> Vec<PairKinematics> {
        (0..count).map(|_| self.kinematics(input)).collect()
    }

    fn batch_ptr<T>(v: &mut [T], how: Pointer) -> *mut T {
        match how {
            Pointer::Null => null_mut(),
            Pointer::Misaligned => (v.as_mut_ptr() as *mut u8).wrapping_add(1) as *mut T,
            Pointer::Valid => v.as_mut_ptr(),
        }
    }

    /// Distinct pool entries, then some of them replaced by null or
    /// misaligned pointers: the entries and the pointers.
    fn scattered_pointers(&mut self, input: &mut Input, count: usize) -> (Vec<usize>, Vec<*mut f64>) {
        let start = input.below(POOL);
        let entries: Vec<usize> = (0..count).map(|c| (start + c) % POOL).collect();
        let mut p: Vec<*mut f64> = entries.iter().map(|&e| self.pool[e].as_mut_ptr()).collect();
        if count > 0 && input.below(4) == 0 {
            let c = input.below(count);
            p[c] = match input.below(2) {
                0 => null_mut(),
                _ => (p[c] as *mut u8).wrapping_add(1) as *mut f64,
            };
        }
        (entries, p)
    }

    fn after_scattered(
        &mut self,
        function: &'static str,
        status: Status,
        out: &[BondOutput],
        before: &[Entry],
        hf: Pointer,
        failed: &Place<usize>,
    ) {
        if self.answer(function, status) {
            if before.iter().all(|s| all_finite(&s[..BOND_STATE_LEN])) {
                for o in out {
                    self.check_bond_output(function, o);
                }
            }
        } else if hf == Pointer::Valid && failed.get() != usize::MAX {
            assert!(
                failed.get() < out.len(),
                "{function}: failed_index {} of {}",
                failed.get(),
                out.len()
            );
        }
    }

    /// The arguments of the indexed entries, drawn in one order for both,
    /// so that an input made for one drives the other to the same point.
    fn indexed_bonds(&mut self, input: &mut Input) -> IndexedBonds {
        let model = self.bond_model(input);
        let count = self.count(input).min(POOL);
        let atoms = input.below(MAX_ATOMS + 1);
        let mut x = Vec::with_capacity(3 * atoms + 1);
        let mut v = Vec::with_capacity(3 * atoms + 1);
        let mut w = Vec::with_capacity(3 * atoms + 1);
        let mut radius = Vec::with_capacity(atoms + 1);
        for a in 0..atoms {
            let k = self.kinematics(input);
            let (xs, vs, ws, r) = if a % 2 == 0 {
                (k.x_i, k.v_i, k.w_i, k.radius_i)
            } else {
                (k.x_j, k.v_j, k.w_j, k.radius_j)
            };
            x.extend(xs);
            v.extend(vs);
            w.extend(ws);
            radius.push(r);
        }
        for a in [&mut x, &mut v, &mut w, &mut radius] {
            a.push(0.0);
        }
        let pairs: Vec<i32> = (0..2 * count + 1)
            .map(|_| match input.below(8) {
                0 => input.i32(),
                1 => atoms as i32,
                _ => input.below(atoms.max(1)) as i32,
            })
            .collect();
        let (hx, hv, hw, hr) = (input.pointer(), input.pointer(), input.pointer(), input.pointer());
        let mut a = AtomArrayPointers {
            x: Self::batch_ptr(&mut x, hx),
            v: Self::batch_ptr(&mut v, hv),
            omega: Self::batch_ptr(&mut w, hw),
            radius: Self::batch_ptr(&mut radius, hr),
            count: atoms,
        };
        if input.below(8) == 0 {
            // a count the arrays cannot hold: only with null arrays, which
            // the ABI must refuse before it reads them
            a = AtomArrayPointers {
                x: null(),
                v: null(),
                omega: null(),
                radius: null(),
                count: input.usize(),
            };
        }
        let dt = self.dt(input);
        let (entries, states) = self.scattered_pointers(input, count);
        let how = [
            input.pointer(),
            input.pointer(),
            input.pointer(),
            input.pointer(),
            input.pointer(),
        ];
        IndexedBonds {
            model,
            count,
            _arrays: [x, v, w, radius],
            atoms: Place::new(a),
            pairs,
            dt,
            entries,
            states,
            how,
        }
    }

    fn bond_indexed(&mut self, input: &mut Input) {
        let mut b = self.indexed_bonds(input);
        let count = b.count;
        let mut states = b.states.clone();
        states.push(null_mut());
        let mut out = vec![BondOutput::default(); count + 1];
        let mut failed = Place::new(usize::MAX);
        let [ha, hp, hs, ho, hf] = b.how;
        let before = self.pool.clone();
        // SAFETY: arrays of `atoms->count` atoms, `count` distinct states,
        // `2 count` indices, `count` outputs (null or misaligned checked).
        let status = unsafe {
            fb::granbond_bond_compute_indexed(
                b.model,
                count,
                b.atoms.ptr(ha),
                Self::batch_ptr(&mut b.pairs, hp),
                b.dt,
                Self::batch_ptr(&mut states, hs),
                Self::batch_ptr(&mut out, ho),
                failed.ptr(hf),
            )
        };
        self.after_scattered(
            "granbond_bond_compute_indexed",
            status,
            &out[..count],
            &before,
            hf,
            &failed,
        );
    }

    /// A rank's bond store through its life: atoms linked, bonds created,
    /// stepped (force and setup passes), broken, packed to another store
    /// and unpacked there, the per-atom events; ids, types, kinds and
    /// positions fuzzed, every pointer null, misaligned or valid.
    fn bond_store(&mut self, input: &mut Input) {
        let n = 2 + input.below(4);
        let model = self.bond_model(input);
        let mut ids: Vec<i64> = (0..n as i64).map(|a| a + 1).collect();
        let mut x = Vec::with_capacity(3 * n);
        let mut v = Vec::with_capacity(3 * n);
        let mut w = Vec::with_capacity(3 * n);
        let mut radius = Vec::with_capacity(n);
        for a in 0..n {
            let k = self.kinematics(input);
            // a chain along x, about a diameter apart, where the pair is sane
            let shift = [2e-3 * a as f64, 0.0, 0.0];
            x.extend((0..3).map(|c| k.x_i[c] - k.x_j[c] + shift[c]));
            v.extend(k.v_i);
            w.extend(k.w_i);
            radius.push(k.radius_i);
        }
        let mut types = vec![1i32; n];
        let mut kinds = [-1i32, -1, -1, 0];
        if input.below(4) == 3 {
            let a = input.below(n);
            ids[a] = input.step();
            types[input.below(n)] = input.i32();
            kinds[input.below(4)] = input.i32();
        }
        let nlocal = n - input.below(2);
        let wide_ids = AtomIds {
            narrow: null(),
            wide: ids.as_ptr(),
            count: n,
        };
        let store_atoms = StoreAtoms {
            ids: wide_ids,
            nlocal,
            x: x.as_ptr(),
            types: types.as_ptr(),
            reach: [0.0, 3e-3, -1.0, f64::NAN][input.below(4)],
        };
        let arrays = AtomArrayPointers {
            x: x.as_ptr(),
            v: v.as_ptr(),
            omega: w.as_ptr(),
            radius: radius.as_ptr(),
            count: n,
        };
        let mut store = Place::new(null_mut::<granbond::bond_store::BondStore>());
        // SAFETY: null, misaligned or valid for one pointer.
        let status = unsafe { fs::granbond_bond_store_new(store.ptr(input.late_pointer())) };
        if !self.answer("granbond_bond_store_new", status) {
            return;
        }
        let st = store.get();
        let ok = |s: &mut Self, f: &'static str, status: Status| s.answer(f, status);
        // SAFETY (every call below): `st` is a live store; the other
        // pointers are null, misaligned or valid for their documented sizes.
        unsafe {
            // the energy budget kept or not, and per bond or not, by the
            // atom count (no input read: the corpus reads on as before)
            let status = fs::granbond_bond_store_keep_energy_budget(st, (n % 2) as i32, (n % 4 < 2) as i32);
            ok(self, "granbond_bond_store_keep_energy_budget", status);
            let status = fs::granbond_bond_store_grow(st, n);
            ok(self, "granbond_bond_store_grow", status);
            let mut report = Place::new(LinkReport::default());
            let mut sa = Place::new(store_atoms);
            let (ha, hr) = (input.late_pointer(), input.late_pointer());
            let status = fs::granbond_bond_store_link(st, sa.ptr(ha), kinds.as_ptr(), 1, report.ptr(hr));
            let linked = ok(self, "granbond_bond_store_link", status);
            let dt = if input.below(8) == 7 { input.f64() } else { 1e-7 };
            let (advance, remember) = (input.below(4) != 3, input.below(2));
            let status = fs::granbond_bond_store_begin_pass(st, dt, advance as i32, remember as i32);
            ok(self, "granbond_bond_store_begin_pass", status);
            for a in 0..nlocal.min(n - 1) {
                let owner = fs::granbond_bond_store_creates_here(1, 1, ids[a], ids[a + 1], 0);
                self.answer_value("granbond_bond_store_creates_here");
                let (o, p) = if owner == 1 { (a + 1, a) } else { (a, a + 1) };
                let three = |arr: &[f64], k: usize| [arr[3 * k], arr[3 * k + 1], arr[3 * k + 2]];
                let k = PairKinematics {
                    x_i: three(&x, o),
                    x_j: three(&x, p),
                    v_i: three(&v, o),
                    v_j: three(&v, p),
                    w_i: three(&w, o),
                    w_j: three(&w, p),
                    radius_i: radius[o],
                    radius_j: radius[p],
                };
                let mut created = Place::new(-1i32);
                let step = if input.below(4) == 3 { input.step() } else { 0 };
                let status = fs::granbond_bond_store_try_create(
                    st,
                    model,
                    input.below(2) as u16,
                    o,
                    p,
                    ids[o],
                    ids[p],
                    &k,
                    step,
                    created.ptr(input.late_pointer()),
                );
                if ok(self, "granbond_bond_store_try_create", status) {
                    assert!(matches!(created.get(), 0 | 1), "created {}", created.get());
                }
            }
            // an owner beyond the atoms: answered, nothing created (it reads
            // no input, so the corpus keeps its meaning)
            let mut created = Place::new(-1i32);
            let k = PairKinematics {
                x_i: [0.0; 3],
                x_j: [1e-3, 0.0, 0.0],
                v_i: [0.0; 3],
                v_j: [0.0; 3],
                w_i: [0.0; 3],
                w_j: [0.0; 3],
                radius_i: 5e-4,
                radius_j: 5e-4,
            };
            let status = fs::granbond_bond_store_create_now(
                st,
                model,
                0,
                n + 1,
                0,
                ids[0],
                ids[0] + 1,
                &k,
                created.ptr(Pointer::Valid),
            );
            if ok(self, "granbond_bond_store_create_now", status) {
                assert_eq!(created.get(), 0, "no bond for an owner beyond the atoms");
            }
            let models = [model, null()];
            let mut ends = vec![0i32; 2 * GRANBOND_BOND_STORE_CHUNK + 1];
            let mut outs = vec![BondOutput::default(); GRANBOND_BOND_STORE_CHUNK + 1];
            let mut failed = Place::new(usize::MAX);
            // the atoms' load sums, with ghost rows or not by the atom
            // count (no input read: the corpus reads on as before)
            let (mut force, mut torque) = (vec![0.0; 3 * n], vec![0.0; 3 * n]);
            let mut ghost_rows = vec![0.0; 6 * (n - nlocal)];
            let loads = AtomLoadPointers {
                force: force.as_mut_ptr(),
                torque: torque.as_mut_ptr(),
                count: n,
                nlocal,
                ghost_rows: if n.is_multiple_of(2) {
                    ghost_rows.as_mut_ptr()
                } else {
                    null_mut()
                },
                relax: if n.is_multiple_of(3) {
                    radius.as_ptr()
                } else {
                    null()
                },
            };
            // the pass that created the bonds, then one over the chain
            // stretched (bonds break past max_distance)
            for round in 0..2 {
                if round == 1 {
                    let stretch = [1e-3, 1e-4, 1e-5, 0.0][input.below(4)];
                    for (a, xa) in x.chunks_mut(3).enumerate() {
                        xa[0] += stretch * a as f64;
                    }
                    let status = fs::granbond_bond_store_link(
                        st,
                        sa.ptr(Pointer::Valid),
                        kinds.as_ptr(),
                        1,
                        report.ptr(Pointer::Valid),
                    );
                    ok(self, "granbond_bond_store_link", status);
                    let status = fs::granbond_bond_store_begin_pass(st, 1e-7, 1, 0);
                    ok(self, "granbond_bond_store_begin_pass", status);
                }
                // the stretched chain's pass in one call where the atom
                // count says so, else chunk by chunk, adding the loads in
                // the first pass and not in the second
                if round == 1 && n % 4 == 1 {
                    let mut count = Place::new(usize::MAX);
                    let status = fs::granbond_bond_store_step_rest(
                        st,
                        models.as_ptr(),
                        1,
                        &arrays,
                        &wide_ids,
                        &loads,
                        count.ptr(Pointer::Valid),
                        failed.ptr(Pointer::Valid),
                    );
                    ok(self, "granbond_bond_store_step_rest", status);
                }
                for _ in 0..4 {
                    let mut count = Place::new(usize::MAX);
                    let (he, ho, hc) = (input.late_pointer(), input.late_pointer(), input.late_pointer());
                    let status = fs::granbond_bond_store_step_next(
                        st,
                        models.as_ptr(),
                        1 + input.below(2),
                        &arrays,
                        &wide_ids,
                        if round == 0 {
                            &loads as *const AtomLoadPointers
                        } else {
                            null()
                        },
                        Self::batch_ptr(&mut ends, he),
                        Self::batch_ptr(&mut outs, ho),
                        count.ptr(hc),
                        failed.ptr(input.late_pointer()),
                    );
                    if !ok(self, "granbond_bond_store_step_next", status) || count.get() == 0 {
                        break;
                    }
                    assert!(
                        count.get() <= GRANBOND_BOND_STORE_CHUNK,
                        "a chunk of {}",
                        count.get()
                    );
                }
                let broken = fs::granbond_bond_store_broken_count(st);
                self.answer_value("granbond_bond_store_broken_count");
                let mut b = Place::new(BrokenBond::default());
                let k = if input.below(4) == 3 { input.usize() } else { 0 };
                let status = fs::granbond_bond_store_broken(st, k.min(broken), b.ptr(input.late_pointer()));
                ok(self, "granbond_bond_store_broken", status);
                let status = fs::granbond_bond_store_finish_pass(st);
                ok(self, "granbond_bond_store_finish_pass", status);
            }
            let mut counts = Place::new(StoreCounts::default());
            let status = fs::granbond_bond_store_counts(st, counts.ptr(input.late_pointer()));
            if ok(self, "granbond_bond_store_counts", status) && linked {
                let c = counts.get();
                assert_eq!(
                    c.created,
                    c.broken() + c.intact + c.lost(),
                    "the store's counts: {c:?}"
                );
            }
            self.ledger_counts(&counts.get());
            let mut keys = vec![f64::NAN; 2 * fs::granbond_bond_store_len(st)];
            let (mut written, mut found) = (usize::MAX, std::mem::zeroed::<CheckReport>());
            let status = fl::granbond_bond_store_check_keys(
                st,
                &wide_ids,
                nlocal,
                keys.as_mut_ptr(),
                keys.len(),
                &mut written,
                &mut found,
            );
            if self.answer("granbond_bond_store_check_keys", status) && found.level == 0 {
                assert_eq!(
                    2 * written,
                    keys.len(),
                    "granbond_bond_store_check_keys: a key a bond"
                );
                assert!(
                    keys.chunks(2).all(|k| k[0] <= k[1]),
                    "granbond_bond_store_check_keys: the lower id first"
                );
            }
            // the flag of the pair of the first and the last atom, set as
            // the keys' count says
            let status =
                fl::granbond_bond_store_check_flag(st, 0, n - 1, &wide_ids, (written % 2) as i32, &mut found);
            if self.answer("granbond_bond_store_check_flag", status) {
                assert!(
                    found.level == 0 || found.level == 1,
                    "granbond_bond_store_check_flag: level {}",
                    found.level
                );
            }
            let held = fs::granbond_bond_store_len(st);
            self.answer_value("granbond_bond_store_len");
            let mut energy = Place::new(f64::NAN);
            let status = fs::granbond_bond_store_stored_energy(
                st,
                models.as_ptr(),
                1 + input.below(2),
                &arrays,
                energy.ptr(input.late_pointer()),
            );
            if ok(self, "granbond_bond_store_stored_energy", status) {
                assert!(!energy.get().is_nan(), "stored energy NaN");
            }
            let mut sums = Place::new(EnergySums::default());
            let status = fs::granbond_bond_store_energy_sums(st, sums.ptr(Pointer::Valid));
            ok(self, "granbond_bond_store_energy_sums", status);
            let mut bond_energy = [f64::NAN; 3];
            let status = fs::granbond_bond_store_bond_energy(
                st,
                models.as_ptr(),
                2,
                &arrays,
                0,
                bond_energy.as_mut_ptr(),
            );
            ok(self, "granbond_bond_store_bond_energy", status);
            let mut shares = [0.0f64; 2 * 7];
            let status = fs::granbond_bond_store_add_dissipated_shares(
                st,
                models.as_ptr(),
                2,
                Self::batch_ptr(&mut shares, input.late_pointer()),
                input.below(3),
                7,
                input.below(3),
            );
            if ok(self, "granbond_bond_store_add_dissipated_shares", status) {
                assert!(
                    shares.iter().all(|s| s.is_finite()),
                    "shares not finite: {shares:?}"
                );
            }
            let _ = fs::granbond_bond_store_bytes(st);
            self.answer_value("granbond_bond_store_bytes");
            let mut bond_ends = [0i32; 3];
            let mut partner = Place::new(0i64);
            let mut state = [0.0f64; BOND_STATE_LEN + 1];
            let status = fs::granbond_bond_store_bond(
                st,
                input.below(held + 1),
                Self::batch_ptr(&mut bond_ends, input.late_pointer()),
                partner.ptr(input.late_pointer()),
                Self::batch_ptr(&mut state, input.late_pointer()),
            );
            ok(self, "granbond_bond_store_bond", status);

            // the view: this rank's rows unpacked at ghost images of its atoms
            let width = fs::granbond_bond_store_view_width(st);
            self.answer_value("granbond_bond_store_view_width");
            let mut row = vec![0.0f64; width + 1];
            let narrow = if input.below(8) == 7 {
                input.below(width + 1)
            } else {
                width
            };
            let status = fs::granbond_bond_store_clear_view(st);
            ok(self, "granbond_bond_store_clear_view", status);
            for a in 0..n {
                let status = fs::granbond_bond_store_pack_view(
                    st,
                    a,
                    Self::batch_ptr(&mut row, input.late_pointer()),
                    narrow,
                );
                ok(self, "granbond_bond_store_pack_view", status);
                if input.below(8) == 7 {
                    row[input.below(width + 1)] = input.f64();
                }
                let status = fs::granbond_bond_store_unpack_view(
                    st,
                    (a + 1) % n,
                    Self::batch_ptr(&mut row, input.late_pointer()),
                    narrow,
                    &wide_ids,
                    nlocal,
                );
                ok(self, "granbond_bond_store_unpack_view", status);
            }
            let status = fs::granbond_bond_store_finish_view(st);
            ok(self, "granbond_bond_store_finish_view", status);
            let mut counts = vec![0u32; nlocal + 1];
            let status = fs::granbond_bond_store_count_atoms(
                st,
                Self::batch_ptr(&mut counts, input.late_pointer()),
                nlocal,
                &wide_ids,
            );
            if ok(self, "granbond_bond_store_count_atoms", status) {
                // each bond counts at most twice on a rank, once an end
                let held = fs::granbond_bond_store_len(st);
                let total: u32 = counts[..nlocal].iter().sum();
                assert!(
                    total as usize <= 2 * held + n * n,
                    "counts {counts:?} of {held} bonds"
                );
            }
            let bonded =
                fs::granbond_bond_store_bonded(st, input.below(n + 1), input.below(n + 1), &wide_ids);
            self.answer_value("granbond_bond_store_bonded");
            assert!(matches!(bonded, 0 | 1), "bonded {bonded}");
            let k = self.kinematics(input);
            let mut creates = Place::new(-1i32);
            let status = fs::granbond_bond_store_would_create(
                st,
                model,
                input.below(n + 1),
                input.below(n + 1),
                &k,
                input.step(),
                creates.ptr(input.late_pointer()),
            );
            if ok(self, "granbond_bond_store_would_create", status) {
                assert!(matches!(creates.get(), 0 | 1), "creates {}", creates.get());
            }

            // an atom migrates to a second store
            let leaving = input.below(n + 1);
            let len = fs::granbond_bond_store_packed_len(st, leaving);
            self.answer_value("granbond_bond_store_packed_len");
            let most = fs::granbond_bond_store_most_packed_len(st);
            self.answer_value("granbond_bond_store_most_packed_len");
            assert!(len <= most.max(2), "packed {len}, most {most}");
            let mut buf = vec![0.0f64; len + 1];
            let capacity = if input.below(8) == 7 {
                input.below(len + 1)
            } else {
                len
            };
            let mut written = Place::new(0usize);
            let status = fs::granbond_bond_store_pack(
                st,
                leaving,
                input.below(2) as i32,
                Self::batch_ptr(&mut buf, input.late_pointer()),
                capacity,
                written.ptr(input.late_pointer()),
            );
            let packed = ok(self, "granbond_bond_store_pack", status);
            let mut other = Place::new(null_mut::<granbond::bond_store::BondStore>());
            if self.answer(
                "granbond_bond_store_new",
                fs::granbond_bond_store_new(other.ptr(Pointer::Valid)),
            ) {
                let ot = other.get();
                let mut read = Place::new(0usize);
                let take = if packed {
                    written.get()
                } else {
                    input.below(len + 1)
                };
                if input.below(4) == 3 {
                    buf[input.below(len + 1)] = input.f64();
                }
                let mut head_len = Place::new(0usize);
                let status =
                    fs::granbond_bond_store_packed_len_in(buf.as_ptr(), 3, head_len.ptr(Pointer::Valid));
                if ok(self, "granbond_bond_store_packed_len_in", status) && packed {
                    assert_eq!(head_len.get(), written.get(), "packed_len_in of a packed atom");
                }
                let status = fs::granbond_bond_store_unpack(
                    ot,
                    input.below(n),
                    Self::batch_ptr(&mut buf, input.late_pointer()),
                    take,
                    read.ptr(input.late_pointer()),
                );
                ok(self, "granbond_bond_store_unpack", status);
                let mut fuzzed = StoreCounts::default();
                input.mutate(&mut fuzzed);
                let mut c = Place::new(fuzzed);
                let status = fs::granbond_bond_store_restore_counts(ot, c.ptr(input.late_pointer()));
                ok(self, "granbond_bond_store_restore_counts", status);
                let mut sums = Place::new(EnergySums::default());
                let status = fs::granbond_bond_store_restore_energy_sums(ot, sums.ptr(Pointer::Valid));
                ok(self, "granbond_bond_store_restore_energy_sums", status);
                fs::granbond_bond_store_free(ot);
                self.answer_value("granbond_bond_store_free");
            }
            // per-atom events, indices in range and beyond
            let (i, j) = (input.below(n + 2), input.below(n + 2));
            let status = fs::granbond_bond_store_copy(st, i, j);
            ok(self, "granbond_bond_store_copy", status);
            let status = fs::granbond_bond_store_clear(st, i);
            ok(self, "granbond_bond_store_clear", status);
            let status = fs::granbond_bond_store_set_seen(st, j, input.step());
            ok(self, "granbond_bond_store_set_seen", status);
            let _ = fs::granbond_bond_store_seen(st, i);
            self.answer_value("granbond_bond_store_seen");
            // the store linked from a listed topology, after all the above:
            // the chain's pairs, then one entry beyond the atoms (no input
            // of its own, so the corpus reads as before)
            let mut listed: Vec<ListedBond> = (1..nlocal.min(n))
                .map(|a| ListedBond {
                    owner: a as i32 - 1,
                    partner: a as i32,
                    kind: 0,
                })
                .collect();
            let mut report = Place::new(LinkReport::default());
            for _ in 0..2 {
                let status = fs::granbond_bond_store_link_listed(
                    st,
                    &wide_ids,
                    nlocal,
                    x.as_ptr(),
                    listed.as_ptr(),
                    listed.len(),
                    report.ptr(Pointer::Valid),
                );
                ok(self, "granbond_bond_store_link_listed", status);
                listed.push(ListedBond {
                    owner: nlocal as i32,
                    partner: 0,
                    kind: 0,
                });
            }
        }
        // SAFETY: from granbond_bond_store_new, not used again; null is allowed.
        unsafe {
            fs::granbond_bond_store_free(st);
            fs::granbond_bond_store_free(null_mut());
        }
        self.answer_value("granbond_bond_store_free");
    }

    fn wall_try_create(&mut self, input: &mut Input) {
        let m = self.bond_model(input);
        let sphere = self.sphere(input);
        let mut sp = Place::new(sphere);
        let mut point = Place::new([sphere.x[0] + sphere.radius, sphere.x[1], sphere.x[2]]);
        if input.below(3) == 0 {
            point = Place::new(input.vec3());
        }
        let step = input.step();
        let i = self.state(input);
        let mut created = Place::new(-7i32);
        let (h1, h2, h3, h4) = (input.pointer(), input.pointer(), input.pointer(), input.pointer());
        let before = self.pool[i];
        let s = self.state_ptr(i, h3);
        // SAFETY: null, misaligned or valid; the state holds
        // WALL_BOND_STATE_LEN doubles.
        let status = unsafe {
            fb::granbond_wall_bond_try_create(
                m,
                sp.ptr(h1),
                point.ptr(h2) as *const f64,
                step,
                s,
                created.ptr(h4),
            )
        };
        let function = "granbond_wall_bond_try_create";
        if self.answer(function, status) {
            let c = created.get();
            assert!(c == 0 || c == 1, "{function}: created = {c}");
            self.check_state_finite(function, i, WALL_BOND_STATE_LEN, &before);
        }
        // the same sphere, model and contact point through the wall-bond
        // store (no input read: the corpus reads on as before)
        self.wall_store(m, sphere, point.get(), step);
    }

    /// The wall-bond store: a sphere reported by two wall elements in a
    /// force pass at `step`, packed into a second store, linked, shown by a
    /// setup and an output pass, counted, cleared.
    fn wall_store(&mut self, m: *const BondModel, sphere: SphereKinematics, point: [f64; 3], step: i64) {
        let mut st = null_mut();
        // SAFETY (every call below): valid pointers; `st` and `ot` live
        // stores from granbond_wall_store_new until they are freed.
        unsafe {
            if !self.answer("granbond_wall_store_new", fw::granbond_wall_store_new(&mut st)) {
                return;
            }
            let grown = fw::granbond_wall_store_grow(st, 2);
            self.answer("granbond_wall_store_grow", grown);
            let contact = |element: i64, kind: i32| WallContact {
                atom: 0,
                id: 7,
                wall: 0,
                element,
                pass: step.wrapping_mul(2).wrapping_add(i64::from(kind == 1)),
                kind,
                step,
                dt: 1e-6,
                may_create: 1,
                sphere,
                wall_velocity: [0.0; 3],
                contact_point: point,
            };
            let visit = |s: &mut Self, st: *mut granbond::bond_store::WallStore, c: WallContact| {
                let mut v = WallVisit::default();
                let status = fw::granbond_wall_store_visit(st, m, &c, &mut v);
                if s.answer("granbond_wall_store_visit", status) {
                    assert!((0..=2).contains(&v.act) && (v.created == 0 || v.created == 1));
                    if v.act == 1 && c.kind == 0 {
                        s.check_bond_output("granbond_wall_store_visit", &v.out);
                    }
                }
            };
            visit(self, st, contact(1, 0));
            visit(self, st, contact(2, 0));
            let mut counts = StoreCounts::default();
            if self.answer(
                "granbond_wall_store_counts",
                fw::granbond_wall_store_counts(st, &mut counts),
            ) {
                assert_eq!(counts.created, counts.broken() + counts.intact + counts.lost());
            }
            let n = fw::granbond_wall_store_packed_len(st, 7);
            self.answer_value("granbond_wall_store_packed_len");
            assert!(n <= fw::granbond_wall_store_most_packed_len(st));
            self.answer_value("granbond_wall_store_most_packed_len");
            let mut buf = vec![0.0; n];
            let mut written = 0;
            let packed = fw::granbond_wall_store_pack(st, 0, 7, 0, buf.as_mut_ptr(), n, &mut written);
            let mut len = 0;
            if self.answer("granbond_wall_store_pack", packed) {
                let head = fw::granbond_wall_store_packed_len_in(buf.as_ptr(), 2, &mut len);
                if self.answer("granbond_wall_store_packed_len_in", head) {
                    assert_eq!(len, written);
                }
            }
            let mut ot = null_mut();
            if self.answer("granbond_wall_store_new", fw::granbond_wall_store_new(&mut ot)) {
                let grown = fw::granbond_wall_store_grow(ot, 1);
                self.answer("granbond_wall_store_grow", grown);
                let mut read = 0;
                let unpacked = fw::granbond_wall_store_unpack(ot, 0, 7, step, buf.as_ptr(), len, &mut read);
                self.answer("granbond_wall_store_unpack", unpacked);
                let ids = [7i64];
                let atoms = AtomIds {
                    narrow: null(),
                    wide: ids.as_ptr(),
                    count: 1,
                };
                let linked = fw::granbond_wall_store_link(ot, &atoms);
                self.answer("granbond_wall_store_link", linked);
                let map = [1i64, 0];
                let renumbered = fw::granbond_wall_store_renumber(ot, map.as_ptr(), map.len());
                self.answer("granbond_wall_store_renumber", renumbered);
                let back = fw::granbond_wall_store_renumber(ot, map.as_ptr(), map.len());
                self.answer("granbond_wall_store_renumber", back);
                let (mut keys, mut written) = ([0.0f64; 8], 0usize);
                let mut found = std::mem::zeroed::<CheckReport>();
                let listed = fl::granbond_wall_store_check_keys(
                    ot,
                    &atoms,
                    keys.as_mut_ptr(),
                    8,
                    &mut written,
                    &mut found,
                );
                if self.answer("granbond_wall_store_check_keys", listed) {
                    assert!(
                        (found.level == 0)
                            == (written == granbond::ffi::wall_store::granbond_wall_store_len(ot)),
                        "granbond_wall_store_check_keys: level {} with {written} keys",
                        found.level
                    );
                }
                let _ = fw::granbond_wall_store_len(ot);
                self.answer_value("granbond_wall_store_len");
                visit(self, ot, contact(2, 1));
                visit(self, ot, contact(1, 2));
                let restored = fw::granbond_wall_store_restore_counts(ot, &counts);
                self.answer("granbond_wall_store_restore_counts", restored);
                fw::granbond_wall_store_free(ot);
                self.answer_value("granbond_wall_store_free");
            }
            let copied = fw::granbond_wall_store_copy(st, 0, 1);
            self.answer("granbond_wall_store_copy", copied);
            let cleared = fw::granbond_wall_store_clear(st, 1);
            self.answer("granbond_wall_store_clear", cleared);
            let _ = fw::granbond_wall_store_bytes(st);
            self.answer_value("granbond_wall_store_bytes");
            let all = fw::granbond_wall_store_clear_all(st);
            self.answer("granbond_wall_store_clear_all", all);
            fw::granbond_wall_store_free(st);
            self.answer_value("granbond_wall_store_free");
        }
    }

    fn wall_compute(&mut self, input: &mut Input) {
        let m = self.bond_model(input);
        let mut sp = Place::new(self.sphere(input));
        let mut velocity = Place::new(match input.below(3) {
            0 => input.vec3(),
            _ => [0.0; 3],
        });
        let dt = self.dt(input);
        let i = self.state(input);
        let mut out = Place::new(BondOutput::default());
        let (h1, h2, h3, h4) = (input.pointer(), input.pointer(), input.pointer(), input.pointer());
        let before = self.pool[i];
        let s = self.state_ptr(i, h3);
        // SAFETY: as in wall_try_create.
        let status = unsafe {
            fb::granbond_wall_bond_compute(m, sp.ptr(h1), velocity.ptr(h2) as *const f64, dt, s, out.ptr(h4))
        };
        let function = "granbond_wall_bond_compute";
        if self.answer(function, status) {
            if all_finite(&before[..WALL_BOND_STATE_LEN]) {
                self.check_bond_output(function, &out.get());
            }
            self.check_state_finite(function, i, WALL_BOND_STATE_LEN, &before);
        }
        let mut recomputed = Place::new(-1i32);
        let s = self.state_ptr(i, h3);
        // SAFETY: as above; `recomputed` valid.
        let status = unsafe {
            fb::granbond_wall_bond_setup_compute(
                m,
                sp.ptr(h1),
                velocity.ptr(h2) as *const f64,
                dt,
                s,
                recomputed.ptr(Pointer::Valid),
                out.ptr(h4),
            )
        };
        if self.answer("granbond_wall_bond_setup_compute", status) && recomputed.get() == 1 {
            self.check_bond_output("granbond_wall_bond_setup_compute", &out.get());
        }
    }

    /// `granbond_bond_max_distance` and `_contact_distance_factor`.
    fn bond_reach(&mut self, input: &mut Input) {
        let m = self.bond_model(input);
        let length = match input.below(2) {
            0 => input.f64(),
            _ => 2e-3,
        };
        let mut out = Place::new(f64::NAN);
        let how = input.pointer();
        // SAFETY: null, misaligned or valid.
        let (function, status) = unsafe {
            let which = input.below(3);
            if which == 0 {
                let st = fb::granbond_bond_max_distance(m, length, out.ptr(how));
                ("granbond_bond_max_distance", st)
            } else if which == 2 {
                let st = fk::granbond_bond_neighbour_reach(m, length, 1, 1, 1, c"si".as_ptr(), out.ptr(how));
                ("granbond_bond_neighbour_reach", st)
            } else {
                let st = fb::granbond_bond_contact_distance_factor(m, length, out.ptr(how));
                ("granbond_bond_contact_distance_factor", st)
            }
        };
        if self.answer(function, status) {
            let d = out.get();
            // infinite is documented (a bond that never breaks); NaN is not
            assert!(d >= 0.0, "{function}({length}) = {d}");
        }
        // the same model and length, read no further from the input so the
        // corpus keeps its meaning: a break's limits at compression
        // `length`, and the fields of a bond created at 2e-3 whose centres
        // are `length` apart
        self.stress_limits(m, length);
        self.bond_fields(m, length);
        self.break_log(m, length);
    }

    /// The break log's event of a bond of `m` that broke at compression
    /// `delta` between spheres `delta` apart (no input read), its line, and
    /// the words of the log's fix with `delta` as the interval.
    fn break_log(&mut self, m: *const BondModel, delta: f64) {
        let out = BondOutput {
            delta,
            sigma: 1e6,
            tau: 2e5,
            break_mode: 2,
            ..Default::default()
        };
        let (x_i, x_j) = ([delta, 0.0, 0.0], [0.0; 3]);
        let mut e = BreakEvent::default();
        // SAFETY: the model pointer as the driver keeps it; valid others.
        let status = unsafe {
            fl::granbond_break_event(
                m,
                &out,
                x_i.as_ptr(),
                x_j.as_ptr(),
                1e-3,
                1e-3,
                7.0,
                3.0,
                10.0,
                &mut e,
            )
        };
        if self.answer("granbond_break_event", status) {
            assert!(
                e.tag_i == 3.0 && e.tag_j == 7.0,
                "granbond_break_event: the smaller id first"
            );
        }
        // a step that is no integer is refused
        e.step = if delta.is_finite() { delta.abs() } else { 10.0 };
        let mut events = [e, e];
        let mut text = vec![0 as c_char; 3 * fl::GRANBOND_BREAK_LOG_LINE_LEN];
        // SAFETY: two events; a buffer of its length.
        let status =
            unsafe { fl::granbond_break_log_text(events.as_mut_ptr(), 2, 1, text.as_mut_ptr(), text.len()) };
        if self.answer("granbond_break_log_text", status) {
            let t = unsafe { CStr::from_ptr(text.as_ptr()) }
                .to_string_lossy()
                .into_owned();
            assert_eq!(
                t.lines().count(),
                3,
                "granbond_break_log_text: the header and two lines: {t}"
            );
        }
        let every = std::ffi::CString::new(format!("{delta}")).unwrap();
        let words = [
            c"log".as_ptr(),
            c"all".as_ptr(),
            c"bond/breaklog".as_ptr(),
            c"f".as_ptr(),
            c"every".as_ptr(),
            every.as_ptr(),
        ];
        let mut n = -1i32;
        let count = if delta > 0.0 { 6 } else { 4 };
        // SAFETY: `count` valid words; a valid output.
        let status = unsafe { fl::granbond_break_log_words(words.as_ptr(), count, &mut n) };
        if self.answer("granbond_break_log_words", status) {
            assert!(n >= 1, "granbond_break_log_words: every {n}");
        }
    }

    /// What the ledger makes of a store's counts (no input read): the row,
    /// a notice (an id out of range where the counts say so) and the
    /// store check's findings.
    fn ledger_counts(&mut self, c: &StoreCounts) {
        let mut row = [f64::NAN; fl::GRANBOND_COUNTS_ROW_LEN];
        // SAFETY: valid counts and row.
        let status = unsafe { fl::granbond_store_counts_row(c, row.as_mut_ptr()) };
        if self.answer("granbond_store_counts_row", status) {
            assert_eq!(
                row[0], c.created as f64,
                "granbond_store_counts_row: created first"
            );
        }
        // the counts through a restart file's record (a short buffer where
        // the counts say so, a damaged length where they say so), and back
        let energy = granbond::bond_store::EnergySums {
            damping: c.created as f64,
            hysteresis: 0.5,
            released: f64::NAN,
        };
        let mut record = [0u8; fl::GRANBOND_STORE_RECORD_LEN];
        let capacity = if c.intact % 5 == 4 { 8 } else { record.len() };
        // SAFETY: valid counts, energy and `capacity` bytes.
        let status = unsafe { fl::granbond_store_record_write(c, &energy, record.as_mut_ptr(), capacity) };
        if self.answer("granbond_store_record_write", status) {
            if c.lost() % 4 == 3 {
                record[0] ^= 1;
            }
            let (mut back, mut energy_back) = (
                StoreCounts::default(),
                granbond::bond_store::EnergySums::default(),
            );
            // SAFETY: a whole record; valid outputs.
            let status =
                unsafe { fl::granbond_store_record_read(record.as_ptr(), &mut back, &mut energy_back) };
            if self.answer("granbond_store_record_read", status) {
                assert_eq!(back, *c, "granbond_store_record_read: the counts bit for bit");
                assert_eq!(energy_back.damping.to_bits(), energy.damping.to_bits());
            }
        }
        let lost = [
            c.lost_owner_gone,
            c.lost_partner_unreached,
            c.lost_id_reused,
            c.lost_no_model,
        ];
        let mut report = unsafe { std::mem::zeroed::<CheckReport>() };
        // SAFETY: four counts, a valid name and report.
        let status = unsafe {
            fl::granbond_ledger_notice(
                (c.created % 7) as i32,
                lost.as_ptr(),
                c.intact,
                c"wall".as_ptr(),
                &mut report,
            )
        };
        if self.answer("granbond_ledger_notice", status) {
            assert!(
                report.level == 0 || report.level == 1,
                "granbond_ledger_notice: level {}",
                report.level
            );
        }
        let mut keys = [
            c.created as f64,
            c.intact as f64,
            c.created as f64,
            (c.intact % 2) as f64,
        ];
        let sums = [c.created, c.broken(), c.intact, c.lost()];
        // SAFETY: two keys, four sums, a valid report.
        let status = unsafe {
            fl::granbond_store_check_findings(
                keys.as_mut_ptr(),
                2,
                sums.as_ptr(),
                (c.lost() % 3) as i32,
                &mut report,
            )
        };
        if self.answer("granbond_store_check_findings", status) {
            assert!(
                report.level == 0 || report.level == 1,
                "granbond_store_check_findings: level {}",
                report.level
            );
        }
    }

    fn stress_limits(&mut self, m: *const BondModel, delta: f64) {
        let (mut sigma_max, mut tau_max) = (f64::NAN, f64::NAN);
        // SAFETY: the model pointer as the driver keeps it; valid outputs.
        let status = unsafe { granbond_bond_stress_limits(m, delta, &mut sigma_max, &mut tau_max) };
        if self.answer("granbond_bond_stress_limits", status) {
            assert!(
                sigma_max >= 0.0 && tau_max >= 0.0,
                "granbond_bond_stress_limits({delta}) = {sigma_max}, {tau_max}"
            );
        }
    }

    fn bond_fields(&mut self, m: *const BondModel, distance: f64) {
        // the state, then the output slots (all zero: no pass wrote them)
        let mut record = vec![0.0; BOND_STATE_LEN + BOND_OUTPUT_LEN];
        record[..BOND_STATE_LEN].copy_from_slice(BondState::created(2e-3).as_slots());
        let (x_i, x_j) = ([distance, 0.0, 0.0], [0.0; 3]);
        let mut values = vec![f64::NAN; BOND_FIELD_COUNT];
        // SAFETY: the model pointer as the driver keeps it; valid buffers.
        let status = unsafe {
            granbond_bond_fields(
                m,
                record.as_ptr(),
                x_i.as_ptr(),
                x_j.as_ptr(),
                values.as_mut_ptr(),
            )
        };
        if self.answer("granbond_bond_fields", status) {
            assert!(distance != 0.0, "granbond_bond_fields: OK for coincident centres");
            self.note_finite("granbond_bond_fields", all_finite(&values));
            assert_eq!(
                values[0], 1.0,
                "granbond_bond_fields: the status of an intact bond"
            );
        }
        self.bond_columns(m, &record, x_i, x_j, distance);
    }

    /// The columns of a per-bond output of the same bond (no input read):
    /// keywords, or LIGGGHTS-INL's layout where `distance` is negative.
    fn bond_columns(
        &mut self,
        m: *const BondModel,
        record: &[f64],
        x_i: [f64; 3],
        x_j: [f64; 3],
        distance: f64,
    ) {
        let words = [
            c"id".as_ptr(),
            c"all".as_ptr(),
            c"energy_stored".as_ptr(),
            c"no_such_column".as_ptr(),
        ];
        let (count, inl) = match distance {
            d if d < 0.0 => (0, 1),
            d if d > 1.0 => (4, 0),
            _ => (3, 0),
        };
        let mut columns: *mut granbond::ledger::columns::BondColumns = null_mut();
        // SAFETY: `count` valid words; a valid output.
        let status = unsafe { fl::granbond_bond_columns_new(words.as_ptr(), count, inl, &mut columns) };
        if !self.answer("granbond_bond_columns_new", status) {
            return;
        }
        let (mut n, mut energy) = (0usize, -1i32);
        // SAFETY: columns from granbond_bond_columns_new; valid outputs.
        let status = unsafe { fl::granbond_bond_columns_info(columns, &mut n, &mut energy) };
        if self.answer("granbond_bond_columns_info", status) {
            assert!(
                n > 0 && (energy == 1) == (inl == 0),
                "granbond_bond_columns_info: {n} columns, energy {energy}"
            );
        }
        let energies = [0.5; BOND_ENERGY_FIELD_COUNT];
        let mut row = vec![f64::NAN; n];
        // SAFETY: as above; buffers of their documented lengths.
        let status = unsafe {
            fl::granbond_bond_columns_row(
                columns,
                m,
                record.as_ptr(),
                energies.as_ptr(),
                1.0,
                2.0,
                x_i.as_ptr(),
                x_j.as_ptr(),
                row.as_mut_ptr(),
            )
        };
        if self.answer("granbond_bond_columns_row", status) && inl == 0 {
            assert_eq!(&row[..2], &[1.0, 2.0], "granbond_bond_columns_row: the ids first");
        }
        // SAFETY: from granbond_bond_columns_new, not used again.
        unsafe { fl::granbond_bond_columns_free(columns) };
        self.answer_value("granbond_bond_columns_free");
    }

    /// The three time-step estimates.
    fn timestep(&mut self, input: &mut Input) {
        let which = input.below(3);
        let bodies: Vec<f64> = (0..4)
            .map(|b| match input.below(3) {
                0 => input.f64(),
                _ => [1e-3, 1.3e-3, 1e-5, 2e-5][b],
            })
            .collect();
        let mut out = Place::new(f64::NAN);
        let how = input.pointer();
        let (r1, r2, m1, m2) = (bodies[0], bodies[1], bodies[2], bodies[3]);
        let (mut voigt, mut bond) = (null(), null());
        let (function, status) = if which == 2 {
            let m = self.voigt_model(input);
            voigt = m;
            // SAFETY: null, misaligned or valid.
            let st = unsafe { fc::granbond_voigt_critical_timestep(m, r1, r2, m1, m2, out.ptr(how)) };
            ("granbond_voigt_critical_timestep", st)
        } else {
            let m = self.bond_model(input);
            bond = m;
            // SAFETY: null, misaligned or valid.
            unsafe {
                if which == 0 {
                    let st = fb::granbond_bond_critical_timestep(m, r1, r2, m1, m2, out.ptr(how));
                    ("granbond_bond_critical_timestep", st)
                } else {
                    let st = fb::granbond_bond_recommended_timestep(m, r1, r2, m1, m2, out.ptr(how));
                    ("granbond_bond_recommended_timestep", st)
                }
            }
        };
        if self.answer(function, status) {
            let dt = out.get();
            // infinite: a model without stiffness has no limit
            assert!(dt > 0.0, "{function}({bodies:?}) = {dt}");
        }
        self.run_check(which, bond, voigt, &bodies, how);
    }

    /// The run checks over one atom type with the model (`bond` or `voigt`)
    /// and bodies the estimate just had (no input read: the corpus decodes as before):
    /// `which` 0 the bond time-step check, 1 the creation check, 2 the
    /// Voigt time-step check.
    fn run_check(
        &mut self,
        which: usize,
        bond: *const BondModel,
        voigt: *const VoigtModel,
        bodies: &[f64],
        how: Pointer,
    ) {
        let types = [
            TypeBodies::none(),
            TypeBodies {
                radius_min: bodies[0],
                radius_max: bodies[1],
                mass_min: bodies[2],
            },
        ];
        let mut report = Place::new(unsafe { std::mem::zeroed::<CheckReport>() });
        let style = c"fuzz";
        let dt = bodies[3];
        // SAFETY: tables of (1 + 1)^2 models and 2 bodies; null, misaligned or valid report.
        let (function, status) = unsafe {
            match which {
                2 => {
                    let table = [null(), null(), null(), voigt];
                    let st = fk::granbond_voigt_timestep_check(
                        table.as_ptr(),
                        1,
                        types.as_ptr(),
                        dt,
                        c"si".as_ptr(),
                        style.as_ptr(),
                        report.ptr(how),
                    );
                    ("granbond_voigt_timestep_check", st)
                }
                _ => {
                    let table = [null(), null(), null(), bond];
                    if which == 0 {
                        let st = fk::granbond_bond_timestep_check(
                            table.as_ptr(),
                            1,
                            types.as_ptr(),
                            dt,
                            0,
                            c"si".as_ptr(),
                            style.as_ptr(),
                            report.ptr(how),
                        );
                        ("granbond_bond_timestep_check", st)
                    } else {
                        let st = fk::granbond_bond_creation_check(
                            table.as_ptr(),
                            1,
                            types.as_ptr(),
                            0,
                            0,
                            0,
                            0,
                            c"si".as_ptr(),
                            style.as_ptr(),
                            report.ptr(how),
                        );
                        ("granbond_bond_creation_check", st)
                    }
                }
            }
        };
        if self.answer(function, status) {
            let r = report.get();
            let text = unsafe { std::ffi::CStr::from_ptr(r.message.as_ptr()) }
                .to_string_lossy()
                .into_owned();
            assert!(
                r.level >= 0 && (r.level == 0) == text.is_empty(),
                "{function}: level {} message \"{text}\"",
                r.level
            );
            if which != 1 {
                assert!(
                    r.level <= 2 && (r.critical > 0.0),
                    "{function}: level {} critical {}",
                    r.level,
                    r.critical
                );
            }
        }
        // a periodic box of the bodies' sizes against a reach of their
        // radii (no input read)
        let length = [bodies[0], bodies[1], bodies[3]];
        let periodic = [1, 0, 1];
        let dimension = 2 + which.min(1) as i32;
        // SAFETY: valid style, three flags, three lengths; null, misaligned or valid report.
        let status = unsafe {
            fl::granbond_thin_periodic_box_check(
                c"fuzz".as_ptr(),
                dimension,
                periodic.as_ptr(),
                length.as_ptr(),
                bodies[2],
                bodies[2] * 0.1,
                -1,
                report.ptr(how),
            )
        };
        if self.answer("granbond_thin_periodic_box_check", status) {
            let r = report.get();
            assert!(
                r.level == 0 || r.level == 1,
                "granbond_thin_periodic_box_check: level {}",
                r.level
            );
        }
    }

    fn voigt_compute(&mut self, input: &mut Input) {
        let m = self.voigt_model(input);
        let mut k = Place::new(self.kinematics(input));
        let dt = self.dt(input);
        let i = self.state(input);
        let mut out = Place::new(ContactOutput::default());
        let (hk, hs, ho) = (input.pointer(), input.pointer(), input.pointer());
        let before = self.pool[i];
        let s = self.state_ptr(i, hs);
        // SAFETY: null, misaligned or valid; the state holds CONTACT_STATE_LEN.
        let status = unsafe { fc::granbond_voigt_compute(m, k.ptr(hk), dt, s, out.ptr(ho)) };
        let function = "granbond_voigt_compute";
        if self.answer(function, status) {
            if all_finite(&before[..CONTACT_STATE_LEN]) {
                self.check_contact_output(function, &out.get());
            }
            self.check_state_finite(function, i, CONTACT_STATE_LEN, &before);
        }
    }

    /// The checked evaluation of a stored state, then an unchecked step of it.
    fn voigt_evaluate_then_step(&mut self, input: &mut Input) {
        let Some(m) = self.live_voigt_model(input) else {
            return;
        };
        let f = self.frame(input);
        let dt = self.dt(input);
        let i = self.state(input);
        let s = self.pool[i].as_mut_ptr();
        let before = self.pool[i];
        let mut evaluated = ContactOutput::default();
        // SAFETY: every pointer valid; the state is only read.
        let status = unsafe { fc::granbond_voigt_evaluate_frame(m, &f, s as *const f64, &mut evaluated) };
        if self.answer("granbond_voigt_evaluate_frame", status) {
            self.check_contact_output("granbond_voigt_evaluate_frame", &evaluated);
            assert_eq!(
                self.pool[i].map(f64::to_bits),
                before.map(f64::to_bits),
                "evaluate wrote the state"
            );
        }
        self.unchecked(m, &f, dt, s);
    }

    fn voigt_unchecked(&mut self, input: &mut Input) {
        let Some(m) = self.live_voigt_model(input) else {
            return;
        };
        let f = self.frame(input);
        let dt = self.dt(input);
        let i = self.state(input);
        let s = self.pool[i].as_mut_ptr();
        self.unchecked(m, &f, dt, s);
    }

    /// The contact of `f` as the engines hand it over: separation or normal
    /// and distance, with the radii (a wall as radius 0).
    fn unchecked(&mut self, m: *const VoigtModel, f: &ContactFrame, dt: f64, s: *mut f64) {
        let mut out = ContactOutput::default();
        let distance = f.lever_i + f.lever_j - f.overlap;
        let del = [f.n[0] * distance, f.n[1] * distance, f.n[2] * distance];
        let rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
        // SAFETY: `s` is the start of a state of the pool.
        let mut copy = unsafe { *(s as *const Entry) };
        // SAFETY: as above; `del` three doubles, `copy` a whole state.
        let status = unsafe {
            fcg::granbond_voigt_compute_separation_unchecked(
                m,
                del.as_ptr(),
                rsq,
                f.lever_i,
                f.lever_j,
                f.v_i.as_ptr(),
                f.v_j.as_ptr(),
                f.w_i.as_ptr(),
                f.w_j.as_ptr(),
                dt,
                copy.as_mut_ptr(),
                &mut out,
            )
        };
        if rsq > 0.0 && self.answer_unchecked("granbond_voigt_compute_separation_unchecked", status) {
            self.check_unchecked_flags(&out);
        }
        // the pool's state itself is advanced by this one
        // SAFETY: every pointer valid (the entry's contract); `s` a whole state.
        let status = unsafe {
            fcg::granbond_voigt_compute_normal_unchecked(
                m,
                f.n.as_ptr(),
                distance,
                f.lever_i,
                f.lever_j,
                f.v_i.as_ptr(),
                f.v_j.as_ptr(),
                f.w_i.as_ptr(),
                f.w_j.as_ptr(),
                dt,
                s,
                &mut out,
            )
        };
        if self.answer_unchecked("granbond_voigt_compute_normal_unchecked", status) {
            self.check_unchecked_flags(&out);
        }
    }

    fn check_unchecked_flags(&self, o: &ContactOutput) {
        for flag in [o.touching, o.sliding, o.rolling_slip] {
            assert!(
                flag == 0 || flag == 1,
                "unchecked Voigt entry: flag {flag} in {o:?}"
            );
        }
        let loads: Vec<f64> = o
            .force_i
            .iter()
            .chain(&o.torque_i)
            .chain(&o.torque_j)
            .copied()
            .collect();
        assert!(all_finite(&loads), "unchecked Voigt entry: OK with loads {o:?}");
    }

    /// The frames the engines' geometry entries build: from the separation
    /// of a pair or from a normal and a distance (a wall as radius 0).
    fn frames(&mut self, input: &mut Input) {
        let k = Place::new(self.kinematics(input));
        let mut f = Place::new(ContactFrame::default());
        // the frame from the separation or from a normal and a distance
        let kin = k.get();
        let mut del = Place::new([
            kin.x_i[0] - kin.x_j[0],
            kin.x_i[1] - kin.x_j[1],
            kin.x_i[2] - kin.x_j[2],
        ]);
        let rsq = del.get().iter().map(|d| d * d).sum::<f64>();
        let radius_j = if input.below(4) == 0 { 0.0 } else { kin.radius_j };
        let mut v = Place::new(kin.v_i);
        let (hd, hv, hf) = (input.pointer(), input.pointer(), input.pointer());
        // SAFETY: null, misaligned or valid.
        let status = unsafe {
            fcg::granbond_contact_frame_separation(
                del.ptr(hd) as *const f64,
                rsq,
                kin.radius_i,
                radius_j,
                v.ptr(hv) as *const f64,
                kin.v_j.as_ptr(),
                kin.w_i.as_ptr(),
                kin.w_j.as_ptr(),
                f.ptr(hf),
            )
        };
        if self.answer("granbond_contact_frame_separation", status) {
            // not a checked frame: a seed for the frames drawn next
            self.frame = f.get();
        }
        let n = self.frame.n;
        let (hv, hf) = (input.pointer(), input.pointer());
        // SAFETY: null, misaligned or valid.
        let status = unsafe {
            fcg::granbond_contact_frame_normal(
                n.as_ptr(),
                rsq.sqrt(),
                kin.radius_i,
                radius_j,
                v.ptr(hv) as *const f64,
                kin.v_j.as_ptr(),
                kin.w_i.as_ptr(),
                kin.w_j.as_ptr(),
                f.ptr(hf),
            )
        };
        self.answer("granbond_contact_frame_normal", status);
    }

    fn voigt_normal_force(&mut self, input: &mut Input) {
        let m = self.voigt_model(input);
        let mut f = Place::new(self.frame(input));
        let mut out = Place::new(f64::NAN);
        let (h1, h2) = (input.pointer(), input.pointer());
        // SAFETY: null, misaligned or valid.
        let status = unsafe { fc::granbond_voigt_normal_force(m, f.ptr(h1), out.ptr(h2)) };
        if self.answer("granbond_voigt_normal_force", status) {
            self.note_finite("granbond_voigt_normal_force", out.get().is_finite());
        }
    }

    fn normal_force(&mut self, input: &mut Input) -> f64 {
        match input.below(3) {
            0 => input.f64(),
            _ => 1e-3,
        }
    }

    fn voigt_tangential(&mut self, input: &mut Input) {
        let m = self.voigt_model(input);
        let mut f = Place::new(self.frame(input));
        let fn_ = self.normal_force(input);
        let dt = self.dt(input);
        let i = self.state(input);
        let mut out = Place::new(TangentialOutput::default());
        let (h1, h2, h3) = (input.pointer(), input.pointer(), input.pointer());
        let before = self.pool[i];
        let spring = self.state_ptr(i, h2);
        // SAFETY: null, misaligned or valid; the spring holds 3 doubles.
        // The stored spring, not advanced, with the same pointers (no input
        // consumed: the corpus decodes as before).
        let mut evaluated = Place::new(TangentialOutput::default());
        // SAFETY: as below; the spring is only read.
        let status = unsafe {
            fc::granbond_voigt_tangential_evaluate(m, f.ptr(h1), fn_, spring as *const f64, evaluated.ptr(h3))
        };
        if self.answer("granbond_voigt_tangential_evaluate", status) {
            assert!(evaluated.get().sliding == 0 || evaluated.get().sliding == 1);
            assert_eq!(
                self.pool[i].map(f64::to_bits),
                before.map(f64::to_bits),
                "evaluate wrote the spring"
            );
        }
        let status = unsafe { fc::granbond_voigt_tangential(m, f.ptr(h1), fn_, dt, spring, out.ptr(h3)) };
        let function = "granbond_voigt_tangential";
        if self.answer(function, status) {
            let o = out.get();
            assert!(o.sliding == 0 || o.sliding == 1);
            if all_finite(&before[..3]) {
                let loads: Vec<f64> = o
                    .force_i
                    .iter()
                    .chain(&o.torque_i)
                    .chain(&o.torque_j)
                    .copied()
                    .collect();
                self.note_finite(function, all_finite(&loads));
            }
            self.check_state_finite(function, i, 3, &before);
        }
    }

    fn voigt_rolling(&mut self, input: &mut Input) {
        let m = self.voigt_model(input);
        let mut f = Place::new(self.frame(input));
        let fn_ = self.normal_force(input);
        let dt = self.dt(input);
        let i = self.state(input);
        let mut torque = Place::new([f64::NAN; 3]);
        let mut slip = Place::new(-7i32);
        let (h1, h2, h3, h4) = (input.pointer(), input.pointer(), input.pointer(), input.pointer());
        let before = self.pool[i];
        let angle = self.state_ptr(i, h2);
        let mut evaluated = Place::new([f64::NAN; 3]);
        let mut evaluated_slip = Place::new(-7i32);
        // SAFETY: as below; the angle is only read (no input consumed).
        let status = unsafe {
            fc::granbond_voigt_rolling_evaluate(
                m,
                f.ptr(h1),
                fn_,
                angle as *const f64,
                evaluated.ptr(h3) as *mut f64,
                evaluated_slip.ptr(h4),
            )
        };
        if self.answer("granbond_voigt_rolling_evaluate", status) {
            assert!(evaluated_slip.get() == 0 || evaluated_slip.get() == 1);
            assert_eq!(
                self.pool[i].map(f64::to_bits),
                before.map(f64::to_bits),
                "evaluate wrote the angle"
            );
        }
        // SAFETY: null, misaligned or valid; angle and torque hold 3 doubles.
        let status = unsafe {
            fc::granbond_voigt_rolling(
                m,
                f.ptr(h1),
                fn_,
                dt,
                angle,
                torque.ptr(h3) as *mut f64,
                slip.ptr(h4),
            )
        };
        let function = "granbond_voigt_rolling";
        if self.answer(function, status) {
            assert!(
                slip.get() == 0 || slip.get() == 1,
                "{function}: slip {}",
                slip.get()
            );
            if all_finite(&before[..3]) {
                self.note_finite(function, all_finite(&torque.get()));
            }
            self.check_state_finite(function, i, 3, &before);
        }
    }

    fn layout(&mut self, input: &mut Input) {
        assert_eq!(abi::granbond_abi_version(), abi::GRANBOND_ABI_VERSION);
        self.answer_value("granbond_abi_version");
        let mut l = library_layout();
        let mutated = input.below(2) == 0;
        if mutated {
            input.mutate(&mut l);
        }
        let mut p = Place::new(l);
        let how = input.pointer();
        // SAFETY: null, misaligned or valid for a whole Layout.
        let status = unsafe { abi::granbond_check_layout(p.ptr(how) as *const Layout) };
        if self.answer("granbond_check_layout", status) {
            assert_eq!(
                l,
                library_layout(),
                "granbond_check_layout accepted a different layout"
            );
        } else if how == Pointer::Valid {
            assert_ne!(
                l,
                library_layout(),
                "granbond_check_layout refused the library's own layout"
            );
        }
    }

    fn state_layout(&mut self, input: &mut Input) {
        let kind = input.i32();
        self.field_table(kind);
        let len = granbond_state_len(kind);
        let want = match kind {
            0 => BOND_STATE_LEN,
            1 => WALL_BOND_STATE_LEN,
            2 => CONTACT_STATE_LEN,
            3 => BOND_OUTPUT_LEN,
            _ => 0,
        };
        assert_eq!(len, want, "granbond_state_len({kind})");
        self.answer_value("granbond_state_len");
        let index = input.usize();
        let mut name = Place::new(null::<c_char>());
        let mut flips = Place::new(-7i32);
        let (h1, h2) = (input.pointer(), input.pointer());
        // SAFETY: null, misaligned or valid.
        let status = unsafe { granbond_state_slot(kind, index, name.ptr(h1), flips.ptr(h2)) };
        if self.answer("granbond_state_slot", status) {
            assert!(index < len, "granbond_state_slot: OK for slot {index} of {len}");
            assert!(flips.get() == 0 || flips.get() == 1);
            // SAFETY: static NUL-terminated storage of the library.
            let got = unsafe { CStr::from_ptr(name.get()) };
            assert!(!got.to_bytes().is_empty());
        }
    }

    /// Row `id` of the bond field table (`id` read no further from the
    /// input: the state kind drawn for the slot query).
    fn field_table(&mut self, id: i32) {
        let count = granbond_bond_field_count();
        assert_eq!(count, BOND_FIELD_COUNT, "granbond_bond_field_count");
        self.answer_value("granbond_bond_field_count");
        let (mut name, mut unit, mut description) = (null::<c_char>(), null::<c_char>(), null::<c_char>());
        let id = id as u32 as usize;
        // SAFETY: valid outputs.
        let status = unsafe { granbond_bond_field_info(id, &mut name, &mut unit, &mut description) };
        if self.answer("granbond_bond_field_info", status) {
            assert!(
                id < count,
                "granbond_bond_field_info: OK for field {id} of {count}"
            );
            // SAFETY: static NUL-terminated storage of the library.
            let got = unsafe { CStr::from_ptr(name) };
            assert_eq!(got.to_str().ok(), Some(BOND_FIELDS[id].name));
        }
        // the energy fields, by the same id
        let count = granbond_bond_energy_field_count();
        assert_eq!(count, BOND_ENERGY_FIELD_COUNT, "granbond_bond_energy_field_count");
        self.answer_value("granbond_bond_energy_field_count");
        // SAFETY: valid outputs.
        let status = unsafe { granbond_bond_energy_field_info(id, &mut name, &mut unit, &mut description) };
        if self.answer("granbond_bond_energy_field_info", status) {
            assert!(
                id < count,
                "granbond_bond_energy_field_info: OK for field {id} of {count}"
            );
            // SAFETY: static NUL-terminated storage of the library.
            let got = unsafe { CStr::from_ptr(name) };
            assert_eq!(got.to_str().ok(), Some(BOND_ENERGY_FIELDS[id].name));
        }
    }
}

/// Runs the calls `data` describes, checking every answer (panics on a
/// wrong one), and adds them to `tally`.
pub fn run(data: &[u8], tally: &mut Tally) {
    tally.inputs += 1;
    let mut input = Input::new(data);
    let mut session = Session::new(tally);
    while !input.done() {
        session.op(&mut input);
    }
    // the error record is reachable at every moment, also after the last call
    let _ = message();
    session.answer_value("granbond_last_error_message");
    let _ = granbond_last_error_parameter();
    session.answer_value("granbond_last_error_parameter");
}
