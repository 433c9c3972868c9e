//! The C test bed: the C files of `tests/c/` (one per topic, sharing
//! `harness.h`) call every function of `include/granbond.h` from C. This
//! test compiles them with the C compiler cc-rs finds for this target, links
//! them against the crate's static library, runs the program, and also
//! compiles them as C++ to prove the header is C++-clean.
//!
//! Which `libgranbond.a`: cargo builds the `staticlib` crate type together
//! with the `rlib` whenever it builds the library, but the copy in
//! `target/<profile>/` is only refreshed ("uplifted") when the library is
//! itself a root of the cargo command (`cargo build`), never by
//! `cargo test --test c_abi`. After a source change that copy is stale, and
//! in a fresh target directory it does not exist. The library built for this
//! very run is `target/<profile>/deps/libgranbond-<hash>.a`, written by the
//! same rustc invocation as the `.rlib` this test executable was linked
//! with; there may be several hashes (`cargo build` and `cargo test` resolve
//! features differently), so [`static_library`] takes the newest one that is
//! not newer than this executable.

use granbond_test_support as common;

use common::header::header_functions;
use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::SystemTime;

const HARNESS_DIR: &str = "tests/c";
const LIBRARY_STEM: &str = "libgranbond";

fn crate_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The harness's C files, in name order (`main.c` holds `main`).
fn harness_sources() -> Vec<PathBuf> {
    let dir = crate_dir().join(HARNESS_DIR);
    let entries = std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("read {}: {e}", dir.display()));
    let mut sources: Vec<PathBuf> = entries
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension() == Some(OsStr::new("c")))
        .collect();
    sources.sort();
    assert!(
        sources.iter().any(|p| p.ends_with("main.c")),
        "no main.c among {sources:?}"
    );
    sources
}

/// Scratch directory under `target/tmp` for the harness executable.
fn work_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("c_abi");
    std::fs::create_dir_all(&dir).expect("create the scratch directory under CARGO_TARGET_TMPDIR");
    dir
}

/// The compiler configuration a build script of this crate would get.
fn build(cpp: bool) -> cc::Build {
    let mut b = cc::Build::new();
    b.target(env!("GRANBOND_TARGET"))
        .host(env!("GRANBOND_HOST"))
        .opt_level(0)
        .debug(false)
        .cpp(cpp)
        .cargo_metadata(false)
        .cargo_warnings(false)
        .out_dir(work_dir());
    b
}

fn modified(path: &Path) -> SystemTime {
    std::fs::metadata(path)
        .and_then(|m| m.modified())
        .unwrap_or_else(|e| panic!("mtime of {}: {e}", path.display()))
}

/// Static libraries of this crate next to the test executable:
/// `deps/libgranbond-<hash>.a` and the uplifted `libgranbond.a`.
fn candidates(deps: &Path, profile_dir: &Path) -> Vec<(SystemTime, PathBuf)> {
    let mut found = Vec::new();
    for (dir, hashed) in [(deps, true), (profile_dir, false)] {
        let Ok(entries) = std::fs::read_dir(dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            let Some(name) = path.file_name().and_then(OsStr::to_str) else {
                continue;
            };
            let matches = if hashed {
                name.starts_with(&format!("{LIBRARY_STEM}-")) && name.ends_with(".a")
            } else {
                name == format!("{LIBRARY_STEM}.a")
            };
            if matches && path.is_file() {
                found.push((modified(&path), path));
            }
        }
    }
    found
}

/// The `libgranbond.a` built with the code this test executable runs (see
/// the module docs).
fn static_library() -> PathBuf {
    let exe = std::env::current_exe().expect("path of the test executable");
    let deps = exe.parent().expect("target/<profile>/deps");
    let profile_dir = deps.parent().expect("target/<profile>");
    let found = candidates(deps, profile_dir);
    assert!(
        !found.is_empty(),
        "no {LIBRARY_STEM}*.a in {} or {}: the lib target must keep crate-type \"staticlib\"",
        deps.display(),
        profile_dir.display()
    );
    let exe_time = modified(&exe);
    // The library this executable was linked with was built before it; a
    // newer one comes from a later, unrelated build in the same target dir.
    let linked = found
        .iter()
        .filter(|(t, _)| *t <= exe_time)
        .max_by_key(|(t, _)| *t);
    let (_, path) = linked
        .or_else(|| found.iter().max_by_key(|(t, _)| *t))
        .expect("at least one candidate");
    path.clone()
}

fn run(mut cmd: Command, what: &str) {
    let shown = format!("{cmd:?}");
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("{what}: cannot run {shown}: {e}"));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "{what} failed ({}):\n$ {shown}\n--- stdout ---\n{stdout}\n--- stderr ---\n{stderr}",
        out.status
    );
}

