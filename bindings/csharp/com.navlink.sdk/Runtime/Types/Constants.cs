using System;

namespace NavLink
{
    // The #define constants of navlink.h, recast.h and plugin.h, grouped by what they qualify. (The tests
    // hold each integer one against the headers, both ways: Tests/LayoutTests.cs names each class's prefix.)

    /// <summary>The header version this binding was written from (navlink/version.h); World.LibraryVersion
    /// is the loaded library's.</summary>
    public static class HeaderVersion
    {
        public const int Major = 0;
        public const int Minor = 2;
        public const int Patch = 0;
    }

    /// <summary>An nl_status: one kind bit at the top (Failure, Success or InProgress) and detail bits below
    /// (navlink.h, "Status"); a failure may carry several details, so this is a [Flags] enum:
    /// <c>StatusCode.Failure | StatusCode.InvalidHandle</c> prints as "Failure, InvalidHandle". Test it with
    /// Status.Failed and Status.Has.</summary>
    [Flags]
    public enum StatusCode : uint
    {
        Failure = 0x80000000u,
        Success = 0x40000000u,
        InProgress = 0x20000000u,
        /// <summary>The detail bits, all of them.</summary>
        DetailMask = 0x0fffffffu,

        InvalidArgument = 0x00000001u,
        InvalidHandle = 0x00000002u,
        BufferTooSmall = 0x00000004u,
        OutOfMemory = 0x00000008u,
        Cancelled = 0x00000010u,
        PartialResult = 0x00000020u,
        NotFound = 0x00000040u,
        InternalError = 0x00000080u,
        IoError = 0x00000100u,
        ParseError = 0x00000200u,
        VersionMismatch = 0x00000400u,
    }

    public static class Limits
    {
        public const float CoordinateLimit = 1.0e9f;
        public const int WorkersAuto = -1;
        public const int MaxWorkers = 1024;
        public const int MaxPolygonVertices = 16;
        public const uint NoPolygon = 0xffffffffu;
        /// <summary>NL_NO_ISLAND: World.GetIslands' island of a polygon in an area the filter excludes.</summary>
        public const uint NoIsland = 0xffffffffu;
        public const float AreaExcluded = 0.0f;
        /// <summary>NL_PATH_WAIT_FOREVER: a raw nl_path_wait timeout that never ends (World.WaitPath takes
        /// a TimeSpan; null waits forever).</summary>
        public const uint PathWaitForever = 0xffffffffu;
        /// <summary>NL_MESH_MAX_AREA: the highest MeshDef.Area (World.AddMesh's area). The Recast builder
        /// carries 0..62 and fails the build above.</summary>
        public const uint MeshMaxArea = 254u;
        /// <summary>NL_BUILD_AREA_OBSTACLE: the area PluginHost.GetBuildTriangles gives an obstacle's triangles.</summary>
        public const uint BuildAreaObstacle = 255u;
    }

    /// <summary>How much a world logs (WorldOptions.LogLevel), and the level of each line (LogHandler).</summary>
    public enum LogLevel : uint
    {
        Error = 0u,
        Warning = 1u,
        Info = 2u,
        Debug = 3u,
    }

    /// <summary>nl_mesh_def.flags (World.AddMesh's flags, MeshInfo.Flags).</summary>
    [Flags]
    public enum MeshFlags : uint
    {
        None = 0u,
        /// <summary>The mesh will move (World.SetMeshTransform); navmeshes can ride it.</summary>
        Movable = 0x00000001u,
        /// <summary>Its fronts are wound clockwise (Godot's meshes): the triangles are turned over when registered.</summary>
        Clockwise = 0x00000002u,
        /// <summary>In navmesh builds it only blocks: none of its triangles is walked on (crates, props).</summary>
        Obstacle = 0x00000004u,
        /// <summary>Left out of navmesh builds (triggers, foliage); rays and link checks still meet it. Not with Obstacle.</summary>
        NotInNavmesh = 0x00000008u,
    }

    /// <summary>nl_mesh_def.up_axis (World.AddMesh's upAxis, MeshInfo.UpAxis). NavLink's own frame is
    /// right-handed with y up.</summary>
    public enum UpAxis : uint
    {
        /// <summary>The default: y up, and a navmesh build warns when the level would hold much more floor with z
        /// up (BuildWarnings.ZUp).</summary>
        NotSaid = 0u,
        /// <summary>Y up, said: no such warning.</summary>
        Y = 1u,
        /// <summary>Z up: turned to y up when registered.</summary>
        Z = 2u,
    }

