using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>nl_mesh_def: pointers are borrowed for the call (pin the arrays around it).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct MeshDef
    {
        public uint Size;
        public IntPtr Vertices;
        public uint VertexCount;
        public uint VertexStride;
        public IntPtr Indices;
        public uint TriangleCount;
        public MeshFlags Flags;
        public IntPtr Transform;
        public ulong UserData;
        /// <summary>The area navmesh builds give the polygons over this mesh (0..Limits.MeshMaxArea; the Recast
        /// builder carries 0..62). Added in 0.3.</summary>
        public uint Area;
        /// <summary>Must be 0.</summary>
        public uint Reserved;
        /// <summary>The length of one unit of Vertices in metres: 0.01 for centimetres (Unreal's, many exporters'),
        /// 0.0254 for inches, 1 for metres; 1e-6..1e6. 0 (the default) means metres, not said: a navmesh build
        /// then warns when the level's size against its agent's suggests other units (BuildWarnings.Units); 1
        /// says metres and silences it. The vertices are scaled when registered, before Transform, which is in
        /// metres as every other position and length. Added in 0.3.</summary>
        public float MetresPerUnit;
        /// <summary>Which axis of Vertices points up. Z-up vertices (Blender's, Unreal's, 3ds Max's own frame) are
        /// turned to NavLink's y up when registered, before Transform: (x, y, z) becomes (x, z, -y), a rotation,
        /// so fronts stay fronts. Added in 0.3.</summary>
        public UpAxis UpAxis;
    }

    /// <summary>nl_mesh_info. Get one from Native.nl_mesh_info_init() (Size set) before asking.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct MeshInfo
    {
        public uint Size;
        public uint VertexCount;
        public uint TriangleCount;
        public uint DegenerateTriangleCount;
        public MeshFlags Flags;
        public fixed float Transform[16];
        public Vec3 BoundsMin;
        public Vec3 BoundsMax;
        public ulong UserData;
        /// <summary>As given in the MeshDef (0.3).</summary>
        public uint Area;
        public uint Reserved;
        /// <summary>As given in the MeshDef (0 = not said) (0.3).</summary>
        public float MetresPerUnit;
        /// <summary>As given in the MeshDef (0.3).</summary>
        public UpAxis UpAxis;
    }

    /// <summary>nl_ray.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Ray
    {
        public Vec3 Origin;
        public Vec3 Direction;
        public float MaxDistance;

        public Ray(Vec3 origin, Vec3 direction, float maxDistance)
        {
            Origin = origin;
            Direction = direction;
            MaxDistance = maxDistance;
        }
    }

    /// <summary>nl_ray_hit. An array element that may grow: the library lays out an output array with the
    /// element size in its first element's Size (Native.nl_ray_hit_init(); World.CastRays sets it).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct RayHit
    {
        public uint Size;
        public float Distance;
        public Vec3 Point;
        public Vec3 Normal;
        public MeshId Mesh;
        public uint Triangle;
        public byte Hit;
        public fixed byte Reserved[3];
    }

    /// <summary>nl_segment.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Segment
    {
        public Vec3 From;
        public Vec3 To;

        public Segment(Vec3 from, Vec3 to)
        {
            From = from;
            To = to;
        }
    }
}
