//! The C ABI: the only `extern "C"` surface of the crate. No physics here;
//! every function is written with `#[entry]` (crate `granbond-macros`),
//! which checks the pointers it declares, runs the body under
//! [`guard::call`] (no panic crosses the boundary) and reports failure as a
//! [`Status`] plus a message from `granbond_last_error_message`. The
//! exception are the `*_unchecked` per-contact entries of engines' hot
//! loops (`#[entry(unchecked)]`): their caller guarantees valid arguments,
//! only the result is checked (and the body cannot panic; a panic would
//! abort, as in any `extern "C"` function).

pub mod abi;
pub mod bond;
pub mod checks;
pub mod contact;
pub mod contact_geometry;
pub mod deck;
pub mod error;
pub mod fields;
pub mod guard;
pub mod layout;
pub mod ledger;
pub mod parameters;
pub mod results;
pub mod store;
pub mod wall_store;

pub use error::Status;

use granbond_macros::entry;