/// Compiles the harness with `flags` (after the warning flags), links it
/// against the static library, runs it with `env` and checks it ran every
/// check; returns its output.
fn harness_passes(variant: &str, flags: &[&str], env: &[(&str, &str)]) -> String {
    let library = static_library();
    println!("static library: {}", library.display());

    let compiler = build(false).get_compiler();
    assert!(
        !compiler.is_like_msvc(),
        "the C test bed expects a GCC-style compiler driver, got {}",
        compiler.path().display()
    );
    // One executable per process: concurrent `cargo test` runs in the same
    // target directory must not overwrite (or fail to link over) each other's.
    let exe = work_dir().join(format!("abi_harness{variant}-{}", std::process::id()));
    let mut cmd = compiler.to_command();
    cmd.args(["-std=c99", "-pedantic-errors", "-Wall", "-Wextra", "-Werror"])
        .args(flags)
        .arg("-I")
        .arg(crate_dir().join("include"))
        .args(harness_sources())
        .arg(&library)
        .args(["-lpthread", "-ldl", "-lm"])
        .arg("-o")
        .arg(&exe);
    run(cmd, "compiling and linking the C harness");

    let out = Command::new(&exe).envs(env.iter().copied()).output();
    // Rebuilt on every run (the source and the command above reproduce it).
    let _ = std::fs::remove_file(&exe);
    let out = out.unwrap_or_else(|e| panic!("cannot run {}: {e}", exe.display()));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "C harness{variant} failed ({}):\n--- stdout ---\n{stdout}\n--- stderr ---\n{stderr}",
        out.status
    );
    let last = stdout.lines().last().unwrap_or("");
    assert!(
        last.starts_with("abi_harness: all ") && last.ends_with(" checks passed"),
        "C harness{variant} did not run to the end:\n{stdout}\n{stderr}"
    );
    println!("{last}");
    stderr.into_owned()
}

#[test]
fn c_harness_passes_against_the_static_library() {
    harness_passes("", &[], &[]);
}

/// AddressSanitizer and UBSanitizer flags, or `None` when this compiler
/// cannot build and run a sanitized program (another toolchain, no
/// libasan): the test says so and passes; scripts/fuzz.sh runs the same
/// check with the core instrumented too.
fn sanitizer_flags() -> Option<&'static [&'static str]> {
    const FLAGS: &[&str] = &[
        "-fsanitize=address,undefined",
        "-fno-sanitize-recover=all",
        "-fno-omit-frame-pointer",
        "-g",
    ];
    let compiler = build(false).get_compiler();
    let dir = work_dir();
    let (probe, exe) = (
        dir.join("sanitizer_probe.c"),
        dir.join(format!("sanitizer_probe-{}", std::process::id())),
    );
    std::fs::write(&probe, "int main(void) { return 0; }\n").expect("write the probe");
    let built = compiler
        .to_command()
        .args(FLAGS)
        .arg(&probe)
        .arg("-o")
        .arg(&exe)
        .output()
        .is_ok_and(|o| o.status.success());
    let ran = built && Command::new(&exe).output().is_ok_and(|o| o.status.success());
    let _ = std::fs::remove_file(&exe);
    ran.then_some(FLAGS)
}

#[test]
fn c_harness_passes_under_address_and_undefined_behaviour_sanitizers() {
    let Some(flags) = sanitizer_flags() else {
        println!("the C compiler cannot build sanitized programs here; skipped");
        return;
    };
    // a sanitizer report aborts the run (non-zero exit, harness_passes fails)
    let stderr = harness_passes(
        "-sanitized",
        flags,
        &[
            ("ASAN_OPTIONS", "detect_leaks=1:abort_on_error=1"),
            ("UBSAN_OPTIONS", "print_stacktrace=1:halt_on_error=1"),
        ],
    );
    assert!(
        !stderr.contains("Sanitizer") && !stderr.contains("runtime error:"),
        "sanitizer output from the harness:\n{stderr}"
    );
}

#[test]
fn header_compiles_as_cpp() {
    let Ok(compiler) = build(true).try_get_compiler() else {
        println!(
            "no C++ compiler configured for {}; skipped",
            env!("GRANBOND_TARGET")
        );
        return;
    };
    let available = Command::new(compiler.path())
        .arg("--version")
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    if !available || compiler.is_like_msvc() {
        println!("no usable C++ compiler ({}); skipped", compiler.path().display());
        return;
    }
    let mut cmd = compiler.to_command();
    cmd.args([
        "-x",
        "c++",
        "-std=c++11",
        "-pedantic-errors",
        "-Wall",
        "-Wextra",
        "-Werror",
    ])
    .arg("-fsyntax-only")
    .arg("-I")
    .arg(crate_dir().join("include"))
    .args(harness_sources());
    run(cmd, "compiling the C harness as C++11");
}

#[test]
fn harness_calls_every_header_function() {
    let functions = header_functions();
    assert!(
        functions.len() >= 20,
        "found only {functions:?} in granbond.h: the header parser is out of date"
    );
    let harness: String = harness_sources()
        .iter()
        .map(|p| std::fs::read_to_string(p).unwrap_or_else(|e| panic!("read {}: {e}", p.display())))
        .collect();
    let missing: Vec<&String> = functions
        .iter()
        .filter(|f| !harness.contains(&format!("{f}(")))
        .collect();
    assert!(
        missing.is_empty(),
        "{HARNESS_DIR}/*.c do not call {missing:?}: every function of granbond.h must be exercised from C"
    );
}
