//! navlink-sys's plain-data structs under Rust names, plain Rust structs for the growable ones the path
//! and agent API use (no `size`, no `reserved`), and the header's constants grouped by meaning.
use crate::kinds::{AgentEventKind, AgentReason, AgentState, LinkKind, PathOutcome, TrajectoryKind};
use crate::plain::plain_struct;
use navlink_sys as sys;

pub type Version = sys::nl_version;
pub type MeshId = sys::nl_mesh_id;
pub type MeshInfo = sys::nl_mesh_info;
pub type Ray = sys::nl_ray;
pub type RayHit = sys::nl_ray_hit;
pub type Segment = sys::nl_segment;
pub type NavmeshId = sys::nl_navmesh_id;
pub type AgentType = sys::nl_agent_type;
pub type NavmeshInfo = sys::nl_navmesh_info;
pub type NavPolygon = sys::nl_nav_polygon;
pub type BoundaryEdge = sys::nl_boundary_edge;
pub type NavPoint = sys::nl_nav_point;
pub type RecastSettings = sys::nl_recast_settings;
pub type LinkId = sys::nl_link_id;
pub type Link = sys::nl_link;
pub type LinkDef = sys::nl_link_def;
pub type LinkRequirements = sys::nl_link_requirements;
pub type LinkGenerationReport = sys::nl_link_generation_report;
pub type NavmeshLoadDef = sys::nl_navmesh_load_def;
pub type NavmeshFileInfo = sys::nl_navmesh_file_info;
pub type PathTicket = sys::nl_path_ticket;
pub type AgentCapabilities = sys::nl_agent_capabilities;
pub type PluginId = sys::nl_plugin_id;
pub type AgentId = sys::nl_agent_id;

/// `nl_status` bits.
pub mod status {
    pub use navlink_sys::{
        NL_STATUS_BUFFER_TOO_SMALL as BUFFER_TOO_SMALL, NL_STATUS_CANCELLED as CANCELLED,
        NL_STATUS_FAILURE as FAILURE, NL_STATUS_INTERNAL_ERROR as INTERNAL_ERROR,
        NL_STATUS_INVALID_ARGUMENT as INVALID_ARGUMENT, NL_STATUS_INVALID_HANDLE as INVALID_HANDLE,
        NL_STATUS_IN_PROGRESS as IN_PROGRESS, NL_STATUS_IO_ERROR as IO_ERROR, NL_STATUS_NOT_FOUND as NOT_FOUND,
        NL_STATUS_OUT_OF_MEMORY as OUT_OF_MEMORY, NL_STATUS_PARSE_ERROR as PARSE_ERROR,
        NL_STATUS_PARTIAL_RESULT as PARTIAL_RESULT, NL_STATUS_SUCCESS as SUCCESS,
        NL_STATUS_VERSION_MISMATCH as VERSION_MISMATCH,
    };
}

/// A `Link`'s and a `LinkDef`'s raw `kind` (`nl_link_kind`); a path point's is a [`crate::LinkKind`].
pub mod link_kind {
    pub use navlink_sys::{
        NL_LINK_DROP as DROP, NL_LINK_FIRST_PLUGIN_KIND as FIRST_PLUGIN_KIND, NL_LINK_JUMP as JUMP,
        NL_LINK_MANUAL as MANUAL, NL_SEGMENT_WALK as WALK,
    };
}

pub use navlink_sys::{
    NL_LINKS_LOAD_ANY_BODY as LINKS_LOAD_ANY_BODY, NL_MAX_WORKERS as MAX_WORKERS, NL_MESH_MAX_AREA as MESH_MAX_AREA,
    NL_NAVMESH_LOAD_SAME_LEVEL as NAVMESH_LOAD_SAME_LEVEL, NL_NO_POLYGON as NO_POLYGON, NL_WORKERS_AUTO as WORKERS_AUTO,
};

plain_struct! {
    /// One point of a path (`nl_path_point`).
    pub struct PathPoint mirrors sys::nl_path_point, default sys::nl_path_point_init(), derives (PartialEq) {
        /// In the world, at the surface's pose when the path was planned.
        position: [f32; 3],
        polygon: u32,
        /// How the path goes on from here: walking, or the link taken.
        segment: LinkKind,
        link: LinkId,
        /// The link's apex, for a jump.
        apex: [f32; 3],
        /// The link is taken end to start.
        reversed: bool,
        /// `position` in the navmesh's own space (equal to it on a navmesh that rides nothing).
        surface_position: [f32; 3],
    }
}

