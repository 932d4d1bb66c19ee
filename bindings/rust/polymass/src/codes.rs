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

/// A set of the C library's flag bits as a type of its own (warnings,
/// checks): named constants, `contains`, `is_empty`, `bits` and `|`. Bits
/// this crate has no constant for are kept.
macro_rules! bit_set {
    ($(#[$meta:meta])* $name:ident { $($(#[$bit_meta:meta])* $bit:ident = $value:expr;)* }) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
        pub struct $name(u32);

        impl $name {
            $($(#[$bit_meta])* pub const $bit: $name = $name($value);)*

            /// Whether every bit of `other` is set.
            pub fn contains(self, other: $name) -> bool {
                self.0 & other.0 == other.0
            }

            /// Whether no bit is set.
            pub fn is_empty(self) -> bool {
                self.0 == 0
            }

            /// The raw bits, as the C library gives them.
            pub fn bits(self) -> u32 {
                self.0
            }

            pub(crate) fn from_bits(bits: u32) -> $name {
                $name(bits)
            }
        }

        impl std::ops::BitOr for $name {
            type Output = $name;

            fn bitor(self, other: $name) -> $name {
                $name(self.0 | other.0)
            }
        }
    };
}
pub(crate) use bit_set;