    /// <summary>nl_navmesh_info.build_warnings (NavmeshInfo.BuildWarnings): a build succeeded on a level that
    /// looks given wrong.</summary>
    [Flags]
    public enum BuildWarnings : uint
    {
        None = 0u,
        /// <summary>Meshes look wound clockwise (NavmeshInfo.TurnedOverMeshCount).</summary>
        Clockwise = 0x1u,
        /// <summary>Meshes that did not say their units (MetresPerUnit 0) look given in other units than metres:
        /// walls more than 25 agents tall, or the whole level narrower than two.</summary>
        Units = 0x2u,
        /// <summary>Meshes that did not say their up axis would hold more than 1.5 times the floor for the agent
        /// with z up.</summary>
        ZUp = 0x4u,
    }

    /// <summary>A link's kind (Link.Kind, LinkDef.Kind), and how a path goes on from a point
    /// (PathPoint.Segment: Walk, or the kind of the link taken). Plugins' kinds are FirstPluginKind and up:
    /// cast them, (LinkKind)(LinkKind.FirstPluginKind + n).</summary>
    public enum LinkKind : uint
    {
        /// <summary>NL_SEGMENT_WALK: no link, a path walks on.</summary>
        Walk = 0u,
        Jump = 1u,
        Drop = 2u,
        Manual = 3u,
        FirstPluginKind = 256u,
    }

    /// <summary>nl_path_outcome values.</summary>
    public enum PathOutcome : uint
    {
        Pending = 0u,
        Complete = 1u,
        Partial = 2u,
        NoPath = 3u,
        StartOffNavmesh = 4u,
        GoalOffNavmesh = 5u,
        Cancelled = 6u,
        Failed = 7u,
    }

    /// <summary>nl_path_shortfall.reason: why a path falls short of its goal (World.ExplainPath).</summary>
    public enum PathShortfallReason : uint
    {
        /// <summary>It reaches the goal, or an end is off the navmesh (the outcome says so).</summary>
        None = 0u,
        /// <summary>MaxNodes stopped the search.</summary>
        OutOfNodes = 1u,
        /// <summary>A body of the navmesh's radius would get there: passages on the way are too narrow for this one.</summary>
        BodyTooWide = 2u,
        /// <summary>Areas the request keeps the body out of stand in the way.</summary>
        AreasExcluded = 3u,
        /// <summary>A link would get there, and the body cannot take it (Limit, Needed, Has, Link).</summary>
        LinkBeyondBody = 4u,
        /// <summary>The goal is on another island of the navmesh, and the navmesh has no links.</summary>
        NoLinks = 5u,
        /// <summary>No passage or link leads there, whatever the body.</summary>
        NotConnected = 6u,
    }

    /// <summary>nl_path_shortfall.limit: what a link asks that the body lacks (PathShortfallReason.LinkBeyondBody).</summary>
    public enum LinkLimit : uint
    {
        None = 0u,
        /// <summary>The gap, against MaxJumpDistance.</summary>
        JumpDistance = 1u,
        /// <summary>The rise, against MaxJumpHeight.</summary>
        JumpHeight = 2u,
        /// <summary>The drop, against MaxDropHeight.</summary>
        DropHeight = 3u,
        /// <summary>The body's diameter, against the link's clearance.</summary>
        Width = 4u,
        /// <summary>Ability bits the body lacks (MissingAbilities).</summary>
        Abilities = 5u,
    }

    /// <summary>nl_agent_state: what an agent is doing.</summary>
    public enum AgentState : uint
    {
        /// <summary>No destination.</summary>
        Idle = 0u,
        Walking = 1u,
        /// <summary>In the air, on the arc the link generator checked.</summary>
        Jumping = 2u,
        /// <summary>On a drop: out past the rim, across, then falling straight down.</summary>
        Falling = 3u,
        /// <summary>On a manual or plugin link: a straight line at its walking speed.</summary>
        Traversing = 4u,
        /// <summary>For its path to be planned, for a link's landing to clear, or at a cross link's take-off for
        /// the link to hold (a ferry away).</summary>
        Waiting = 5u,
        Arrived = 6u,
        /// <summary>Cannot go on; AgentInfo.Reason says why.</summary>
        Failed = 7u,
    }

