using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>nl_navmesh_load_def: how to load a navmesh file. Get one from Native.nl_default_navmesh_load_def()
    /// (World.LoadNavmesh fills one from its arguments).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct NavmeshLoadDef
    {
        public uint Size;
        /// <summary>For a file whose navmesh rode a movable mesh (NavmeshFileInfo.RidesSurface): the movable mesh
        /// it rides now. The null id otherwise.</summary>
        public MeshId Surface;
        /// <summary>NavmeshLoadFlags.SameLevel: refuse a file baked from other level geometry. 0: load it
        /// whatever the level.</summary>
        public NavmeshLoadFlags Flags;
    }

    /// <summary>nl_navmesh_file_info: what a navmesh file holds and was made for (World.DescribeNavmeshFile).
    /// Not an nl_*_init struct: set Size to its sizeof before a raw call.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct NavmeshFileInfo
    {
        public uint Size;
        /// <summary>The file's format version.</summary>
        public uint Version;
        /// <summary>Bytes.</summary>
        public ulong FileSize;
        /// <summary>The body the navmesh was made for.</summary>
        public AgentType Agent;
        public uint VertexCount;
        public uint PolygonCount;
        /// <summary>0: no height detail.</summary>
        public uint DetailTriangleCount;
        public uint LinkCount;
        /// <summary>Of LinkCount, made by link generation.</summary>
        public uint GeneratedLinkCount;
        /// <summary>1: its coordinates are in the space of a movable mesh it rode.</summary>
        public uint RidesSurface;
        /// <summary>Metres per step of its fixed-point coordinates (1/1024).</summary>
        public float Quantum;
        public uint Reserved;
        /// <summary>Of the level triangles it was built from; 0: handed over by the host.</summary>
        public ulong LevelHash;
    }
}
