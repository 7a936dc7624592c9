using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>nl_agent_type: the body a navmesh is built for.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct AgentType
    {
        public float Radius;
        public float Height;
        public float MaxClimb;
        public float MaxSlope;
    }

    /// <summary>nl_navmesh_def: a navmesh handed over by the host; pointers borrowed for the call.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct NavmeshDef
    {
        public uint Size;
        public IntPtr Vertices;
        public uint VertexCount;
        public uint VertexStride;
        public IntPtr Indices;
        public IntPtr PolygonVertexCounts;
        public uint PolygonCount;
        public IntPtr Areas;
        public float WeldTolerance;
        public AgentType Agent;
        public IntPtr DetailVertices;
        public uint DetailVertexCount;
        public IntPtr DetailTriangles;
        public uint DetailTriangleCount;
        public IntPtr DetailTriangleStarts;
        /// <summary>A movable mesh (MeshFlags.Movable) the navmesh rides, or the null id. With one, every
        /// coordinate above is in that mesh's own space and World.SetMeshTransform moves the navmesh. Added in 0.3.</summary>
        public MeshId Surface;
    }

    /// <summary>nl_navmesh_info. Get one from Native.nl_navmesh_info_init() (Size set) before asking.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct NavmeshInfo
    {
        public uint Size;
        public uint VertexCount;
        public uint PolygonCount;
        public uint PortalCount;
        public uint BoundaryEdgeCount;
        public uint WeldedVertexCount;
        public uint FlippedPolygonCount;
        public uint DroppedPolygonCount;
        public uint NonManifoldEdgeCount;
        public AgentType Agent;
        /// <summary>In the world; for a navmesh that rides a moving mesh, a box that holds it where the mesh is now.</summary>
        public Vec3 BoundsMin;
        public Vec3 BoundsMax;
        /// <summary>The movable mesh it rides; the null id for none. Added in 0.3.</summary>
        public MeshId Surface;
        /// <summary>Meshes World.BuildNavmesh built it on that look wound clockwise: turned over, they would hold
        /// much more floor for its agent than as given (the build also logs a warning naming them and
        /// MeshFlags.Clockwise). 0 for a navmesh added from polygons or loaded from a file. Added in 0.3.</summary>
        public uint TurnedOverMeshCount;
        /// <summary>What World.BuildNavmesh found wrong with its level (each also said in a warning in the log). 0
        /// for a navmesh added from polygons or loaded from a file. Added in 0.3.</summary>
        public BuildWarnings BuildWarnings;
    }

    /// <summary>nl_nav_polygon. May grow: Size set by Native.nl_nav_polygon_init() (World.GetPolygon sets it).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct NavPolygon
    {
        public uint Size;
        public uint VertexCount;
        public fixed uint Vertices[16];
        public fixed uint Neighbours[16];
        public uint Area;
        public Vec3 Normal;
        public Vec3 Centre;
    }

    /// <summary>nl_boundary_edge.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct BoundaryEdge
    {
        public Vec3 Start;
        public Vec3 End;
        public Vec3 Outward;
        public Vec3 Normal;
        public uint Polygon;
        public uint Edge;
    }

    /// <summary>nl_nav_point.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct NavPoint
    {
        public Vec3 Point;
        public float Distance;
        public uint Polygon;
        public byte Found;
        /// <summary>Why Found is 0: 1 when the navmesh's nearest point lies beyond the search box; Point and
        /// Distance then give that point (Polygon stays Limits.NoPolygon). 0 when found. Added in 0.3.</summary>
        public byte BeyondBox;
        public fixed byte Reserved[2];
    }

    /// <summary>nl_navmesh_build_def. Builder and SettingsJson are UTF-8 pointers borrowed for the call.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct NavmeshBuildDef
    {
        public uint Size;
        public IntPtr Builder;
        public AgentType Agent;
        public IntPtr Settings;
        public IntPtr SettingsJson;
        public UIntPtr SettingsJsonLength;
        /// <summary>A movable mesh to build on (alone, in its own space; the navmesh rides it), or the null
        /// id: every static mesh. Added in 0.3.</summary>
        public MeshId Surface;
        /// <summary>Optional nl_progress_fn (a NativeCallbacks.ProgressFn pointer): told of the build's progress
        /// from its start; returning 0 cancels it (Cancelled, nothing added). Added in 0.3.</summary>
        public IntPtr Progress;
        /// <summary>Passed back to Progress; not dereferenced.</summary>
        public IntPtr ProgressUser;
    }

    /// <summary>nl_recast_settings (navlink/recast.h).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct RecastSettings
    {
        public uint Size;
        public float CellSize;
        public float CellHeight;
        public float RegionMinSize;
        public float RegionMergeSize;
        public float EdgeMaxLength;
        public float EdgeMaxError;
        public uint VerticesPerPolygon;
        public float DetailSampleDistance;
        public float DetailSampleMaxError;
        public RecastPartition Partition;
        public byte FilterLowHangingObstacles;
        public byte FilterLedgeSpans;
        public byte FilterWalkableLowHeightSpans;
        public byte Reserved;
    }
}
