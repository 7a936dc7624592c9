using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>nl_agent_def: how to add an agent. Get one from World.DefaultAgentDef() (a walker, height 2,
    /// speed 3.5, acceleration 8, gravity 9.81, avoidance on, never giving up) and set Navmesh
    /// and Position.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct AgentDef
    {
        public uint Size;
        public NavmeshId Navmesh;
        public float Height;
        /// <summary>What its body can do (the links it takes) and its radius.</summary>
        public AgentCapabilities Capabilities;
        /// <summary>Walking speed, m/s; also a drop's way out and manual and plugin links.</summary>
        public float MaxSpeed;
        public float MaxAcceleration;
        /// <summary>How long a jump's arc and a fall take.</summary>
        public float Gravity;
        /// <summary>&gt; 0: a jump's time comes from this take-off speed instead of gravity.</summary>
        public float TakeoffSpeed;
        /// <summary>Where it starts: on the navmesh, else NotFound.</summary>
        public Vec3 Position;
        /// <summary>1: steers around other agents.</summary>
        public byte Avoidance;
        public fixed byte Reserved[3];
        /// <summary>The host's, handed back in AgentInfo and AgentEvent.</summary>
        public ulong UserData;
        /// <summary>0 (default): never. Held up this long by bodies heading the other way (walking or giving
        /// way on the ground) without getting 1 m nearer its destination along its path, it gives the
        /// destination up: AgentState.Failed, AgentReason.Crowd. A queue, all one way, never counts. Added in
        /// 0.3.</summary>
        public float GiveUpSeconds;
        public uint Reserved2;
    }

    /// <summary>nl_agent_info: an agent's state. An array element that may grow: the library lays out an
    /// output array with its first element's Size (Native.nl_agent_info_init(); World sets it).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct AgentInfo
    {
        public uint Size;
        public AgentState State;
        public AgentId Id;
        /// <summary>Feet, on the surface (in the air: on the link's trajectory).</summary>
        public Vec3 Position;
        public Vec3 Velocity;
        /// <summary>The navmesh polygon it stands on (its take-off's while in the air).</summary>
        public uint Polygon;
        /// <summary>Why it failed, or why its current path was planned.</summary>
        public AgentReason Reason;
        /// <summary>The link it is taking, or waits to take; null otherwise.</summary>
        public LinkId Link;
        /// <summary>0..1 of the link's time.</summary>
        public float LinkProgress;
        /// <summary>Its destination, if HasDestination is 1: in the world, where it is now (on a moving surface
        /// it moves with the surface).</summary>
        public Vec3 Destination;
        public byte HasDestination;
        public fixed byte Reserved[3];
        /// <summary>Path points still to reach (World.GetAgentCorners).</summary>
        public uint CornersAhead;
        public ulong UserData;
        /// <summary>The navmesh it stands on now: it changes when the agent takes a cross link; while in the air,
        /// the one it took off from. Added in 0.3.</summary>
        public NavmeshId Navmesh;
        /// <summary>The movable mesh that navmesh rides (the agent rides it too), or the null id (IsNull).
        /// Added in 0.3.</summary>
        public MeshId Surface;
        /// <summary>Position in that mesh's own space (Position itself on no surface, and in the air over a
        /// cross link): to parent the body to the platform in the scene. Added in 0.3.</summary>
        public Vec3 SurfacePosition;
        public uint Reserved2;
    }

    /// <summary>nl_agent_trajectory: the link an agent is taking, as the generator checked it, with its timing,
    /// for a host that animates the body. Get one from Native.nl_agent_trajectory_init() (Size set).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct AgentTrajectory
    {
        public uint Size;
        public TrajectoryKind Kind;
        public LinkId Link;
        public Vec3 From;
        public Vec3 To;
        public Vec3 Apex;
        /// <summary>C's float[4][3], x y z of each point in turn: use Point(k). For TrajectoryKind.Fall;
        /// otherwise From, From, To, To.</summary>
        public fixed float Points[12];
        /// <summary>Seconds from take-off to landing.</summary>
        public float Duration;
        /// <summary>Seconds since take-off.</summary>
        public float Elapsed;

        /// <summary>Points[k], k in 0..3.</summary>
        public Vec3 Point(int k)
        {
            if (k < 0 || k > 3) throw new System.ArgumentOutOfRangeException("k");
            fixed (float* p = Points) return new Vec3(p[3 * k], p[3 * k + 1], p[3 * k + 2]);
        }
    }

    /// <summary>nl_agent_event: what happened to an agent in the last step. An array element that may grow
    /// (Native.nl_agent_event_init(); World sets it).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct AgentEvent
    {
        public uint Size;
        public AgentEventKind Kind;
        public AgentId Agent;
        public LinkId Link;
        public AgentReason Reason;
        public uint Reserved;
        /// <summary>The agent's.</summary>
        public ulong UserData;
    }
}
