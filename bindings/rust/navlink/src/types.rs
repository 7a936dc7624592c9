//! navlink-sys's plain-data structs under Rust names, and the header's constants grouped by meaning.
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
pub type LinkSettings = sys::nl_link_settings;
pub type LinkGenerationReport = sys::nl_link_generation_report;
pub type NavmeshLoadDef = sys::nl_navmesh_load_def;
pub type NavmeshFileInfo = sys::nl_navmesh_file_info;
pub type PathTicket = sys::nl_path_ticket;
pub type AgentCapabilities = sys::nl_agent_capabilities;
pub type PathPoint = sys::nl_path_point;
pub type PathQueueStats = sys::nl_path_queue_stats;
pub type PluginId = sys::nl_plugin_id;
pub type AgentId = sys::nl_agent_id;
pub type AgentDef = sys::nl_agent_def;
pub type AgentInfo = sys::nl_agent_info;
pub type AgentTrajectory = sys::nl_agent_trajectory;
pub type AgentEvent = sys::nl_agent_event;

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

/// How a path segment is travelled: walking, or the kind of the link taken (`nl_link_kind`).
pub mod link_kind {
    pub use navlink_sys::{
        NL_LINK_DROP as DROP, NL_LINK_FIRST_PLUGIN_KIND as FIRST_PLUGIN_KIND, NL_LINK_JUMP as JUMP,
        NL_LINK_MANUAL as MANUAL, NL_SEGMENT_WALK as WALK,
    };
}

/// What an agent is doing (`AgentInfo::state`).
pub mod agent_state {
    pub use navlink_sys::{
        NL_AGENT_ARRIVED as ARRIVED, NL_AGENT_FAILED as FAILED, NL_AGENT_FALLING as FALLING, NL_AGENT_IDLE as IDLE,
        NL_AGENT_JUMPING as JUMPING, NL_AGENT_TRAVERSING as TRAVERSING, NL_AGENT_WAITING as WAITING,
        NL_AGENT_WALKING as WALKING,
    };
}

/// Why an agent planned again or failed (`AgentInfo::reason`, `AgentEvent::reason`).
pub mod agent_reason {
    pub use navlink_sys::{
        NL_AGENT_REASON_CAPABILITIES_CHANGED as CAPABILITIES_CHANGED, NL_AGENT_REASON_DESTINATION_SET as DESTINATION_SET,
        NL_AGENT_REASON_LINK_GONE as LINK_GONE, NL_AGENT_REASON_NAVMESH_REMOVED as NAVMESH_REMOVED,
        NL_AGENT_REASON_NONE as NONE, NL_AGENT_REASON_NO_PATH as NO_PATH, NL_AGENT_REASON_OFF_PATH as OFF_PATH,
        NL_AGENT_REASON_WORLD_CHANGED as WORLD_CHANGED,
    };
}

/// What happened to an agent in the last step (`AgentEvent::kind`).
pub mod agent_event {
    pub use navlink_sys::{
        NL_AGENT_EVENT_ARRIVED as ARRIVED, NL_AGENT_EVENT_FAILED as FAILED, NL_AGENT_EVENT_LINK_FINISHED as LINK_FINISHED,
        NL_AGENT_EVENT_LINK_STARTED as LINK_STARTED, NL_AGENT_EVENT_PATH_READY as PATH_READY,
        NL_AGENT_EVENT_REPLANNED as REPLANNED,
    };
}

/// How a link is being taken (`AgentTrajectory::kind`).
pub mod trajectory_kind {
    pub use navlink_sys::{NL_TRAJECTORY_ARC as ARC, NL_TRAJECTORY_FALL as FALL, NL_TRAJECTORY_LINE as LINE};
}

pub use navlink_sys::{
    NL_LINKS_LOAD_ANY_BODY as LINKS_LOAD_ANY_BODY, NL_MAX_WORKERS as MAX_WORKERS, NL_MESH_MOVABLE as MESH_MOVABLE,
    NL_NAVMESH_LOAD_SAME_LEVEL as NAVMESH_LOAD_SAME_LEVEL, NL_NO_POLYGON as NO_POLYGON, NL_WORKERS_AUTO as WORKERS_AUTO,
};
