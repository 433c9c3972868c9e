//! One status type for every fallible call; the message of the last failure
//! on this thread is fetched by a separate call (as rustls-ffi does).

use super::entry;
use crate::kinematics::KinematicsError;
use crate::parameters::ParameterError;
use std::cell::RefCell;
use std::ffi::{c_char, CString};
use std::sync::atomic::{AtomicBool, Ordering};

/// Result of every fallible ABI call.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    Ok = 0,
    /// A required pointer argument was null or misaligned.
    NullPointer = 1,
    /// A model parameter is out of range; see the message and
    /// `granbond_last_error_parameter`.
    InvalidParameter = 2,
    /// NaN or infinity in positions, velocities or radii.
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
}

/// A failure on its way to the caller.
#[derive(Debug)]
pub struct Failure {
    pub status: Status,
    pub message: String,
    pub parameter: i32,
}

impl Failure {
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
