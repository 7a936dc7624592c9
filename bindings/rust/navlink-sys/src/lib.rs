//! Raw bindings to NavLink's C ABI: `navlink/navlink.h`, `navlink/recast.h` and `navlink/plugin.h`, one
//! to one. Types keep their C names and layouts (`#[repr(C)]`, checked against the C compiler by
//! `tests/layout.rs`), functions their C signatures. Every function is `unsafe`: the header's comments
//! say what each pointer must be. The safe API is the `navlink` crate.
//!
//! Callback types are `Option<unsafe extern "C" fn ...>`: `None` is the header's NULL.
#![allow(non_camel_case_types)]

mod level;
mod links;
mod navmesh;
mod paths;
mod plugins;
mod recast;
mod status;
mod world;

pub use level::*;
pub use links::*;
pub use navmesh::*;
pub use paths::*;
pub use plugins::*;
pub use recast::*;
pub use status::*;
pub use world::*;
