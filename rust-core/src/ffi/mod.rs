//! The C ABI: the only `extern "C"` surface of the crate. No physics here;
//! every function checks its pointers, runs its body under [`guard::call`]
//! (no panic crosses the boundary) and reports failure as a [`Status`] plus
//! a message from `granbond_last_error_message`.

pub mod abi;
pub mod bond;
pub mod contact;
pub mod error;
pub mod guard;
pub mod layout;

pub use error::Status;
