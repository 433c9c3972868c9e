//! One status type for every fallible call; the message of the last failure
//! on this thread is fetched by a separate call (as rustls-ffi does).

use super::entry;
use crate::contact::FrameError;
use crate::kinematics::KinematicsError;
use crate::parameters::ParameterError;
use std::cell::RefCell;
use std::ffi::{c_char, CString};
use std::sync::atomic::{AtomicBool, Ordering};

/// Result of every fallible ABI call.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// The call succeeded.
    Ok = 0,
    /// A required pointer argument was null.
    NullPointer = 1,
    /// A model parameter is out of range; see the message and
    /// `granbond_last_error_parameter`.
    InvalidParameter = 2,
    /// NaN or infinity in what the caller passed: positions, velocities,
    /// radii, a frame, a state or a number passed by value.
    NonFiniteInput = 3,
    /// The two centres coincide: the pair has no axis.
    CoincidentCentres = 4,
    /// A radius is zero or negative.
    NonPositiveRadius = 5,
    /// The caller was compiled against a different header.
    LayoutMismatch = 6,
    /// An argument other than a parameter struct is invalid (index, length).
    InvalidArgument = 7,
    /// A bug: the call panicked and was stopped at the boundary.
    Panic = 8,
    /// A pointer argument is not aligned for the type it points to.
    Misaligned = 9,
    /// The result came out NaN or infinite: finite input far outside the
    /// model's range, or (from an unchecked entry) non-finite input the
    /// caller let through. Nothing was written where the entry says so.
    NonFiniteResult = 10,
}

/// A failure on its way to the caller.
#[derive(Debug)]
pub struct Failure {
    /// What the call returns.
    pub status: Status,
    /// What `granbond_last_error_message` returns.
    pub message: String,
    /// The refused parameter's row in its model's table
    /// (`granbond_last_error_parameter`), or -1.
    pub parameter: i32,
}

impl Failure {
    /// A failure that names no parameter.
    pub fn new(status: Status, message: impl Into<String>) -> Self {
        Self {
            status,
            message: message.into(),
            parameter: -1,
        }
    }
}

impl From<ParameterError> for Failure {
    fn from(e: ParameterError) -> Self {
        Self {
            status: Status::InvalidParameter,
            message: e.message,
            parameter: e.parameter as i32,
        }
    }
}

impl From<KinematicsError> for Failure {
    fn from(e: KinematicsError) -> Self {
        match e {
            KinematicsError::NonFinite => {
                Failure::new(Status::NonFiniteInput, "non-finite position, velocity or radius")
            }
            KinematicsError::CoincidentCentres => Failure::new(
                Status::CoincidentCentres,
                "coincident centres: the pair has no axis",
            ),
            KinematicsError::NonPositiveRadius => {
                Failure::new(Status::NonPositiveRadius, "radius must be > 0")
            }
            KinematicsError::DistanceOverflows => Failure::new(
                Status::NonFiniteResult,
                "the centre distance overflows: the centres are too far apart",
            ),
        }
    }
}

impl From<FrameError> for Failure {
    fn from(e: FrameError) -> Self {
        match e {
            FrameError::NonFinite => KinematicsError::NonFinite.into(),
            FrameError::NotUnitNormal(len) => Failure::new(
                Status::InvalidArgument,
                format!("frame normal must be a unit vector; |n| = {len}"),
            ),
        }
    }
}

struct LastError {
    message: CString,
    parameter: i32,
}

thread_local! {
    static LAST: RefCell<LastError> = RefCell::new(LastError { message: CString::default(), parameter: -1 });
}

/// Whether any thread has recorded a failure since the library was loaded.
/// Until one has, every thread's record is clear, and a successful call need
/// not look at its own: with the core linked into a shared library (the
/// engine adapters) that look-up is a call into the dynamic loader
/// (`__tls_get_addr`) on every call. Set by the
/// recording thread itself before it writes its record, so it always sees
/// its own store.
static ANY_RECORDED: AtomicBool = AtomicBool::new(false);

pub(crate) fn record(function: &str, failure: &Failure) {
    let text = format!("{}: {}", function, failure.message).replace('\0', " ");
    let message = CString::new(text).unwrap_or_default();
    ANY_RECORDED.store(true, Ordering::Relaxed);
    LAST.with(|l| {
        *l.borrow_mut() = LastError {
            message,
            parameter: failure.parameter,
        }
    });
}

/// Called after every successful call: must not allocate on the hot path,
/// so an already clear record is left alone.
pub(crate) fn clear() {
    if !ANY_RECORDED.load(Ordering::Relaxed) {
        return;
    }
    LAST.with(|l| {
        let mut l = l.borrow_mut();
        if !l.message.as_bytes().is_empty() || l.parameter != -1 {
            l.message = CString::default();
            l.parameter = -1;
        }
    });
}

/// Message of the last failed call on this thread ("" after a success).
/// Valid until the next granbond call on the same thread.
#[entry(or = c"".as_ptr())]
#[no_mangle]
pub extern "C" fn granbond_last_error_message() -> *const c_char {
    LAST.with(|l| l.borrow().message.as_ptr())
}

/// Parameter id (row of the model's parameter table) of the last
/// `InvalidParameter` failure on this thread, or -1.
#[entry(or = -1)]
#[no_mangle]
pub extern "C" fn granbond_last_error_parameter() -> i32 {
    LAST.with(|l| l.borrow().parameter)
}

#[cfg(test)]
mod tests {
    use super::Status;
    use crate::contact::{ContactOutput, VoigtModel, VoigtParams, CONTACT_STATE_LEN};
    use crate::ffi::contact::granbond_voigt_compute;
    use crate::kinematics::PairKinematics;

    /// Two spheres 1 mm in radius, overlapping by 1 um, i sliding past j.
    fn touching() -> PairKinematics {
        PairKinematics {
            x_j: [-1.999e-3, 0.0, 0.0],
            v_i: [0.0, 0.1, 0.0],
            radius_i: 1e-3,
            radius_j: 1e-3,
            ..PairKinematics::default()
        }
    }

    fn step(k: &PairKinematics, dt: f64, state: *mut f64) -> Status {
        let model = VoigtModel::new(VoigtParams::default()).unwrap();
        let mut out = ContactOutput::default();
        // SAFETY: `state` is null, misaligned (both refused) or valid.
        unsafe { granbond_voigt_compute(&model, k, dt, state, &mut out) }
    }

    #[test]
    fn a_misaligned_pointer_is_not_reported_as_a_null_one() {
        let mut words = [0.0; CONTACT_STATE_LEN + 1];
        let misaligned = (words.as_mut_ptr() as *mut u8).wrapping_add(4) as *mut f64;
        assert_eq!(step(&touching(), 1e-7, std::ptr::null_mut()), Status::NullPointer);
        assert_eq!(step(&touching(), 1e-7, misaligned), Status::Misaligned);
        assert_eq!(step(&touching(), 1e-7, words.as_mut_ptr()), Status::Ok);
    }

    #[test]
    fn non_finite_input_is_told_from_a_non_finite_result_of_finite_input() {
        let mut state = [0.0; CONTACT_STATE_LEN];
        let mut nan = touching();
        nan.v_j[2] = f64::NAN;
        assert_eq!(step(&nan, 1e-7, state.as_mut_ptr()), Status::NonFiniteInput);
        // finite, but the spring increment v dt overflows
        let mut fast = touching();
        fast.v_i[1] = 1e300;
        assert_eq!(step(&fast, 1e300, state.as_mut_ptr()), Status::NonFiniteResult);
    }
}
