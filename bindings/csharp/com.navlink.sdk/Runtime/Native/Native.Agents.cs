using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public static unsafe partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern AgentDef nl_default_agent_def();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_agent_add(IntPtr world, AgentDef* def, AgentId* outId);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_agent_remove(IntPtr world, AgentId agent);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern int nl_agent_is_valid(IntPtr world, AgentId agent);

        /// <summary>point: 3 floats.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_agent_set_destination(IntPtr world, AgentId agent, float* point);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_agent_stop(IntPtr world, AgentId agent);

        /// <summary>point: 3 floats.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_agent_teleport(IntPtr world, AgentId agent, float* point);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_agent_set_capabilities(IntPtr world, AgentId agent, AgentCapabilities* capabilities);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_agent_set_speed(IntPtr world, AgentId agent, float maxSpeed, float maxAcceleration);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_world_step(IntPtr world, float dt);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_agent_get_info(IntPtr world, AgentId agent, AgentInfo* outInfo);

        /// <summary>outInfos[0].Size set (nl_agent_info_init) when outInfos is not null.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_world_get_agents(IntPtr world, AgentInfo* outInfos, uint capacity, uint* outCount);

        /// <summary>outPoints[0].Size set (nl_path_point_init) when outPoints is not null.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_agent_get_corners(IntPtr world, AgentId agent, PathPoint* outPoints, uint capacity,
                                                       uint* outCount);

        /// <summary>NOT_FOUND (nothing written) while the agent is on the ground.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_agent_get_trajectory(IntPtr world, AgentId agent, AgentTrajectory* outTrajectory);

        /// <summary>outEvents[0].Size set (nl_agent_event_init) when outEvents is not null.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_world_get_agent_events(IntPtr world, AgentEvent* outEvents, uint capacity,
                                                            uint* outCount);
    }
}