    /// <summary>nl_agent_reason: why an agent planned again or failed (AgentInfo.Reason, AgentEvent.Reason).</summary>
    public enum AgentReason : uint
    {
        None = 0u,
        DestinationSet = 1u,
        /// <summary>A link of its path was removed, disabled, or is beyond its body now (found at the take-off).</summary>
        LinkGone = 2u,
        WorldChanged = 3u,
        /// <summary>Pushed too far off its path, or teleported.</summary>
        OffPath = 4u,
        /// <summary>The destination cannot be reached (it went as near as it could).</summary>
        NoPath = 5u,
        NavmeshRemoved = 6u,
        CapabilitiesChanged = 7u,
        /// <summary>Other bodies are in its way: it waits for room (AgentEventKind.Waiting; AgentInfo reads
        /// AgentState.Waiting with this reason meanwhile), or it gave its destination up after
        /// AgentDef.GiveUpSeconds (AgentState.Failed). Added in 0.3.</summary>
        Crowd = 8u,
    }

    /// <summary>nl_trajectory_kind: how a link is being taken (AgentTrajectory.Kind).</summary>
    public enum TrajectoryKind : uint
    {
        /// <summary>On the ground: no link is being taken (the rest is zero).</summary>
        None = 0u,
        /// <summary>A jump: a parabola from From to To over Apex.</summary>
        Arc = 1u,
        /// <summary>A drop: Points 0 to 1 (past the rim) and 2 (above the landing) walking, then down to 3.</summary>
        Fall = 2u,
        /// <summary>Any other link: a straight line at the walking speed.</summary>
        Line = 3u,
    }

    /// <summary>nl_agent_event_kind: what happened to an agent in the last step.</summary>
    public enum AgentEventKind : uint
    {
        /// <summary>Its path was planned (Reason: why it was asked for).</summary>
        PathReady = 1u,
        /// <summary>It took off on Link.</summary>
        LinkStarted = 2u,
        /// <summary>It landed at the end of Link.</summary>
        LinkFinished = 3u,
        Arrived = 4u,
        /// <summary>Reason says why.</summary>
        Failed = 5u,
        /// <summary>It asked for a new path (Reason; Link for LinkGone).</summary>
        Replanned = 6u,
        /// <summary>It stopped for room (Reason Crowd): stuck among other bodies for 0.75 s, or giving way to
        /// one; its AgentInfo reads AgentState.Waiting, AgentReason.Crowd, until it walks on. Said once per
        /// wait. Added in 0.3.</summary>
        Waiting = 7u,
    }

    /// <summary>nl_navmesh_load_links_json's flags (World.LoadLinksJson's anyBody).</summary>
    [Flags]
    public enum LinksLoadFlags : uint
    {
        None = 0u,
        /// <summary>Load links generated for another body than the navmesh's (with a warning to the log).</summary>
        AnyBody = 0x1u,
    }

    /// <summary>nl_navmesh_load_def.Flags (World.LoadNavmesh's sameLevel).</summary>
    [Flags]
    public enum NavmeshLoadFlags : uint
    {
        None = 0u,
        /// <summary>Refuse a file baked from other level geometry than the world holds now.</summary>
        SameLevel = 0x1u,
    }

    /// <summary>What a plugin provides (PluginSummary.Kinds, nl_plugin_info.kinds).</summary>
    [Flags]
    public enum PluginKinds : uint
    {
        None = 0u,
        NavmeshBuilder = 0x1u,
        LinkKind = 0x2u,
    }

    /// <summary>navlink/plugin.h's version and entry point, for plugins written in C#.</summary>
    public static class PluginAbi
    {
        /// <summary>NL_PLUGIN_ABI_VERSION.</summary>
        public const uint Version = 1u;
        public const string EntrySymbol = "nl_plugin_entry";
    }

    /// <summary>How Recast partitions the walkable area into regions (RecastSettings.Partition).</summary>
    public enum RecastPartition : uint
    {
        /// <summary>Best polygons; slowest (the default).</summary>
        Watershed = 0u,
        /// <summary>Fastest; long thin polygons.</summary>
        Monotone = 1u,
        /// <summary>Between the two; good for tiles.</summary>
        Layers = 2u,
    }
}
