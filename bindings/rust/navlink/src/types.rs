//! navlink-sys's plain-data structs (ids, rays, bodies: no `size`, no `reserved`) under Rust names, plain
//! Rust structs for the ones that carry `size` or `reserved`, and the header's constants grouped by meaning.
use crate::error::Status;
use crate::kinds::{AgentEventKind, AgentReason, AgentState, LinkKind, PathOutcome, RecastPartition, TrajectoryKind, UpAxis};
use crate::level::MeshFlags;
use crate::navmesh::BuildWarnings;
use crate::plain::plain_struct;
use navlink_sys as sys;

pub type Version = sys::nl_version;
pub type MeshId = sys::nl_mesh_id;
pub type Ray = sys::nl_ray;
pub type Segment = sys::nl_segment;
pub type NavmeshId = sys::nl_navmesh_id;
pub type AgentType = sys::nl_agent_type;
pub type BoundaryEdge = sys::nl_boundary_edge;
pub type LinkId = sys::nl_link_id;
pub type PathTicket = sys::nl_path_ticket;
pub type AgentCapabilities = sys::nl_agent_capabilities;
pub type PluginId = sys::nl_plugin_id;
pub type AgentId = sys::nl_agent_id;
/// One straight walk for `World::raycast_batch` (`nl_navmesh_ray`): `start` over `start_polygon`, towards `end`.
pub type NavmeshRay = sys::nl_navmesh_ray;

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

pub use navlink_sys::{
    NL_AREA_EXCLUDED as AREA_EXCLUDED, NL_LINKS_LOAD_ANY_BODY as LINKS_LOAD_ANY_BODY, NL_MAX_WORKERS as MAX_WORKERS, NL_MESH_MAX_AREA as MESH_MAX_AREA,
    NL_NAVMESH_LOAD_SAME_LEVEL as NAVMESH_LOAD_SAME_LEVEL, NL_NO_ISLAND as NO_ISLAND, NL_NO_POLYGON as NO_POLYGON, NL_WORKERS_AUTO as WORKERS_AUTO,
};

plain_struct! {
    /// One point of a path (`nl_path_point`).
    pub struct PathPoint mirrors sys::nl_path_point, default sys::nl_path_point_init(), derives (PartialEq) {
        /// In the world, at the carrier's pose when the path was planned.
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
        carrier_position: [f32; 3],
    }
}

