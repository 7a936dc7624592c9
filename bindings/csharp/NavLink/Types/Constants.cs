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
