//! The one wrapper every fallible `extern "C"` function goes through, and
//! the argument checks they share. Each check takes the argument, any
//! further arguments it needs, and the argument's name for the message, as
//! `#[entry(argument: check(further))]` calls it.

use super::error::{clear, record, Failure, Status};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Runs `body`, turning its error or its panic into a [`Status`] and a
/// recorded message naming `function`.
pub fn call(function: &str, body: impl FnOnce() -> Result<(), Failure>) -> Status {
    let failure = match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => {
            clear();
            return Status::Ok;
        }
        Ok(Err(f)) => f,
        Err(panic) => {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown".into());
            Failure::new(
                Status::Panic,
                format!("internal error (panic: {what}); please report"),
            )
        }
    };
    record(function, &failure);
    failure.status
}

fn check<T>(ptr: *const T, name: &str) -> Result<(), Failure> {
    if ptr.is_null() {
        return Err(Failure::new(
            Status::NullPointer,
            format!("argument `{name}` is null"),
        ));
    }
    if !(ptr as usize).is_multiple_of(std::mem::align_of::<T>()) {
        return Err(Failure::new(
            Status::Misaligned,
            format!("argument `{name}` is misaligned"),
        ));
    }
    Ok(())
}

/// `&*ptr` after checking it is non-null and aligned.
///
/// # Safety
/// A non-null `ptr` must point to a valid `T` for the returned lifetime.
pub unsafe fn reference<'a, T>(ptr: *const T, name: &str) -> Result<&'a T, Failure> {
    check(ptr, name)?;
    Ok(&*ptr)
}

/// `&mut *ptr` after checking it is non-null and aligned.
///
/// # Safety
/// A non-null `ptr` must point to a valid, unaliased `T`.
pub unsafe fn reference_mut<'a, T>(ptr: *mut T, name: &str) -> Result<&'a mut T, Failure> {
    check(ptr, name)?;
    Ok(&mut *ptr)
}

/// A slice of `len` elements at `ptr` (any pointer allowed when `len` is 0).
///
/// # Safety
/// A non-null `ptr` must point to `len` valid elements.
pub unsafe fn slice<'a, T>(ptr: *const T, len: usize, name: &str) -> Result<&'a [T], Failure> {
    if len == 0 {
        return Ok(&[]);
    }
    check(ptr, name)?;
    Ok(std::slice::from_raw_parts(ptr, len))
}

/// Mutable counterpart of [`slice()`].
///
/// # Safety
/// A non-null `ptr` must point to `len` valid, unaliased elements.
pub unsafe fn slice_mut<'a, T>(ptr: *mut T, len: usize, name: &str) -> Result<&'a mut [T], Failure> {
    if len == 0 {
        return Ok(&mut []);
    }
    check(ptr, name)?;
    Ok(std::slice::from_raw_parts_mut(ptr, len))
}

/// The optional `failed_index` output of the batch calls: null (not
/// wanted) or an aligned `size_t`, checked before the batch runs, so a
/// misaligned one is refused rather than written through.
#[derive(Clone, Copy)]
pub struct FailedIndex(*mut usize);

impl FailedIndex {
    /// # Safety
    /// A non-null `ptr` must be valid for writes of a `usize` while the
    /// result is used.
    pub unsafe fn new(ptr: *mut usize, name: &str) -> Result<Self, Failure> {
        if !ptr.is_null() {
            check(ptr, name)?;
        }
        Ok(Self(ptr))
    }

    /// Writes `index` where the caller asked for it (nowhere when it passed
    /// null).
    pub fn report(self, index: usize) {
        if !self.0.is_null() {
            // SAFETY: non-null, aligned and valid for writes (`new`).
            unsafe { *self.0 = index };
        }
    }

    /// Reports `index` and names it (`what` the kind of element, "bond" or
    /// "contact") in the failure's message.
    pub fn fail(self, what: &str, index: usize, f: Failure) -> Failure {
        self.report(index);
        Failure::new(f.status, format!("{what} {index}: {}", f.message))
    }
}

/// A time step must be finite and non-negative.
pub fn time_step(dt: f64, name: &str) -> Result<f64, Failure> {
    if dt.is_finite() && dt >= 0.0 {
        Ok(dt)
    } else {
        Err(Failure::new(
            Status::InvalidArgument,
            format!("time step {name} must be finite and >= 0; got {dt}"),
        ))
    }
}

/// `x` if it is finite and `within` holds, else an invalid argument
/// naming `name` and the `bound`.
fn finite_within(x: f64, within: bool, name: &str, bound: &str) -> Result<f64, Failure> {
    if x.is_finite() && within {
        Ok(x)
    } else {
        Err(Failure::new(
            Status::InvalidArgument,
            format!("{name} must be finite and {bound}; got {x}"),
        ))
    }
}

/// A length or a mass must be finite and positive.
pub fn positive(x: f64, name: &str) -> Result<f64, Failure> {
    finite_within(x, x > 0.0, name, "> 0")
}

/// A length that may be 0 (a wall's radius) must be finite and non-negative.
pub fn non_negative(x: f64, name: &str) -> Result<f64, Failure> {
    finite_within(x, x >= 0.0, name, ">= 0")
}

/// A number taken as it is must be finite.
pub fn finite(x: f64, name: &str) -> Result<f64, Failure> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Failure::new(
            Status::NonFiniteInput,
            format!("{name} must be finite; got {x}"),
        ))
    }
}

/// Three doubles at `ptr`.
///
/// # Safety
/// A non-null `ptr` must point to three doubles.
pub unsafe fn vector3(ptr: *const f64, name: &str) -> Result<[f64; 3], Failure> {
    Ok(*array(ptr, name)?)
}

/// Three finite doubles at `ptr` (a position).
///
/// # Safety
/// A non-null `ptr` must point to three doubles.
pub unsafe fn finite_vector3(ptr: *const f64, name: &str) -> Result<[f64; 3], Failure> {
    let v = vector3(ptr, name)?;
    if v.iter().all(|x| x.is_finite()) {
        Ok(v)
    } else {
        Err(Failure::new(
            Status::NonFiniteInput,
            format!("{name} must be finite; got [{}, {}, {}]", v[0], v[1], v[2]),
        ))
    }
}

/// `N` doubles at `ptr`, as an array.
///
/// # Safety
/// A non-null `ptr` must point to `N` doubles for the returned lifetime.
pub unsafe fn array<'a, const N: usize>(ptr: *const f64, name: &str) -> Result<&'a [f64; N], Failure> {
    reference(ptr as *const [f64; N], name)
}

/// Mutable counterpart of [`array()`].
///
/// # Safety
/// A non-null `ptr` must point to `N` unaliased doubles.
pub unsafe fn array_mut<'a, const N: usize>(ptr: *mut f64, name: &str) -> Result<&'a mut [f64; N], Failure> {
    reference_mut(ptr as *mut [f64; N], name)
}
