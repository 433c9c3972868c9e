//! What `include/granbond.h` declares, read from the header itself.

use std::path::Path;

/// Names of the functions `include/granbond.h` declares (its `static
/// inline` helpers included).
pub fn header_functions() -> Vec<String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../rust-core/include/granbond.h");
    let header = std::fs::read_to_string(path).expect("read granbond.h");
    let mut names = Vec::new();
    for line in header.lines().map(str::trim) {
        if line.starts_with('*') || line.starts_with('/') || line.starts_with('#') {
            continue;
        }
        let Some(start) = line.find("granbond_") else {
            continue;
        };
        let rest = &line[start..];
        let end = rest
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(rest.len());
        if rest[end..].starts_with('(') {
            names.push(rest[..end].to_string());
        }
    }
    names
}
