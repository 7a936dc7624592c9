using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>nl_agent_capabilities: what an agent's body can do.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct AgentCapabilities
    {
        public float MaxJumpDistance;
        public float MaxJumpHeight;
        public float MaxDropHeight;
        public float Radius;
        public ulong Abilities;
    }

    /// <summary>nl_path_request_def. AreaCosts is borrowed (copied by the call); Callback is a function
    /// pointer to a static NativeCallbacks.PathCallback, User its context (a GCHandle).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct PathRequestDef
    {
        public uint Size;
        public NavmeshId Navmesh;
        public Vec3 Start;
        public Vec3 Goal;
        public Vec3 SearchHalfExtents;
        public AgentCapabilities Agent;
        public IntPtr AreaCosts;
        public uint AreaCostCount;
        public float LinkCost;
        public uint MaxNodes;
        public byte AcceptPartial;
        public fixed byte Reserved[3];
        public IntPtr Callback;
        public IntPtr User;
    }

    /// <summary>nl_path_point: one point of a path and how the agent goes on from it.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct PathPoint
    {
        public Vec3 Position;
        public uint Polygon;
        /// <summary>LinkKind.Walk, or the kind of the link taken to the next point.</summary>
        public uint Segment;
        public LinkId Link;
        public Vec3 Apex;
        public byte Reversed;
        public fixed byte Reserved[3];
    }

    /// <summary>nl_path_result. Set Size before asking.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct PathResultInfo
    {
        public uint Size;
        public PathOutcome Outcome;
        public uint Status;
        public uint PointCount;
        public uint LinksUsed;
        public uint NodesVisited;
        public byte OutOfNodes;
        public fixed byte Reserved[3];
        public float Length;
        public float Cost;
        public Vec3 Start;
        public Vec3 Goal;
    }

    /// <summary>nl_path_queue_stats. Set Size before asking.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct PathQueueStats
    {
        public uint Size;
        public uint Workers;
        public uint Queued;
        public uint Running;
        public uint Unreleased;
        public uint Reserved;
        public ulong Submitted;
        public ulong Finished;
    }
}