plain_struct! {
    /// What a finished request found, besides its points (`nl_path_result`).
    pub struct PathSummary mirrors sys::nl_path_result, default sys::nl_path_result_init(), derives (PartialEq) {
        outcome: PathOutcome,
        /// For `PathOutcome::Failed`, the `nl_status` saying why; `SUCCESS` otherwise. Prints by name.
        status: Status,
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
        /// Seconds held up by bodies heading the other way without getting 1 m nearer its destination
        /// along its path before it gives the destination up (`AgentState::Failed`,
        /// `AgentReason::Crowd`); 0 (default): never.
        give_up_seconds: f32,
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
        /// In the world, where it is now (on a carrier it moves with the carrier).
        destination: [f32; 3],
        has_destination: bool,
        corners_ahead: u32,
        user_data: u64,
        /// The navmesh it stands on now (it changes when the agent takes a cross link; in the air, the one
        /// it took off from).
        navmesh: NavmeshId,
        /// The movable mesh that navmesh rides, its carrier (the agent rides it too), or the null id.
        carrier: MeshId,
        /// `position` in that mesh's own space.
        carrier_position: [f32; 3],
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

plain_struct! {
    /// A registered mesh (`nl_mesh_info`).
    pub struct MeshInfo mirrors sys::nl_mesh_info, default sys::nl_mesh_info_init(), derives (PartialEq) {
        vertex_count: u32,
        /// Triangles kept (degenerate ones excluded).
        triangle_count: u32,
        degenerate_triangle_count: u32,
        flags: MeshFlags,
        /// Column-major 4x4 affine matrix.
        transform: [f32; 16],
        bounds_min: [f32; 3],
        bounds_max: [f32; 3],
        user_data: u64,
        /// As given in the mesh's options (`MeshOptions::area`).
        area: u32,
        /// As given in the mesh's options (`MeshOptions::metres_per_unit`; 0 = not said).
        metres_per_unit: f32,
        /// As given in the mesh's options (`MeshOptions::up_axis`).
        up_axis: UpAxis,
    }
}

plain_struct! {
    /// What a ray met (`nl_ray_hit`); every field but `hit` is zero for a miss.
    pub struct RayHit mirrors sys::nl_ray_hit, default sys::nl_ray_hit_init(), derives (PartialEq) {
        distance: f32,
        point: [f32; 3],
        normal: [f32; 3],
        mesh: MeshId,
        /// The triangle's index in the mesh's input.
        triangle: u32,
        hit: bool,
    }
}

plain_struct! {
    /// A navmesh's counts, body and bounds (`nl_navmesh_info`).
    pub struct NavmeshInfo mirrors sys::nl_navmesh_info, default sys::nl_navmesh_info_init(), derives (PartialEq) {
        vertex_count: u32,
        polygon_count: u32,
        portal_count: u32,
        boundary_edge_count: u32,
        welded_vertex_count: u32,
        flipped_polygon_count: u32,
        dropped_polygon_count: u32,
        non_manifold_edge_count: u32,
        agent_type: AgentType,
        /// In the world; for a navmesh that rides a moving mesh, a box that holds it where the mesh is now.
        bounds_min: [f32; 3],
        bounds_max: [f32; 3],
        /// The movable mesh it rides (its carrier); the null id for none.
        carrier: MeshId,
        /// Meshes `World::build_navmesh` built it on that look wound clockwise: turned over, they would hold
        /// much more floor for its agent than as given (the build also logs a warning naming them and
        /// `MeshFlags::CLOCKWISE`). 0 for a navmesh added from polygons or loaded from a file.
        turned_over_mesh_count: u32,
        /// What `World::build_navmesh` found wrong with its level (each also said in a warning in the log).
        /// `BuildWarnings::NONE` for a navmesh added from polygons or loaded from a file.
        build_warnings: BuildWarnings,
    }
}

plain_struct! {
    /// One navmesh polygon (`nl_nav_polygon`): the first `vertex_count` entries of `vertices` and
    /// `neighbours` are used (`NO_POLYGON`: no neighbour across that edge).
    pub struct NavPolygon mirrors sys::nl_nav_polygon, default sys::nl_nav_polygon_init(), derives (PartialEq) {
        vertex_count: u32,
        vertices: [u32; sys::NL_MAX_POLYGON_VERTICES],
        neighbours: [u32; sys::NL_MAX_POLYGON_VERTICES],
        area: u32,
        normal: [f32; 3],
        centre: [f32; 3],
    }
}

plain_struct! {
    /// The navmesh point nearest a query point (`nl_nav_point`); `polygon` is `NO_POLYGON` when not `found`.
    pub struct NavPoint mirrors sys::nl_nav_point, default sys::nl_nav_point::default(), derives (PartialEq) {
        point: [f32; 3],
        distance: f32,
        polygon: u32,
        found: bool,
        /// Why `found` is false: the navmesh's nearest point lies beyond the search box; `point` and
        /// `distance` then give that point (`polygon` stays `NO_POLYGON`). False when found.
        beyond_box: bool,
    }
}

plain_struct! {
    /// How far a straight walk along a navmesh went (`nl_navmesh_raycast_hit`, `World::raycast`).
    pub struct NavmeshRaycastHit mirrors sys::nl_navmesh_raycast_hit, default sys::nl_navmesh_raycast_hit_init(), derives (PartialEq) {
        /// A wall (the navmesh's outline, or an excluded area) stopped the walk before its end.
        hit: bool,
        /// The fraction of start to end walked (seen from above): 1 if it arrived.
        t: f32,
        /// Where it stopped (or the end), at the navmesh surface's height.
        point: [f32; 3],
        /// The wall's normal, horizontal, pointing back the way the walk came; zero if it arrived.
        wall_normal: [f32; 3],
        /// The polygon holding `point`.
        end_polygon: u32,
        /// Polygons crossed, the start polygon first and `end_polygon` last.
        polygon_count: u32,
    }
}

plain_struct! {
    /// The Recast builder's settings (`nl_recast_settings`); `Default` is `default_recast_settings()`.
    pub struct RecastSettings mirrors sys::nl_recast_settings, default unsafe { sys::nl_default_recast_settings() }, derives (PartialEq) {
        cell_size: f32,
        cell_height: f32,
        region_min_size: f32,
        region_merge_size: f32,
        edge_max_length: f32,
        edge_max_error: f32,
        vertices_per_polygon: u32,
        detail_sample_distance: f32,
        detail_sample_max_error: f32,
        partition: RecastPartition,
        filter_low_hanging_obstacles: bool,
        filter_ledge_spans: bool,
        filter_walkable_low_height_spans: bool,
    }
}

plain_struct! {
    /// What a link asks of the body taking it (`nl_link_requirements`); `Default`: all zero.
    pub struct LinkRequirements mirrors sys::nl_link_requirements, default sys::nl_link_requirements::default(), derives (PartialEq) {
        gap: f32,
        rise: f32,
        drop: f32,
        clearance_width: f32,
        abilities: u64,
        length: f32,
    }
}

plain_struct! {
    /// A link as the world holds it (`nl_link`).
    pub struct Link mirrors sys::nl_link, default sys::nl_link_init(), derives (PartialEq) {
        kind: LinkKind,
        id: LinkId,
        navmesh: NavmeshId,
        start: [f32; 3],
        end: [f32; 3],
        apex: [f32; 3],
        bidirectional: bool,
        /// Made by link generation (else added by the host).
        generated: bool,
        enabled: bool,
        cost_modifier: f32,
        start_polygon: u32,
        end_polygon: u32,
        user_data: u64,
        requirements: LinkRequirements,
        /// For a cross link, the navmesh its end is on; the null id for a link within `navmesh`
        /// (`LinkExt::landing` reads it as an `Option`).
        landing_navmesh: NavmeshId,
        /// A cross link's: how far its end may move, seen from its start, before it stops holding; 0 for
        /// other links.
        tolerance: f32,
        /// The link can be taken as the navmeshes stand now: always for a link within one navmesh; for a
        /// cross link, while its end, seen from its start, is within `tolerance` of where it was.
        holds: bool,
    }
}

plain_struct! {
    /// How to add or update a link (`nl_link_def`); `Default` is `default_link_def()`.
    pub struct LinkDef mirrors sys::nl_link_def, default unsafe { sys::nl_default_link_def() }, derives (PartialEq) {
        kind: LinkKind,
        start: [f32; 3],
        end: [f32; 3],
        bidirectional: bool,
        enabled: bool,
        /// false: `requirements`' gap, length, rise and drop are measured from the ends; true: all of
        /// `requirements` as given.
        requirements_as_given: bool,
        cost_modifier: f32,
        user_data: u64,
        requirements: LinkRequirements,
        /// The null id: both ends on the link's navmesh; another navmesh: a cross link onto it
        /// (`LinkDefExt::with_landing`).
        landing_navmesh: NavmeshId,
        /// Of a cross link, metres (>= 0).
        tolerance: f32,
    }
}

plain_struct! {
    /// What a link generation did (`nl_link_generation_report`).
    pub struct LinkGenerationReport mirrors sys::nl_link_generation_report, default sys::nl_link_generation_report_init(), derives (PartialEq) {
        edges: u32,
        groups: u32,
        samples: u32,
        takeoff_points: u32,
        jump_candidates: u32,
        drop_candidates: u32,
        jump_links: u32,
        drop_links: u32,
        plugin_links: u32,
        rejected_wall: u32,
        rejected_not_ledge: u32,
        rejected_distance: u32,
        rejected_rise: u32,
        rejected_angle: u32,
        rejected_no_landing: u32,
        rejected_clearance: u32,
        rejected_duplicate: u32,
        rays_cast: u64,
        milliseconds_edges: f64,
        milliseconds_takeoff: f64,
        milliseconds_jumps: f64,
        milliseconds_drops: f64,
        milliseconds_merge: f64,
        milliseconds_total: f64,
        box_queries: u64,
        body_tests: u64,
        rejected_walkable: u32,
        rejected_too_shallow: u32,
        rejected_too_deep: u32,
    }
}

plain_struct! {
    /// What a navmesh file holds and was made for (`nl_navmesh_file_info`, from `describe_navmesh_file`).
    pub struct NavmeshFileInfo mirrors sys::nl_navmesh_file_info, default sys::nl_navmesh_file_info::default(), derives (PartialEq) {
        /// The file's format version.
        version: u32,
        /// Bytes.
        file_size: u64,
        /// The body the navmesh was made for.
        agent_type: AgentType,
        vertex_count: u32,
        polygon_count: u32,
        /// 0: no height detail.
        detail_triangle_count: u32,
        link_count: u32,
        /// Of `link_count`, made by link generation.
        generated_link_count: u32,
        /// Its coordinates are in the space of a movable mesh it rode (load it with
        /// `NavmeshLoadOptions::carrier`).
        rides_carrier: bool,
        /// Metres per step of its fixed-point coordinates (1/1024).
        quantum: f32,
        /// Of the level triangles it was built from; 0: handed over by the host.
        level_hash: u64,
    }
}

#[cfg(test)]
mod tests {
    //! `to_c` over a C value with only `size` set rebuilds the C default: every field but `size` and
    //! `reserved` is mirrored, so nothing the header sets is lost on the way through the plain struct.
    use super::*;

    #[test]
    fn link_def_default_is_the_c_default_whole() {
        let c = unsafe { sys::nl_default_link_def() };
        let plain = LinkDef::default();
        assert_eq!(plain.to_c(sys::nl_link_def { size: c.size, ..Default::default() }), c);
        assert_eq!((plain.kind, plain.enabled, plain.bidirectional, plain.requirements_as_given), (LinkKind::Manual, true, false, false));
        assert_eq!((plain.cost_modifier, plain.tolerance, plain.landing_navmesh), (1.0, 0.25, NavmeshId::default()));
    }

    #[test]
    fn recast_settings_default_is_the_c_default_whole() {
        let c = unsafe { sys::nl_default_recast_settings() };
        assert_eq!(RecastSettings::default().to_c(sys::nl_recast_settings { size: c.size, ..Default::default() }), c);
    }

    #[test]
    fn link_round_trips_with_every_field() {
        let mut c = sys::nl_link_init();
        c.kind = sys::NL_LINK_FIRST_PLUGIN_KIND + 4;
        c.id = LinkId { index1: 2, revision: 3 };
        c.navmesh = NavmeshId { index1: 1, revision: 1 };
        c.start = [1.0, 2.0, 3.0];
        c.end = [4.0, 5.0, 6.0];
        c.apex = [2.5, 7.0, 4.5];
        c.bidirectional = 1;
        c.generated = 1;
        c.enabled = 0;
        c.cost_modifier = 1.5;
        c.start_polygon = 7;
        c.end_polygon = 8;
        c.user_data = 99;
        c.requirements = sys::nl_link_requirements { gap: 1.0, rise: 2.0, drop: 3.0, clearance_width: 0.5, abilities: 6, length: 4.0, reserved: 0 };
        c.landing_navmesh = NavmeshId { index1: 5, revision: 2 };
        c.tolerance = 0.3;
        c.holds = 1;
        let plain = Link::from(c);
        assert_eq!(plain.kind, LinkKind::Other(sys::NL_LINK_FIRST_PLUGIN_KIND + 4));
        assert!(plain.kind.is_plugin() && plain.bidirectional && plain.generated && !plain.enabled && plain.holds);
        assert_eq!(plain.requirements.abilities, 6);
        assert_eq!(plain.to_c(sys::nl_link_init()), c);
    }

    #[test]
    fn output_structs_round_trip() {
        let mut hit = sys::nl_ray_hit_init();
        hit.distance = 2.0;
        hit.hit = 1;
        hit.mesh = MeshId { index1: 1, revision: 4 };
        assert_eq!(RayHit::from(hit).to_c(sys::nl_ray_hit_init()), hit);
        assert!(RayHit::from(hit).hit);

        let mut info = sys::nl_mesh_info_init();
        info.flags = sys::NL_MESH_MOVABLE | sys::NL_MESH_OBSTACLE | 0x100;
        info.area = 3;
        info.metres_per_unit = 0.01;
        info.up_axis = sys::NL_UP_AXIS_Z;
        let plain = MeshInfo::from(info);
        assert!(plain.flags.contains(MeshFlags::MOVABLE | MeshFlags::OBSTACLE) && plain.flags.to_raw() & 0x100 != 0);
        assert_eq!((plain.metres_per_unit, plain.up_axis), (0.01, UpAxis::Z));
        assert_eq!(plain.to_c(sys::nl_mesh_info_init()), info);

        let mut file = sys::nl_navmesh_file_info::default();
        file.rides_carrier = 1;
        file.level_hash = 0xfeed;
        let plain = NavmeshFileInfo::from(file);
        assert!(plain.rides_carrier);
        assert_eq!(plain.to_c(sys::nl_navmesh_file_info::default()), file);

        let point = sys::nl_nav_point { point: [1.0, 0.0, 2.0], distance: 0.5, polygon: 9, found: 1, beyond_box: 0, reserved: [0; 2] };
        assert!(NavPoint::from(point).found && !NavPoint::from(point).beyond_box);
        assert_eq!(NavPoint::from(point).to_c(sys::nl_nav_point::default()), point);
        let beyond = sys::nl_nav_point { found: 0, beyond_box: 1, polygon: sys::NL_NO_POLYGON, ..point };
        assert!(NavPoint::from(beyond).beyond_box);
        assert_eq!(NavPoint::from(beyond).to_c(sys::nl_nav_point::default()), beyond);

        let hit = sys::nl_navmesh_raycast_hit {
            hit: 1,
            t: 0.375,
            point: [2.0, 0.0, 0.5],
            wall_normal: [-1.0, 0.0, 0.0],
            end_polygon: 1,
            polygon_count: 2,
            ..sys::nl_navmesh_raycast_hit_init()
        };
        assert!(NavmeshRaycastHit::from(hit).hit);
        assert_eq!(NavmeshRaycastHit::from(hit).to_c(sys::nl_navmesh_raycast_hit_init()), hit);
    }
}
