{# `KIND`, `Observer` and `observer()` of the design's chosen kind, and the saved tables' hash. #}
/// The kind of [`Observer`] (`[observer] kind` of the spec, or `gen`'s choice for `auto`).
pub const KIND: &str = "{{ kind }}";

/// This design's observer: {{ what }}.
pub type Observer = {{ ty }};

/// A fresh [`Observer`], holding no sample yet.
pub const fn observer() -> Observer {
    {{ ty }}::new()
}

/// SHA-256 of the tables `gen` saved with this file (`design.json`'s `tables_sha256`): `estimate`
/// uses saved tables only beside the observer file written with them.
pub const TABLES_SHA256: &str = "{{ tables }}";

