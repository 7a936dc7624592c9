using System;

namespace NavLink
{
    public sealed partial class World
    {
        /// <summary>A walker (World.DefaultAgentCapabilities()), height 2, speed 3.5, acceleration 8, gravity
        /// 9.81, avoidance on, never giving up (GiveUpSeconds 0), on the null navmesh at the origin:
        /// set Navmesh and Position.</summary>
        public static AgentDef DefaultAgentDef() { LibraryCheck.EnsureLoaded(); return Native.nl_default_agent_def(); }

        /// <summary>Adds an agent standing still (AgentState.Idle) at the navmesh point of def.Position
        /// (NavLinkException with NotFound when it is off the navmesh).</summary>
        public unsafe AgentId AddAgent(AgentDef def)
        {
            AgentId id;
            using (var w = Enter()) Status.Check(Native.nl_agent_add(w.Pointer, &def, &id));
            return id;
        }

        public void RemoveAgent(AgentId agent)
        {
            using (var w = Enter()) Status.Check(Native.nl_agent_remove(w.Pointer, agent));
        }

        public bool IsValid(AgentId agent)
        {
            using (var w = Enter()) return Native.nl_agent_is_valid(w.Pointer, agent) != 0;
        }

        /// <summary>Sends the agent to the navmesh point of destination, on its navmesh or else on a navmesh that
        /// cross links join to it (a platform, a ledge across a chasm); NotFound on none of them (the destination
        /// is not kept). One on a navmesh that rides a moving mesh moves with the mesh. Its path is planned in a
        /// coming Step.</summary>
        public unsafe void SetAgentDestination(AgentId agent, Vec3 destination)
        {
            using (var w = Enter()) Status.Check(Native.nl_agent_set_destination(w.Pointer, agent, (float*)&destination));
        }

        /// <summary>Forgets the destination: the agent stands (AgentState.Idle); one in the air lands first.</summary>
        public void StopAgent(AgentId agent)
        {
            using (var w = Enter()) Status.Check(Native.nl_agent_stop(w.Pointer, agent));
        }

        /// <summary>Puts the agent at the navmesh point of position, keeping its destination (refused while it
        /// is taking a link).</summary>
        public unsafe void TeleportAgent(AgentId agent, Vec3 position)
        {
            using (var w = Enter()) Status.Check(Native.nl_agent_teleport(w.Pointer, agent, (float*)&position));
        }

        /// <summary>Changes what the agent's body can do; it plans again.</summary>
        public unsafe void SetAgentCapabilities(AgentId agent, AgentCapabilities capabilities)
        {
            using (var w = Enter()) Status.Check(Native.nl_agent_set_capabilities(w.Pointer, agent, &capabilities));
        }

        public void SetAgentSpeed(AgentId agent, float maxSpeed, float maxAcceleration)
        {
            using (var w = Enter()) Status.Check(Native.nl_agent_set_speed(w.Pointer, agent, maxSpeed, maxAcceleration));
        }

        /// <summary>Advances every agent by dt seconds (finite, &gt;= 0) on the world's workers, with the same
        /// result whatever their number. An agent's trouble is its AgentState.Failed and AgentEventKind.Failed,
        /// not an exception. Then read GetAgents() and GetAgentEvents().</summary>
        public void Step(float dt)
        {
            using (var w = Enter()) Status.Check(Native.nl_world_step(w.Pointer, dt));
        }

        public unsafe AgentInfo GetAgentInfo(AgentId agent)
        {
            AgentInfo info = Native.nl_agent_info_init();
            using (var w = Enter()) Status.Check(Native.nl_agent_get_info(w.Pointer, agent, &info));
            return info;
        }

        /// <summary>Every agent's state, in a stable order until an agent is removed.</summary>
        public unsafe AgentInfo[] GetAgents()
        {
            using (var w = Enter())
            {
                IntPtr world = w.Pointer;
                return ListTwoCall<AgentInfo>((buffer, capacity, count) =>
                    Native.nl_world_get_agents(world, (AgentInfo*)buffer, capacity, count), Native.nl_agent_info_init());
            }
        }

        /// <summary>The path points the agent has yet to reach, the next first: where it walks, and at which
        /// point it takes which link (PathPoint.Segment, Link). A route that leaves its navmesh ends at the
        /// take-off of the cross link, with that link.</summary>
        public unsafe PathPoint[] GetAgentCorners(AgentId agent)
        {
            using (var w = Enter())
            {
                IntPtr world = w.Pointer;
                return ListTwoCall<PathPoint>((buffer, capacity, count) =>
                    Native.nl_agent_get_corners(world, agent, (PathPoint*)buffer, capacity, count), Native.nl_path_point_init());
            }
        }

        /// <summary>The trajectory of the link the agent is taking now; false while it is on the ground (the
        /// library's kind TrajectoryKind.None), also while it waits at a take-off. In the world: a link within a
        /// navmesh that rides a moving mesh is given where the mesh is now; a cross link is flown in the world, to
        /// where its landing was expected to be at landing time.</summary>
        public unsafe bool TryGetAgentTrajectory(AgentId agent, out AgentTrajectory trajectory)
        {
            AgentTrajectory found = Native.nl_agent_trajectory_init();
            using (var w = Enter()) Status.Check(Native.nl_agent_get_trajectory(w.Pointer, agent, &found));
            trajectory = found;
            return found.Kind != TrajectoryKind.None;
        }

        /// <summary>The events of the last Step, in agent order. They stay until the next Step: read them
        /// once per step.</summary>
        public unsafe AgentEvent[] GetAgentEvents()
        {
            using (var w = Enter())
            {
                IntPtr world = w.Pointer;
                return ListTwoCall<AgentEvent>((buffer, capacity, count) =>
                    Native.nl_world_get_agent_events(world, (AgentEvent*)buffer, capacity, count), Native.nl_agent_event_init());
            }
        }
    }
}
