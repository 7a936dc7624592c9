//! Raw bindings to NavLink's C ABI: `navlink/navlink.h`, `navlink/recast.h` and `navlink/plugin.h`, one
//! to one. Types keep their C names and layouts (`#[repr(C)]`, checked against the C compiler by
//! `tests/layout.rs`), functions their C signatures. Every function is `unsafe`: the header's comments
//! (the items' documentation here) say what each pointer must be. The safe API is the `navlink` crate.
//!
//! The declarations are generated from the headers (`bindings/generate/generate.py`, emit_rust.py):
//! `constants_generated.rs` (the kinds as `u32` aliases, every `NL_*` constant), `types_generated.rs` (the
//! structs, callback types and inline initialisers) and `functions_generated.rs` (the `extern "C"` block).
//! What is written here by hand is what is not mechanical: `output_init`, the ids' `Debug`, and
//! `nl_succeeded` / `nl_failed` (status.rs: the header's function-like macros).
//!
//! Callback types are `Option<unsafe extern "C" fn ...>`: `None` is the header's NULL.
//!
//! Output structs that may grow start with `size`. The header's inline initialisers
//! (`NL_DEFINE_OUTPUT_INIT`: `nl_link_init()`...) are not exported by the library; they are defined here
//! under the same names, and each such struct's `Default` is its initialiser, so `vec![nl_link::default(); n]`
//! is an output array the library can lay out (it reads the element size from the first element). A struct
//! that starts with `size` and that no function returns (`nl_navmesh_file_info`, the plugin ABI's) is
//! `Default` zeroed with `size` set too.
#![allow(non_camel_case_types)]

/// What the header's `NL_DEFINE_OUTPUT_INIT` functions return: a zeroed `T` with its leading `size` set.
///
/// # Safety
/// `T` must be one of the header's plain C structs that starts with `uint32_t size` and for which all
/// zero bytes are a valid value (integers, floats, raw pointers).
pub(crate) unsafe fn output_init<T>() -> T {
    let mut value: T = std::mem::zeroed();
    *(&mut value as *mut T as *mut u32) = std::mem::size_of::<T>() as u32;
    value
}

/// `impl Debug` for an id, under the safe crate's name and by what it means rather than its raw fields:
/// `MeshId { index: 3, revision: 1 }` (the slot index, from 0, and how many objects the slot has held),
/// or `MeshId(null)` for the all-zero id. docs/c-api.md, "Ids": the low 28 bits of `index1` are the slot
/// index + 1 (the top 4 the kind of object) and the low 20 bits of `revision` count the slot's reuse
/// (the top 12 name the world); ids stay opaque values: compare both raw fields.
macro_rules! id_debug {
    ($t:ident, $name:literal) => {
        impl std::fmt::Debug for $t {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                if self.index1 == 0 {
                    return write!(f, concat!($name, "(null)"));
                }
                f.debug_struct($name)
                    .field("index", &(i64::from(self.index1 & crate::ID_SLOT_MASK) - 1))
                    .field("revision", &(self.revision & crate::ID_REVISION_MASK))
                    .finish()
            }
        }
    };
}

/// The bits of an id's `index1` that hold its slot index + 1 (for reading ids: `Debug`).
const ID_SLOT_MASK: u32 = (1 << 28) - 1;
/// The bits of an id's `revision` that count its slot's reuse.
const ID_REVISION_MASK: u32 = (1 << 20) - 1;

// Generated from the headers (bindings/generate/emit_rust.py); rustfmt leaves them as the generator writes them.
#[rustfmt::skip]
mod constants_generated;
#[rustfmt::skip]
mod functions_generated;
#[rustfmt::skip]
mod types_generated;

mod status;

pub use constants_generated::*;
pub use functions_generated::*;
pub use status::*;
pub use types_generated::*;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_debug_by_slot_and_revision() {
        // As the library issues them: the kind of object in index1's top 4 bits, the world in revision's top 12.
        let mesh = nl_mesh_id { index1: 1 << 28 | 4, revision: 5 << 20 | 1 };
        assert_eq!(format!("{:?}", mesh), "MeshId { index: 3, revision: 1 }");
        assert_eq!(format!("{:?}", nl_navmesh_id { index1: 1, revision: 2 }), "NavmeshId { index: 0, revision: 2 }");
        assert_eq!(format!("{:?}", nl_link_id { index1: 3 << 28 | 12, revision: 7 }), "LinkId { index: 11, revision: 7 }");
        assert_eq!(format!("{:?}", nl_path_ticket { index1: 2, revision: 1 }), "PathTicket { index: 1, revision: 1 }");
        assert_eq!(format!("{:?}", nl_agent_id { index1: 6 << 28 | 1, revision: 1 }), "AgentId { index: 0, revision: 1 }");
        assert_eq!(format!("{:?}", nl_plugin_id { index1: 9, revision: 3 }), "PluginId { index: 8, revision: 3 }");
        assert_eq!(format!("{:#?}", nl_mesh_id { index1: 4, revision: 1 }), "MeshId {\n    index: 3,\n    revision: 1,\n}");
    }

    #[test]
    fn null_ids_debug_as_null() {
        assert_eq!(format!("{:?}", nl_mesh_id::default()), "MeshId(null)");
        assert_eq!(format!("{:?}", nl_navmesh_id::default()), "NavmeshId(null)");
        assert_eq!(format!("{:?}", nl_link_id::default()), "LinkId(null)");
        assert_eq!(format!("{:?}", nl_path_ticket::default()), "PathTicket(null)");
        assert_eq!(format!("{:?}", nl_agent_id::default()), "AgentId(null)");
        assert_eq!(format!("{:?}", nl_plugin_id::default()), "PluginId(null)");
        // A struct holding ids shows them so too.
        let link = nl_link_init();
        assert!(format!("{:?}", link).contains("id: LinkId(null), navmesh: NavmeshId(null)"), "{:?}", link);
    }
}
