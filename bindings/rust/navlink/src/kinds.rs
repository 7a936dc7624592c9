//! The header's `u32` kinds, states and outcomes as Rust enums. Each is `#[non_exhaustive]` and keeps a
//! value it does not know (a newer library's, a plugin's link kind) in `Other(raw)`, so reading a newer
//! library never fails and never loses the value.
use navlink_sys as sys;

/// An enum over one of the header's `u32` kinds, with `from_raw` and `to_raw`, and the conversions a plain
/// struct's field of it needs (plain.rs's `FromC`, `IntoC`).
macro_rules! c_enum {
    ($(#[$meta:meta])* pub enum $name:ident { $($(#[$variant_meta:meta])* $variant:ident = $raw:path,)* }) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        #[non_exhaustive]
        pub enum $name {
            $($(#[$variant_meta])* $variant,)*
            /// A value this binding has no name for.
            Other(u32),
        }

        impl $name {
            pub fn from_raw(raw: u32) -> Self {
                match raw {
                    $($raw => $name::$variant,)*
                    other => $name::Other(other),
                }
            }

            pub fn to_raw(self) -> u32 {
                match self {
                    $($name::$variant => $raw,)*
                    $name::Other(raw) => raw,
                }
            }
        }

        // A plain struct's field of this kind (plain.rs; the generated plain structs use any enum here).
        impl crate::plain::FromC<u32> for $name {
            fn from_c(c: u32) -> $name {
                $name::from_raw(c)
            }
        }

        impl crate::plain::IntoC<u32> for $name {
            fn into_c(self) -> u32 {
                self.to_raw()
            }
        }
    };
}

c_enum! {
    /// How a request ended (`nl_path_outcome`).
    pub enum PathOutcome {
        /// Not finished yet (also what a wait that timed out reports).
        Pending = sys::NL_PATH_PENDING,
        Complete = sys::NL_PATH_COMPLETE,
        /// As close to the goal as the search got (`accept_partial`).
        Partial = sys::NL_PATH_PARTIAL,
        NoPath = sys::NL_PATH_NO_PATH,
        StartOffNavmesh = sys::NL_PATH_START_OFF_NAVMESH,
        GoalOffNavmesh = sys::NL_PATH_GOAL_OFF_NAVMESH,
        Cancelled = sys::NL_PATH_CANCELLED,
        Failed = sys::NL_PATH_FAILED,
    }
}

c_enum! {
    /// Why a path falls short of its goal (`PathShortfall::reason`, `NL_PATH_SHORTFALL_*`).
    pub enum PathShortfallReason {
        /// It reaches the goal, or an end is off the navmesh (the outcome says so).
        None = sys::NL_PATH_SHORTFALL_NONE,
        /// `max_nodes` stopped the search.
        OutOfNodes = sys::NL_PATH_SHORTFALL_OUT_OF_NODES,
        /// A body of the navmesh's radius would get there: passages on the way are too narrow for this one.
        BodyTooWide = sys::NL_PATH_SHORTFALL_BODY_TOO_WIDE,
        /// Areas the request keeps the body out of stand in the way.
        AreasExcluded = sys::NL_PATH_SHORTFALL_AREAS_EXCLUDED,
        /// A link would get there, and the body cannot take it (`limit`, `needed`, `has`, `link`).
        LinkBeyondBody = sys::NL_PATH_SHORTFALL_LINK_BEYOND_BODY,
        /// The goal is on another island of the navmesh, and the navmesh has no links.
        NoLinks = sys::NL_PATH_SHORTFALL_NO_LINKS,
        /// No passage or link leads there, whatever the body.
        NotConnected = sys::NL_PATH_SHORTFALL_NOT_CONNECTED,
    }
}

c_enum! {
    /// What a link asks that the body lacks (`PathShortfall::limit`, `NL_LINK_LIMIT_*`).
    pub enum LinkLimit {
        None = sys::NL_LINK_LIMIT_NONE,
        /// The gap, against `max_jump_distance`.
        JumpDistance = sys::NL_LINK_LIMIT_JUMP_DISTANCE,
        /// The rise, against `max_jump_height`.
        JumpHeight = sys::NL_LINK_LIMIT_JUMP_HEIGHT,
        /// The drop, against `max_drop_height`.
        DropHeight = sys::NL_LINK_LIMIT_DROP_HEIGHT,
        /// The body's diameter, against the link's clearance.
        Width = sys::NL_LINK_LIMIT_WIDTH,
        /// Ability bits the body lacks (`missing_abilities`).
        Abilities = sys::NL_LINK_LIMIT_ABILITIES,
    }
}

c_enum! {
    /// How a path segment is travelled: walking, or the kind of link taken (`nl_link_kind`); also a link's
    /// kind (`Link::kind`, `LinkDef::kind`). A plugin's kinds are `Other(k)` with
    /// `k >= LinkKind::FIRST_PLUGIN_KIND`.
    pub enum LinkKind {
        /// A path segment that walks; never a link's kind.
        Walk = sys::NL_SEGMENT_WALK,
        Jump = sys::NL_LINK_JUMP,
        Drop = sys::NL_LINK_DROP,
        Manual = sys::NL_LINK_MANUAL,
    }
}

impl LinkKind {
    /// The first raw kind a link-kind plugin can register (`NL_LINK_FIRST_PLUGIN_KIND`).
    pub const FIRST_PLUGIN_KIND: u32 = sys::NL_LINK_FIRST_PLUGIN_KIND;

    /// A kind a link-kind plugin registered.
    pub fn is_plugin(self) -> bool {
        self.to_raw() >= sys::NL_LINK_FIRST_PLUGIN_KIND
    }
}

c_enum! {
    /// How the Recast builder partitions the walkable area into regions (`RecastSettings::partition`,
    /// `NL_RECAST_PARTITION_*`).
    pub enum RecastPartition {
        Watershed = sys::NL_RECAST_PARTITION_WATERSHED,
        Monotone = sys::NL_RECAST_PARTITION_MONOTONE,
        Layers = sys::NL_RECAST_PARTITION_LAYERS,
    }
}

c_enum! {
    /// What an agent is doing (`AgentInfo::state`).
    pub enum AgentState {
        Idle = sys::NL_AGENT_IDLE,
        Walking = sys::NL_AGENT_WALKING,
        Jumping = sys::NL_AGENT_JUMPING,
        Falling = sys::NL_AGENT_FALLING,
        Traversing = sys::NL_AGENT_TRAVERSING,
        /// Its path waits its turn (`WorldOptions::agent_paths_per_step`).
        Waiting = sys::NL_AGENT_WAITING,
        Arrived = sys::NL_AGENT_ARRIVED,
        Failed = sys::NL_AGENT_FAILED,
    }
}

c_enum! {
    /// Why an agent planned again or failed (`AgentInfo::reason`, `AgentEvent::reason`).
    pub enum AgentReason {
        None = sys::NL_AGENT_REASON_NONE,
        DestinationSet = sys::NL_AGENT_REASON_DESTINATION_SET,
        LinkGone = sys::NL_AGENT_REASON_LINK_GONE,
        WorldChanged = sys::NL_AGENT_REASON_WORLD_CHANGED,
        OffPath = sys::NL_AGENT_REASON_OFF_PATH,
        NoPath = sys::NL_AGENT_REASON_NO_PATH,
        NavmeshRemoved = sys::NL_AGENT_REASON_NAVMESH_REMOVED,
        CapabilitiesChanged = sys::NL_AGENT_REASON_CAPABILITIES_CHANGED,
        /// Other bodies are in its way: it waits for room (`AgentEventKind::Waiting`; `AgentInfo` reads
        /// `AgentState::Waiting` with this reason meanwhile), or it gave its destination up after
        /// `AgentDef::give_up_seconds` (`AgentState::Failed`).
        Crowd = sys::NL_AGENT_REASON_CROWD,
        /// The tile it stands on was removed (`World::remove_tile`): it waits where it stood
        /// (`AgentEventKind::Waiting`; `AgentInfo` reads `AgentState::Waiting` with this reason) until a tile
        /// holds it again, then plans again.
        TileUnloaded = sys::NL_AGENT_REASON_TILE_UNLOADED,
    }
}

c_enum! {
    /// What happened to an agent in the last step (`AgentEvent::kind`).
    pub enum AgentEventKind {
        PathReady = sys::NL_AGENT_EVENT_PATH_READY,
        LinkStarted = sys::NL_AGENT_EVENT_LINK_STARTED,
        LinkFinished = sys::NL_AGENT_EVENT_LINK_FINISHED,
        Arrived = sys::NL_AGENT_EVENT_ARRIVED,
        Failed = sys::NL_AGENT_EVENT_FAILED,
        Replanned = sys::NL_AGENT_EVENT_REPLANNED,
        /// It stopped for room (`AgentReason::Crowd`): stuck among other bodies for 0.75 s, or giving way
        /// to one; its `AgentInfo` reads `AgentState::Waiting`, reason `Crowd`, until it walks on; or for its
        /// tile (`AgentReason::TileUnloaded`). Said once per wait.
        Waiting = sys::NL_AGENT_EVENT_WAITING,
    }
}

c_enum! {
    /// Which axis of a mesh's vertices points up (`MeshOptions::up_axis`, `MeshInfo::up_axis`). NavLink's own
    /// frame is right-handed with y up.
    pub enum UpAxis {
        /// The default: y up, and a navmesh build warns when the level would hold much more floor with z up
        /// (`BuildWarnings::Z_UP`).
        NotSaid = sys::NL_UP_AXIS_NOT_SAID,
        /// Y up, said: no such warning.
        Y = sys::NL_UP_AXIS_Y,
        /// Z up (Blender's, Unreal's, 3ds Max's own frame): turned to y up when registered, (x, y, z) becoming
        /// (x, z, -y), a rotation, so fronts stay fronts.
        Z = sys::NL_UP_AXIS_Z,
    }
}

impl Default for UpAxis {
    fn default() -> Self {
        UpAxis::NotSaid
    }
}

c_enum! {
    /// How a link is being taken (`AgentTrajectory::kind`); `World::agent_trajectory` gives `None`
    /// rather than the library's "none".
    pub enum TrajectoryKind {
        Arc = sys::NL_TRAJECTORY_ARC,
        Fall = sys::NL_TRAJECTORY_FALL,
        Line = sys::NL_TRAJECTORY_LINE,
    }
}
