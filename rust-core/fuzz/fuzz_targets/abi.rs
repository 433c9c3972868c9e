//! Every entry point of the C ABI with arbitrary arguments: the calls an
//! input makes and the checks of their answers are in
//! `tests/fuzz_driver` (shared with the corpus replay of the stable suite).
#![no_main]

#[path = "../../tests/fuzz_driver/mod.rs"]
mod fuzz_driver;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    fuzz_driver::run(data, &mut fuzz_driver::Tally::default());
});
