//! Plain Rust structs over the header's structs that carry `size` or `reserved`: the same fields without
//! them, `u8` (and `uint32_t` yes/no) flags as `bool`, kinds as enums, flag words as `MeshFlags` or
//! `BuildWarnings`, nested such structs as their plain structs. `From<c struct>` reads one; `to_c` writes
//! one over a C value that already has its `size` (and the header's defaults for fields not mirrored).
//!
//! The `plain_struct!` invocations are generated from the headers (plain_generated.rs, by
//! bindings/generate/emit_rust_plain.py, which says how each field's type is found); this file holds the
//! macro and the conversions of a field's value: the enums' are in kinds.rs's `c_enum!`, the flag words'
//! (`MeshFlags`, `BuildWarnings`: emit_rust_plain.py's FLAG_WORDS) and `Status`'s here.
use crate::error::Status;
use crate::level::MeshFlags;
use crate::navmesh::BuildWarnings;

/// A C field's value as its Rust field's type.
pub(crate) trait FromC<C> {
    fn from_c(c: C) -> Self;
}

/// A Rust field's value as its C field's type.
pub(crate) trait IntoC<C> {
    fn into_c(self) -> C;
}

impl<T> FromC<T> for T {
    fn from_c(c: T) -> T {
        c
    }
}

impl<T> IntoC<T> for T {
    fn into_c(self) -> T {
        self
    }
}

impl FromC<u8> for bool {
    fn from_c(c: u8) -> bool {
        c != 0
    }
}

impl IntoC<u8> for bool {
    fn into_c(self) -> u8 {
        self as u8
    }
}

/// A `uint32_t` yes/no field (`nl_navmesh_file_info::rides_carrier`).
impl FromC<u32> for bool {
    fn from_c(c: u32) -> bool {
        c != 0
    }
}

impl IntoC<u32> for bool {
    fn into_c(self) -> u32 {
        self as u32
    }
}

impl FromC<u32> for MeshFlags {
    fn from_c(c: u32) -> MeshFlags {
        MeshFlags::from_raw(c)
    }
}

impl IntoC<u32> for MeshFlags {
    fn into_c(self) -> u32 {
        self.to_raw()
    }
}

impl FromC<u32> for BuildWarnings {
    fn from_c(c: u32) -> BuildWarnings {
        BuildWarnings::from_raw(c)
    }
}

impl IntoC<u32> for BuildWarnings {
    fn into_c(self) -> u32 {
        self.to_raw()
    }
}

impl FromC<u32> for Status {
    fn from_c(c: u32) -> Status {
        Status(c)
    }
}

impl IntoC<u32> for Status {
    fn into_c(self) -> u32 {
        self.0
    }
}

/// A plain struct mirroring some fields of a C struct, with `From<C>`, `to_c` and a `Default` taken
/// from the C side's default value (`$default`). It is also a field type of other plain structs
/// (`FromC`/`IntoC`: written back over `$default`).
macro_rules! plain_struct {
    (
        $(#[$meta:meta])*
        pub struct $name:ident mirrors $c:ty, default $default:expr, derives ($($derive:ident),*) {
            $($(#[$field_meta:meta])* $field:ident: $ty:ty,)*
        }
    ) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, $($derive),*)]
        pub struct $name {
            $($(#[$field_meta])* pub $field: $ty,)*
        }

        impl From<$c> for $name {
            fn from(c: $c) -> $name {
                $name { $($field: $crate::plain::FromC::from_c(c.$field),)* }
            }
        }

        impl Default for $name {
            fn default() -> $name {
                let c: $c = $default;
                $name::from(c)
            }
        }

        #[allow(dead_code)] // output-only structs are never written back
        impl $name {
            /// `base` (which carries `size` and the fields not mirrored) with this struct's fields.
            pub(crate) fn to_c(&self, mut base: $c) -> $c {
                $(base.$field = $crate::plain::IntoC::into_c(self.$field);)*
                base
            }
        }

        impl $crate::plain::FromC<$c> for $name {
            fn from_c(c: $c) -> $name {
                $name::from(c)
            }
        }

        impl $crate::plain::IntoC<$c> for $name {
            fn into_c(self) -> $c {
                self.to_c($default)
            }
        }
    };
}
pub(crate) use plain_struct;
