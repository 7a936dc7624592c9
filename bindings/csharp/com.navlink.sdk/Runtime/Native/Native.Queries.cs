using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    // navlink.h: "Queries on a navmesh for one body". Every filter may be null (nl_default_query_filter()).
    public static unsafe partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern QueryFilterDef nl_default_query_filter();

        /// <summary>fromPolygons, toPolygons: count each; outReachable: count bytes (1 or 0).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_can_reach(IntPtr world, NavmeshId navmesh, QueryFilterDef* filter,
                                                             uint* fromPolygons, uint* toPolygons, uint count,
                                                             byte* outReachable);

        /// <summary>The two-call pattern: outPolygons null with capacity 0 asks the count.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_get_reachable_polygons(IntPtr world, NavmeshId navmesh, QueryFilterDef* filter,
                                                                          uint fromPolygon, uint* outPolygons, uint capacity,
                                                                          uint* outCount);

        /// <summary>The two-call pattern (one island per polygon); outIslandCount may be null.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_get_islands(IntPtr world, NavmeshId navmesh, QueryFilterDef* filter,
                                                               uint* outIslands, uint capacity, uint* outCount,
                                                               uint* outIslandCount);

        /// <summary>rays: count entries; outHits: count entries, outHits[0].Size set (nl_navmesh_raycast_hit_init).
        /// outPolygons: null with polygonsPerRay 0, or count * polygonsPerRay entries: ray i's crossed polygons
        /// from outPolygons[i * polygonsPerRay], at most polygonsPerRay of them (its hit's PolygonCount is how
        /// many it crossed; no BufferTooSmall). A refused batch writes nothing.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_raycast(IntPtr world, NavmeshId navmesh, QueryFilterDef* filter,
                                                           NavmeshRay* rays, uint count, NavmeshRaycastHit* outHits,
                                                           uint* outPolygons, uint polygonsPerRay);

        /// <summary>start, target: 3 floats each; outPolygons may be null with capacity 0; outCount (may be null)
        /// receives how many polygons it visited, also when fewer fit (BufferTooSmall: the point is written and
        /// the first capacity polygons).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_move_along_surface(IntPtr world, NavmeshId navmesh, QueryFilterDef* filter,
                                                                      uint startPolygon, float* start, float* target,
                                                                      NavPoint* outPoint, uint* outPolygons, uint capacity,
                                                                      uint* outCount);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern RandomPointsDef nl_default_random_points_def();

        /// <summary>outPoints: count entries; outFound receives how many were drawn.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_navmesh_random_points(IntPtr world, NavmeshId navmesh, RandomPointsDef* def,
                                                                 NavPoint* outPoints, uint count, uint* outFound);
    }
}
