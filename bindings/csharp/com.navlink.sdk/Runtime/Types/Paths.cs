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

    /// <summary>nl_path_point: one point of a path and how the agent goes on from it. An array element that
    /// may grow: the library lays out an output array with its first element's Size (Native.nl_path_point_init()).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct PathPoint
    {
        public uint Size;
        public Vec3 Position;
        public uint Polygon;
        /// <summary>LinkKind.Walk, or the kind of the link taken to the next point (Walk at the last point of a
        /// path; an agent's corners, whose route leaves its navmesh, end at a cross link's take-off, with that
        /// link).</summary>
        public LinkKind Segment;
        public LinkId Link;
        public Vec3 Apex;
        public byte Reversed;
        public fixed byte Reserved[3];
        /// <summary>The point in its navmesh's own space (Position and Apex are in the world, at the surface's
        /// pose when the path was planned); equal to Position on a navmesh that rides nothing. Added in 0.3.</summary>
        public Vec3 SurfacePosition;
    }

    /// <summary>nl_path_result. Get one from Native.nl_path_result_init() (Size set) before asking.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct PathResultInfo
    {
        public uint Size;
        public PathOutcome Outcome;
        public StatusCode Status;
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

    /// <summary>nl_path_shortfall: why a request's path falls short of its goal (Native.nl_path_explain). Get one
    /// from Native.nl_path_shortfall_init() (Size set) before asking. World.ExplainPath returns a PathShortfall
    /// instead, with Text as a string.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct PathShortfallInfo
    {
        public uint Size;
        public PathShortfallReason Reason;
        /// <summary>For PathShortfallReason.LinkBeyondBody: what the link asks that the body lacks.</summary>
        public LinkLimit Limit;
        /// <summary>LinkBeyondBody: what the link needs, metres (for LinkLimit.Width the body's diameter);
        /// BodyTooWide: the body's radius.</summary>
        public float Needed;
        /// <summary>LinkBeyondBody: what the body can, metres (for LinkLimit.Width the link's clearance);
        /// BodyTooWide: the navmesh's radius.</summary>
        public float Has;
        /// <summary>1 if the link would be taken from its end to its start.</summary>
        public uint Reversed;
        /// <summary>LinkLimit.Abilities: the bits the body lacks.</summary>
        public ulong MissingAbilities;
        /// <summary>LinkBeyondBody: the link; the null id otherwise.</summary>
        public LinkId Link;
        /// <summary>Where the body would take the link, in the world.</summary>
        public Vec3 LinkStart;
        /// <summary>The same as a NUL-terminated UTF-8 sentence naming the field to change ("" for None).</summary>
        public fixed byte Text[256];
    }

    /// <summary>How much World.ProcessPaths (nl_path_process) may do in one call: nl_path_budget. Get one from
    /// World.DefaultPathBudget() (no limits). A request is never split: the budget is checked between
    /// requests, so a call that finds the queue non-empty plans at least one.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct PathBudget
    {
        public uint Size;
        /// <summary>Requests planned at most; 0: no limit.</summary>
        public uint MaxRequests;
        /// <summary>Time spent at most; &lt;= 0: no limit.</summary>
        public double MaxMilliseconds;
        /// <summary>Polygons the searches may visit in all (their NodesVisited added up); 0: no limit.</summary>
        public ulong MaxSearchNodes;
    }

    /// <summary>nl_path_finished: a request that finished, as Native.nl_path_take_finished reports it. An
    /// array element that may grow (Native.nl_path_finished_init()). World.TakeFinishedPaths returns
    /// FinishedPath values instead: User is the request's raw `user`, which World uses for its callback.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct PathFinished
    {
        public uint Size;
        public PathOutcome Outcome;
        public PathTicket Ticket;
        public IntPtr User;
    }

    /// <summary>A request that finished since the last World.TakeFinishedPaths: its ticket and outcome.</summary>
    public struct FinishedPath : IEquatable<FinishedPath>
    {
        public readonly PathTicket Ticket;
        public readonly PathOutcome Outcome;

        public FinishedPath(PathTicket ticket, PathOutcome outcome)
        {
            Ticket = ticket;
            Outcome = outcome;
        }

        public bool Equals(FinishedPath o) { return Ticket.Equals(o.Ticket) && Outcome == o.Outcome; }
        public override bool Equals(object o) { return o is FinishedPath && Equals((FinishedPath)o); }
        public override int GetHashCode() { return Ticket.GetHashCode() * 31 + (int)Outcome; }
        public override string ToString() { return Ticket + ": " + Outcome; }
    }

    /// <summary>nl_path_queue_stats. Get one from Native.nl_path_queue_stats_init() (Size set) before asking.</summary>
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