plain_struct! {
    /// What a finished request found, besides its points (`nl_path_result`).
    pub struct PathSummary mirrors sys::nl_path_result, default sys::nl_path_result_init(), derives (PartialEq) {
        outcome: PathOutcome,
        /// The request's `nl_status` (PARTIAL_RESULT for `PathOutcome::Partial`).
        status: u32,
        point_count: u32,
        links_used: u32,
        nodes_visited: u32,
        /// The search stopped at `max_nodes`.
        out_of_nodes: bool,
        length: f32,
        cost: f32,
        /// The navmesh points the search started and ended at.
        start: [f32; 3],
        goal: [f32; 3],
    }
}

plain_struct! {
    /// The path queue's counters (`nl_path_queue_stats`).
    pub struct PathQueueStats mirrors sys::nl_path_queue_stats, default sys::nl_path_queue_stats_init(), derives (PartialEq, Eq) {
        workers: u32,
        queued: u32,
        running: u32,
        /// Tickets not released yet (a `PathRequest` releases its own when dropped).
        unreleased: u32,
        submitted: u64,
        finished: u64,
    }
}

plain_struct! {
    /// How to add an agent (`nl_agent_def`); `Default` is `default_agent_def()`.
    pub struct AgentDef mirrors sys::nl_agent_def, default unsafe { sys::nl_default_agent_def() }, derives (PartialEq) {
        navmesh: NavmeshId,
        height: f32,
        capabilities: AgentCapabilities,
        max_speed: f32,
        max_acceleration: f32,
        gravity: f32,
        takeoff_speed: f32,
        position: [f32; 3],
        avoidance: bool,
        user_data: u64,
    }
}

plain_struct! {
    /// An agent's state (`nl_agent_info`).
    pub struct AgentInfo mirrors sys::nl_agent_info, default sys::nl_agent_info_init(), derives (PartialEq) {
        state: AgentState,
        id: AgentId,
        position: [f32; 3],
        velocity: [f32; 3],
        polygon: u32,
        reason: AgentReason,
        link: LinkId,
        link_progress: f32,
        /// In the world, where it is now (on a moving surface it moves with the surface).
        destination: [f32; 3],
        has_destination: bool,
        corners_ahead: u32,
        user_data: u64,
        /// The navmesh it stands on now (it changes when the agent takes a cross link; in the air, the one
        /// it took off from).
        navmesh: NavmeshId,
        /// The movable mesh that navmesh rides (the agent rides it too), or the null id.
        surface: MeshId,
        /// `position` in that mesh's own space.
        surface_position: [f32; 3],
    }
}

plain_struct! {
    /// How a link is being taken: the trajectory the generator checked, with its timing (`nl_agent_trajectory`).
    pub struct AgentTrajectory mirrors sys::nl_agent_trajectory, default sys::nl_agent_trajectory_init(), derives (PartialEq) {
        kind: TrajectoryKind,
        link: LinkId,
        from: [f32; 3],
        to: [f32; 3],
        apex: [f32; 3],
        /// For `TrajectoryKind::Fall`; else from, from, to, to.
        points: [[f32; 3]; 4],
        duration: f32,
        elapsed: f32,
    }
}

plain_struct! {
    /// What happened to an agent in the last step (`nl_agent_event`).
    pub struct AgentEvent mirrors sys::nl_agent_event, default sys::nl_agent_event_init(), derives (PartialEq, Eq) {
        kind: AgentEventKind,
        agent: AgentId,
        link: LinkId,
        reason: AgentReason,
        user_data: u64,
    }
}

plain_struct! {
    /// How links are generated (`nl_link_settings` without its plugin JSON, which `generate_links` takes
    /// apart); `Default` is `default_link_settings()`.
    pub struct LinkSettings mirrors sys::nl_link_settings, default unsafe { sys::nl_default_link_settings() }, derives (PartialEq) {
        min_edge_length: f32,
        min_group_size: u32,
        max_group_size: u32,
        sample_spacing: f32,
        falloff_distance: f32,
        max_jump_gap: f32,
        min_link_distance: f32,
        short_link_distance: f32,
        max_jump_up: f32,
        jump_arc_height: f32,
        strict_forward_angle: f32,
        permissive_forward_angle: f32,
        strict_incline_angle: f32,
        permissive_incline_angle: f32,
        max_drop_distance: f32,
        drop_angles: [f32; 16],
        drop_angle_count: u32,
        drop_steepness: f32,
        merge_distance: f32,
        clearance_margin: f32,
        arc_segments: u32,
        walk_factor: f32,
        walk_distance: f32,
    }
}
