// The C-harness test compiles a C program for the same target as the crate;
// only the build script is told the target triple, so pass it on.
fn main() {
    println!(
        "cargo:rustc-env=GRANBOND_TARGET={}",
        std::env::var("TARGET").unwrap()
    );
    println!("cargo:rustc-env=GRANBOND_HOST={}", std::env::var("HOST").unwrap());
    println!("cargo:rerun-if-changed=build.rs");
}
