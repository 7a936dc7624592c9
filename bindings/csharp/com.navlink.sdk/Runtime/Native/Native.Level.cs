using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public static unsafe partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern MeshDef nl_default_mesh_def();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_mesh_add(IntPtr world, MeshDef* def, MeshId* outId);

        /// <summary>path: NUL-terminated UTF-8 (Utf8.Encode).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_mesh_add_obj_file(IntPtr world, byte* path, MeshDef* def, MeshId* outId);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_mesh_add_obj_memory(IntPtr world, byte* data, UIntPtr length, MeshDef* def,
                                                         MeshId* outId);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_mesh_remove(IntPtr world, MeshId mesh);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_mesh_set_transform(IntPtr world, MeshId mesh, float* transform);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern int nl_mesh_is_valid(IntPtr world, MeshId mesh);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_mesh_get_info(IntPtr world, MeshId mesh, MeshInfo* outInfo);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_world_get_meshes(IntPtr world, MeshId* outIds, uint capacity, uint* outCount);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_world_cast_rays(IntPtr world, Ray* rays, uint count, RayHit* outHits);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_world_segments_blocked(IntPtr world, Segment* segments, uint count,
                                                            byte* outBlocked);
    }
}
