//! Safe Rust API over NavLink (libnavlink.so): level geometry and ray queries, navmeshes (built by
//! Recast or handed over), generated jump and drop links, queued path requests planned for what each
//! agent's body can do, and agents that follow those paths, stepped by the world.
//!
//! - [`World`] owns an `nl_world*` and destroys it on drop. It is `Send + Sync`: navlink.h makes every
//!   function that takes a world safe to call from several threads at once, except `nl_world_destroy`,
//!   which only `Drop` calls, when no borrow is left.
//! - Failures are [`Error`]s: the `nl_status` and the library's message for the failing call.
//! - Value types are plain Rust structs: those the header lets grow (`Link`, `LinkDef`, `RayHit`,
//!   `MeshInfo`, `NavmeshInfo`, `RecastSettings`, `PathPoint`, `AgentInfo`...) without `size` and
//!   `reserved`, with `bool` flags, enums for kinds ([`LinkKind`]...) and `Default` as the header's
//!   defaults; ids, rays, segments and bodies are navlink-sys's `#[repr(C)]` structs under Rust names
//!   (they carry neither). Lists come back as `Vec`s, batch queries take slices.
//! - Callbacks are closures behind trampolines that catch panics: a panic never unwinds into C.
mod agents;
mod callbacks;
mod error;
mod kinds;
mod level;
mod links;
mod list;
mod navmesh;
mod navmesh_files;
mod paths;
mod plain;
// Generated from the headers (bindings/generate/emit_rust_plain.py); rustfmt leaves it as the generator writes it.
#[rustfmt::skip]
mod plain_generated;
mod plugins;
mod queries;
mod types;
mod world;

pub use agents::{default_agent_def, AgentInfoExt};
pub use error::{status_string, Error, ErrorKind, Result, Status};
pub use kinds::{
    AgentEventKind, AgentReason, AgentState, LinkKind, LinkLimit, PathOutcome, PathShortfallReason, RecastPartition, TrajectoryKind,
    UpAxis,
};
pub use level::{MeshFlags, MeshOptions};
pub use callbacks::Progress;
pub use links::{default_link_def, default_link_settings, link_settings_from_json, LinkDefExt, LinkExt, LinksLoadOptions};
pub use navmesh::{default_agent_type, default_recast_settings, BuildWarnings, NavmeshBuild, NavmeshDetail, NavmeshInput, NavmeshTile};
pub use navmesh_files::{describe_navmesh_file, NavmeshLoadOptions};
pub use paths::{default_agent_capabilities, FinishedPath, PathBudget, PathQuery, PathRequest, PathResult, PathShortfall};
pub use plugins::PluginSummary;
pub use queries::{default_query_filter, QueryFilter, RandomPointsOptions};
pub use types::*;
pub use world::{HostTasks, LogFn, World, WorldOptions};

/// The raw bindings, for what the safe API does not cover (and for writing plugins).
pub use navlink_sys as sys;
