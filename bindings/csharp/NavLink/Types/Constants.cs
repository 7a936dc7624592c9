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

    /// <summary>nl_status bits: a kind in the top bits, detail bits below (navlink.h, "Status").</summary>
    public static class StatusBits
    {
        public const uint Failure = 0x80000000u;
        public const uint Success = 0x40000000u;
        public const uint InProgress = 0x20000000u;
        public const uint DetailMask = 0x0fffffffu;

        public const uint InvalidArgument = 0x00000001u;
        public const uint InvalidHandle = 0x00000002u;
        public const uint BufferTooSmall = 0x00000004u;
        public const uint OutOfMemory = 0x00000008u;
        public const uint Cancelled = 0x00000010u;
        public const uint PartialResult = 0x00000020u;
        public const uint NotFound = 0x00000040u;
        public const uint InternalError = 0x00000080u;
        public const uint IoError = 0x00000100u;
        public const uint ParseError = 0x00000200u;
        public const uint VersionMismatch = 0x00000400u;

        public static bool Succeeded(uint status) { return (status & Success) != 0u; }
        public static bool Failed(uint status) { return (status & Failure) != 0u; }
    }

    public static class Limits
    {
        public const float CoordinateLimit = 1.0e9f;
        public const int WorkersAuto = -1;
        public const int MaxWorkers = 1024;
        public const int MaxPolygonVertices = 16;
        public const uint NoPolygon = 0xffffffffu;
        public const float AreaExcluded = 0.0f;
    }

    public static class LogLevel
    {
        public const uint Error = 0u;
        public const uint Warning = 1u;
        public const uint Info = 2u;
        public const uint Debug = 3u;
    }

    public static class MeshFlags
    {
        public const uint Movable = 0x00000001u;
    }

    /// <summary>nl_link_kind values; NL_SEGMENT_WALK (0) is added for path segments.</summary>
    public static class LinkKind
    {
        public const uint Walk = 0u;
        public const uint Jump = 1u;
        public const uint Drop = 2u;
        public const uint Manual = 3u;
        public const uint FirstPluginKind = 256u;
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
    }

    /// <summary>nl_navmesh_load_links_json's flags (World.LoadLinksJson's anyBody).</summary>
    public static class LinksLoadFlags
    {
        /// <summary>Load links generated for another body than the navmesh's (with a warning to the log).</summary>
        public const uint AnyBody = 0x1u;
    }

    /// <summary>nl_navmesh_load_def.Flags (World.LoadNavmesh's sameLevel).</summary>
    public static class NavmeshLoadFlags
    {
        /// <summary>Refuse a file baked from other level geometry than the world holds now.</summary>
        public const uint SameLevel = 0x1u;
    }

    public static class PluginKinds
    {
        public const uint NavmeshBuilder = 0x1u;
        public const uint LinkKind = 0x2u;
        public const uint AbiVersion = 1u;
        public const string EntrySymbol = "nl_plugin_entry";
    }

    public static class RecastPartition
    {
        public const uint Watershed = 0u;
        public const uint Monotone = 1u;
        public const uint Layers = 2u;
    }
}
