//! How the tool writes a number for a reader and fingerprints a text: formatting helpers that the spec
//! (its messages, its hash) and the output (the files) both use, in a leaf module that imports
//! neither.

/// A number as a message should show it: plain when it reads well, in scientific notation when it
/// is huge or tiny (`1e308`, not a 309-digit decimal).
pub fn readable(value: f64) -> String {
    let size = value.abs();
    if size != 0.0 && size.is_finite() && !(1e-4..1e9).contains(&size) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

/// A computed value as a reader wants it: at most 10 significant digits, so that rounding noise of
/// the arithmetic does not show (`63.400000000000006` → `63.4`, `3.0000000000000004` → `3`), in
/// exponent form outside `1e-4 ..1e9` as [`readable`] writes a spec's values.
pub fn number(value: f64) -> String {
    let rounded = format!("{value:.9e}").parse().unwrap_or(value);
    readable(rounded)
}

/// Lower-case hex SHA-256 of `bytes`: how the tool fingerprints specs, sources, tables and the files
/// it wrote.
pub fn sha256_hex(bytes: &[u8]) -> String {
    use sha2::Digest;
    sha2::Sha256::digest(bytes).iter().map(|b| format!("{b:02x}")).collect()
}
