using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public static unsafe partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern AgentType nl_default_agent_type();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern NavmeshDef nl_default_navmesh_def();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_add(IntPtr world, NavmeshDef* def, NavmeshId* outId);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_remove(IntPtr world, NavmeshId navmesh);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern int nl_navmesh_is_valid(IntPtr world, NavmeshId navmesh);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_get_info(IntPtr world, NavmeshId navmesh, NavmeshInfo* outInfo);

        /// <summary>outXyz: room for capacity vertices (3 * capacity floats).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_get_vertices(IntPtr world, NavmeshId navmesh, float* outXyz,
                                                          uint capacity, uint* outCount);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_get_polygon(IntPtr world, NavmeshId navmesh, uint polygon,
                                                         NavPolygon* outPolygon);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_get_boundary_edges(IntPtr world, NavmeshId navmesh, BoundaryEdge* outEdges,
                                                                uint capacity, uint* outCount);

        /// <summary>points: x y z per point; halfExtents: 3 floats.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_find_nearest(IntPtr world, NavmeshId navmesh, float* points, uint count,
                                                          float* halfExtents, NavPoint* outPoints);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_world_get_navmeshes(IntPtr world, NavmeshId* outIds, uint capacity,
                                                         uint* outCount);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern NavmeshBuildDef nl_default_navmesh_build_def();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_build(IntPtr world, NavmeshBuildDef* def, NavmeshId* outId);

        /// <summary>navlink/recast.h.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern RecastSettings nl_default_recast_settings();
    }
}
