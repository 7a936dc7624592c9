//! Raw bindings to NavLink's C ABI: `navlink/navlink.h`, `navlink/recast.h` and `navlink/plugin.h`, one
//! to one. Types keep their C names and layouts (`#[repr(C)]`, checked against the C compiler by
//! `tests/layout.rs`), functions their C signatures. Every function is `unsafe`: the header's comments
//! say what each pointer must be. The safe API is the `navlink` crate.
//!
//! Callback types are `Option<unsafe extern "C" fn ...>`: `None` is the header's NULL.
//!
//! Output structs that may grow start with `size`. The header's inline initialisers
//! (`NL_DEFINE_OUTPUT_INIT`: `nl_link_init()`...) are not exported by the library; they are defined here
//! under the same names, and each such struct's `Default` is its initialiser, so `vec![nl_link::default(); n]`
//! is an output array the library can lay out (it reads the element size from the first element).
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

/// `impl Default` as the struct's inline initialiser.
macro_rules! default_is_init {
    ($t:ident, $init:ident) => {
        impl Default for $t {
            /// The header's initialiser: zeroed, with `size` set.
            fn default() -> Self {
                $init()
            }
        }
    };
}

mod agents;
mod level;
mod links;
mod navmesh;
mod navmesh_files;
mod paths;
mod plugins;
mod queries;
mod recast;
mod status;
mod world;

pub use agents::*;
pub use level::*;
pub use links::*;
pub use navmesh::*;
pub use navmesh_files::*;
pub use paths::*;
pub use plugins::*;
pub use queries::*;
pub use recast::*;
pub use status::*;
pub use world::*;
