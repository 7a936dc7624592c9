using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public sealed partial class World
    {
        /// <summary>Registers a triangle mesh (copied): x y z per vertex, 3 indices per triangle, an
        /// optional column-major 4x4 transform (empty: identity). flags: Movable; Clockwise for fronts wound
        /// clockwise (Godot's); Obstacle (blocks navmesh builds, never walked on) or NotInNavmesh (left out of
        /// them). area: what navmesh builds give the polygons over the mesh (0..Limits.MeshMaxArea; the Recast
        /// builder carries 0..62), priced by PathQuery's area costs. metresPerUnit: the length of one unit of
        /// the vertices in metres (0.01 for centimetres; 0, not said: metres, and a navmesh build warns when
        /// the level looks otherwise); upAxis: UpAxis.Z for z-up vertices (Blender's, Unreal's). Both apply
        /// before the transform, which is in metres with y up (MeshDef.MetresPerUnit, MeshDef.UpAxis).</summary>
        public unsafe MeshId AddMesh(ReadOnlySpan<float> vertices, ReadOnlySpan<uint> indices, MeshFlags flags = MeshFlags.None,
                                     ReadOnlySpan<float> transform = default(ReadOnlySpan<float>), ulong userData = 0,
                                     uint area = 0, float metresPerUnit = 0, UpAxis upAxis = UpAxis.NotSaid)
        {
            MeshDef def = Native.nl_default_mesh_def();
            MeshId id;
            fixed (float* v = &MemoryMarshal.GetReference(vertices))
            fixed (uint* i = &MemoryMarshal.GetReference(indices))
            fixed (float* t = &MemoryMarshal.GetReference(transform))
            using (var w = Enter())
            {
                def.Vertices = (IntPtr)v;
                def.VertexCount = (uint)(vertices.Length / 3);
                def.Indices = (IntPtr)i;
                def.TriangleCount = (uint)(indices.Length / 3);
                SetMeshOptions(ref def, flags, transform.IsEmpty ? IntPtr.Zero : (IntPtr)t, userData, area, metresPerUnit, upAxis);
                Status.Check(Native.nl_mesh_add(w.Pointer, &def, &id));
            }
            return id;
        }

        /// <summary>Loads a Wavefront OBJ file as one mesh (flags, area, metresPerUnit and upAxis as for AddMesh).</summary>
        public unsafe MeshId AddObjFile(string path, MeshFlags flags = MeshFlags.None,
                                        ReadOnlySpan<float> transform = default(ReadOnlySpan<float>), ulong userData = 0,
                                        uint area = 0, float metresPerUnit = 0, UpAxis upAxis = UpAxis.NotSaid)
        {
            byte[] utf8 = Utf8.EncodeZ(path);
            MeshDef def = Native.nl_default_mesh_def();
            MeshId id;
            fixed (byte* p = utf8)
            fixed (float* t = &MemoryMarshal.GetReference(transform))
            using (var w = Enter())
            {
                SetMeshOptions(ref def, flags, transform.IsEmpty ? IntPtr.Zero : (IntPtr)t, userData, area, metresPerUnit, upAxis);
                Status.Check(Native.nl_mesh_add_obj_file(w.Pointer, p, &def, &id));
            }
            return id;
        }

        /// <summary>Registers OBJ text from memory as one mesh (flags, area, metresPerUnit and upAxis as for
        /// AddMesh).</summary>
        public unsafe MeshId AddObjMemory(ReadOnlySpan<byte> objText, MeshFlags flags = MeshFlags.None,
                                          ReadOnlySpan<float> transform = default(ReadOnlySpan<float>), ulong userData = 0,
                                          uint area = 0, float metresPerUnit = 0, UpAxis upAxis = UpAxis.NotSaid)
        {
            MeshDef def = Native.nl_default_mesh_def();
            MeshId id;
            fixed (byte* p = &MemoryMarshal.GetReference(objText))
            fixed (float* t = &MemoryMarshal.GetReference(transform))
            using (var w = Enter())
            {
                SetMeshOptions(ref def, flags, transform.IsEmpty ? IntPtr.Zero : (IntPtr)t, userData, area, metresPerUnit, upAxis);
                Status.Check(Native.nl_mesh_add_obj_memory(w.Pointer, p, (UIntPtr)objText.Length, &def, &id));
            }
            return id;
        }

        // What AddMesh, AddObjFile and AddObjMemory take beyond the geometry; transform is pinned by the caller.
        private static void SetMeshOptions(ref MeshDef def, MeshFlags flags, IntPtr transform, ulong userData, uint area,
                                           float metresPerUnit, UpAxis upAxis)
        {
            def.Flags = flags;
            def.Transform = transform;
            def.UserData = userData;
            def.Area = area;
            def.MetresPerUnit = metresPerUnit;
            def.UpAxis = upAxis;
        }

        /// <summary>Removes a mesh (InvalidArgument for a mesh a navmesh rides: remove the navmesh first).</summary>
        public void RemoveMesh(MeshId mesh)
        {
            using (var w = Enter()) Status.Check(Native.nl_mesh_remove(w.Pointer, mesh));
        }

        /// <summary>Replaces a mesh's transform (16 floats, column-major, affine). The navmeshes that ride the
        /// mesh move with it; such a mesh takes rotations and translations only (InvalidArgument otherwise).</summary>
        public unsafe void SetMeshTransform(MeshId mesh, ReadOnlySpan<float> transform)
        {
            if (transform.Length != 16) throw new ArgumentException("a transform is 16 floats", "transform");
            fixed (float* t = &MemoryMarshal.GetReference(transform))
            using (var w = Enter())
                Status.Check(Native.nl_mesh_set_transform(w.Pointer, mesh, t));
        }

        public bool IsValid(MeshId mesh)
        {
            using (var w = Enter()) return Native.nl_mesh_is_valid(w.Pointer, mesh) != 0;
        }

        public unsafe MeshInfo GetMeshInfo(MeshId mesh)
        {
            MeshInfo info;
            if (!TryGetMeshInfo(mesh, out info)) throw new NavLinkException(Native.nl_get_last_status(), Status.LastErrorMessage());
            return info;
        }

        /// <summary>False (and the reason in the last error) for a null, stale or foreign id.</summary>
        public unsafe bool TryGetMeshInfo(MeshId mesh, out MeshInfo info)
        {
            MeshInfo result = Native.nl_mesh_info_init();
            StatusCode status;
            using (var w = Enter()) status = Native.nl_mesh_get_info(w.Pointer, mesh, &result);
            info = result;
            if ((status & StatusCode.InvalidHandle) != 0) return false;
            Status.Check(status);
            return true;
        }

        public unsafe MeshId[] GetMeshes()
        {
            using (var w = Enter())
            {
                IntPtr world = w.Pointer;
                return ListTwoCall<MeshId>((buffer, capacity, count) => Native.nl_world_get_meshes(world, (MeshId*)buffer, capacity, count));
            }
        }

        /// <summary>Casts every ray; hits must have room for one result per ray (their contents are
        /// overwritten, Size included).</summary>
        public unsafe void CastRays(ReadOnlySpan<Ray> rays, Span<RayHit> hits)
        {
            if (hits.Length < rays.Length) throw new ArgumentException("one hit per ray", "hits");
            if (rays.Length > 0) hits[0] = Native.nl_ray_hit_init();  // the element size the library writes with
            fixed (Ray* r = &MemoryMarshal.GetReference(rays))
            fixed (RayHit* h = &MemoryMarshal.GetReference(hits))
            using (var w = Enter())
                Status.Check(Native.nl_world_cast_rays(w.Pointer, r, (uint)rays.Length, h));
        }

        public RayHit[] CastRays(Ray[] rays)
        {
            var hits = new RayHit[rays.Length];
            CastRays(rays, hits);
            return hits;
        }

        /// <summary>Writes 1 (blocked) or 0 (clear) per segment.</summary>
        public unsafe void SegmentsBlocked(ReadOnlySpan<Segment> segments, Span<byte> blocked)
        {
            if (blocked.Length < segments.Length) throw new ArgumentException("one entry per segment", "blocked");
            fixed (Segment* s = &MemoryMarshal.GetReference(segments))
            fixed (byte* b = &MemoryMarshal.GetReference(blocked))
            using (var w = Enter())
                Status.Check(Native.nl_world_segments_blocked(w.Pointer, s, (uint)segments.Length, b));
        }

        public bool[] SegmentsBlocked(Segment[] segments)
        {
            var raw = new byte[segments.Length];
            SegmentsBlocked(segments, raw);
            return Array.ConvertAll(raw, b => b != 0);
        }
    }
}
