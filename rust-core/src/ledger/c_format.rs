//! Numbers read and written as the C library does, so that a message or
//! a log line reads the same as the engines' own (`strtol`, `%g`).

/// A whole word read as C's `strtol` in base 10 reads it (leading white
/// space and a sign allowed), or `None`.
pub fn c_long(word: &str) -> Option<i64> {
    let t = word.trim_start_matches([' ', '\t', '\n', '\r', '\x0b', '\x0c']);
    let digits = t.strip_prefix(['+', '-']).unwrap_or(t);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    // beyond the range strtol saturates, which the range check refuses
    Some(
        t.parse::<i64>()
            .unwrap_or(if t.starts_with('-') { i64::MIN } else { i64::MAX }),
    )
}

/// `v` as C's `printf("%.*g", precision, v)` writes it.
pub fn c_g(v: f64, precision: usize) -> String {
    if v.is_nan() {
        return if v.is_sign_negative() { "-nan" } else { "nan" }.into();
    }
    if v.is_infinite() {
        return if v < 0.0 { "-inf" } else { "inf" }.into();
    }
    let p = precision.max(1);
    let scientific = format!("{:.*e}", p - 1, v);
    let (mantissa, exponent) = scientific.split_once('e').expect("{:e} writes an exponent");
    let exponent: i32 = exponent.parse().expect("{:e} writes an integer exponent");
    let strip = |s: &str| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s.to_string()
        }
    };
    if exponent < -4 || exponent >= p as i32 {
        let sign = if exponent < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", strip(mantissa), exponent.abs())
    } else {
        strip(&format!("{:.*}", (p as i32 - 1 - exponent) as usize, v))
    }
}
