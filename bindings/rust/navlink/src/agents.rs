//! Agents: bodies that walk their navmesh, take the links their body can, and keep out of each other's
//! way. `World::step` moves them all; read their states (`agents`) and the step's events (`agent_events`)
//! in bulk afterwards.
use crate::error::{check, Result};
use crate::list::two_call_as;
use crate::types::{AgentCapabilities, AgentDef, AgentEvent, AgentId, AgentInfo, AgentTrajectory, MeshId, PathPoint};
use crate::world::World;
use navlink_sys as sys;

/// A walker (`default_agent_capabilities()`), height 2, speed 3.5, acceleration 8, gravity 9.81, avoidance
/// on, never giving up, on the null navmesh at the origin: set `navmesh` and `position`.
pub fn default_agent_def() -> AgentDef {
    AgentDef::default()
}

/// Where an `AgentInfo` says the agent stands (navlink.h 0.3), as Rust values. The raw fields stay:
/// `navmesh` (the navmesh it stands on now; it changes when the agent takes a cross link, and in the air
/// it is the one it took off from; never null) and `carrier_position` (`position` in the carrier's own
/// space, to parent the body to the platform; `position` itself on no carrier and in the air over a
/// cross link).
pub trait AgentInfoExt {
    /// The movable mesh the agent's navmesh rides (`carrier`), the agent with it; `None` for the null id.
    fn carrier_mesh(&self) -> Option<MeshId>;
}

impl AgentInfoExt for AgentInfo {
    fn carrier_mesh(&self) -> Option<MeshId> {
        if self.carrier == MeshId::default() {
            None
        } else {
            Some(self.carrier)
        }
    }
}

impl World {
    /// Adds an agent standing still (`AgentState::Idle`) at the navmesh point of `def.position`
    /// (NOT_FOUND when it is off the navmesh).
    pub fn add_agent(&self, def: &AgentDef) -> Result<AgentId> {
        let def = def.to_c(unsafe { sys::nl_default_agent_def() });
        let mut id = AgentId::default();
        check(unsafe { sys::nl_agent_add(self.raw(), &def, &mut id) })?;
        Ok(id)
    }

    pub fn remove_agent(&self, agent: AgentId) -> Result<()> {
        check(unsafe { sys::nl_agent_remove(self.raw(), agent) }).map(drop)
    }

    pub fn is_agent_valid(&self, agent: AgentId) -> bool {
        unsafe { sys::nl_agent_is_valid(self.raw(), agent) != 0 }
    }

    /// Sends the agent to the navmesh point of `destination`, on its navmesh or else on a navmesh that
    /// cross links join to it (a platform, a ledge across a chasm); NOT_FOUND on none of them (the
    /// destination is not kept). One on a navmesh that rides a moving mesh moves with the mesh. Its path
    /// is planned in a coming `step`.
    pub fn set_agent_destination(&self, agent: AgentId, destination: [f32; 3]) -> Result<()> {
        check(unsafe { sys::nl_agent_set_destination(self.raw(), agent, destination.as_ptr()) }).map(drop)
    }

    /// Forgets the destination: the agent stands (`AgentState::Idle`); one in the air lands first.
    pub fn stop_agent(&self, agent: AgentId) -> Result<()> {
        check(unsafe { sys::nl_agent_stop(self.raw(), agent) }).map(drop)
    }

    /// Puts the agent at the navmesh point of `position`, keeping its destination (refused while it is
    /// taking a link).
    pub fn teleport_agent(&self, agent: AgentId, position: [f32; 3]) -> Result<()> {
        check(unsafe { sys::nl_agent_teleport(self.raw(), agent, position.as_ptr()) }).map(drop)
    }

    /// Changes what the agent's body can do; it plans again.
    pub fn set_agent_capabilities(&self, agent: AgentId, capabilities: &AgentCapabilities) -> Result<()> {
        check(unsafe { sys::nl_agent_set_capabilities(self.raw(), agent, capabilities) }).map(drop)
    }

    pub fn set_agent_speed(&self, agent: AgentId, max_speed: f32, max_acceleration: f32) -> Result<()> {
        check(unsafe { sys::nl_agent_set_speed(self.raw(), agent, max_speed, max_acceleration) }).map(drop)
    }

    /// Advances every agent by `dt` seconds (finite, >= 0) on the world's workers, with the same result
    /// whatever their number. An agent's trouble is its `AgentState::Failed` and its event, not an `Err`.
    pub fn step(&self, dt: f32) -> Result<()> {
        check(unsafe { sys::nl_world_step(self.raw(), dt) }).map(drop)
    }

    pub fn agent_info(&self, agent: AgentId) -> Result<AgentInfo> {
        let mut info = sys::nl_agent_info_init();
        check(unsafe { sys::nl_agent_get_info(self.raw(), agent, &mut info) })?;
        Ok(info.into())
    }

    /// Every agent's state, in a stable order until an agent is removed.
    pub fn agents(&self) -> Result<Vec<AgentInfo>> {
        // two_call's buffer is of nl_agent_info::default(), whose size tells the library the element size.
        two_call_as(|buffer, capacity, count| unsafe { sys::nl_world_get_agents(self.raw(), buffer, capacity, count) })
    }

    /// The path points the agent has yet to reach, the next first: where it walks, and at which point it
    /// takes which link (`segment`, `link`). A route that leaves its navmesh ends at the take-off of the
    /// cross link, with that link.
    pub fn agent_corners(&self, agent: AgentId) -> Result<Vec<PathPoint>> {
        two_call_as(|buffer, capacity, count| unsafe { sys::nl_agent_get_corners(self.raw(), agent, buffer, capacity, count) })
    }

    /// The trajectory of the link the agent is taking now, or `None` while it is on the ground (the
    /// library's kind `NL_TRAJECTORY_NONE`), also while it waits at a take-off. In the world: a link within
    /// a navmesh that rides a moving mesh is given where the mesh is now; a cross link is flown in the
    /// world, to where its landing was expected to be at landing time.
    pub fn agent_trajectory(&self, agent: AgentId) -> Result<Option<AgentTrajectory>> {
        let mut trajectory = sys::nl_agent_trajectory_init();
        check(unsafe { sys::nl_agent_get_trajectory(self.raw(), agent, &mut trajectory) })?;
        Ok((trajectory.kind != sys::NL_TRAJECTORY_NONE).then(|| AgentTrajectory::from(trajectory)))
    }

    /// The events of the last `step`, in agent order. They stay until the next step: read them once per step.
    pub fn agent_events(&self) -> Result<Vec<AgentEvent>> {
        two_call_as(|buffer, capacity, count| unsafe { sys::nl_world_get_agent_events(self.raw(), buffer, capacity, count) })
    }
}
