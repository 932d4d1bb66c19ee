//! Rust enums over the C library's integer codes (statuses, shell kinds): one
//! table per enum, read both ways; each enum also has a variant that keeps a
//! code of a newer library.

/// The kind `table` pairs with `code`, if this crate knows the code.
pub(crate) fn known_kind<K: Copy>(table: &[(K, i32)], code: i32) -> Option<K> {
    table
        .iter()
        .find(|(_, known)| *known == code)
        .map(|(kind, _)| *kind)
}

/// The code `table` pairs with `kind`, which must be one of its kinds.
pub(crate) fn known_code<K: Copy + PartialEq>(table: &[(K, i32)], kind: K) -> i32 {
    table
        .iter()
        .find(|(known, _)| *known == kind)
        .map(|(_, code)| *code)
        .expect("every known kind is in its table")
}
