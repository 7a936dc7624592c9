using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>nl_query_filter: the body a navmesh query is for, as a path request gives it. AreaCosts is
    /// borrowed for the call (pin the array around it); an area of cost Limits.AreaExcluded is kept out of.
    /// Get one from Native.nl_default_query_filter(). World's query methods take a QueryFilter (the class)
    /// and build this themselves.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct QueryFilterDef
    {
        public uint Size;
        public AgentCapabilities Agent;
        public IntPtr AreaCosts;
        /// <summary>At most 256.</summary>
        public uint AreaCostCount;
        /// <summary>Must be 0.</summary>
        public uint Reserved;
    }

    /// <summary>nl_navmesh_ray: one straight walk for Native.nl_navmesh_raycast (World.Raycast takes a span of
    /// them).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct NavmeshRay
    {
        /// <summary>Over StartPolygon (within 1 mm, seen from above).</summary>
        public Vec3 Start;
        /// <summary>The polygon under Start, from World.FindNearest.</summary>
        public uint StartPolygon;
        /// <summary>Anywhere: the walk heads for it, seen from above.</summary>
        public Vec3 End;

        public NavmeshRay(Vec3 start, uint startPolygon, Vec3 end)
        {
            Start = start;
            StartPolygon = startPolygon;
            End = end;
        }
    }

    /// <summary>nl_navmesh_raycast_hit: how far a straight walk along a navmesh went. An element of an output
    /// array that may grow: set the first one's Size (Native.nl_navmesh_raycast_hit_init()) before asking.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct NavmeshRaycastHit
    {
        public uint Size;
        /// <summary>1 if a wall (the navmesh's outline, or an excluded area) stopped the walk before its end; 0
        /// if it arrived.</summary>
        public byte Hit;
        public fixed byte Reserved[3];
        /// <summary>The fraction of start to end walked (seen from above): 1 if it arrived.</summary>
        public float T;
        /// <summary>Where it stopped (or the end), at the navmesh surface's height.</summary>
        public Vec3 Point;
        /// <summary>The wall's normal, horizontal, pointing back the way the walk came; zero if it arrived.</summary>
        public Vec3 WallNormal;
        /// <summary>The polygon holding Point.</summary>
        public uint EndPolygon;
        /// <summary>Polygons crossed, the start polygon first and EndPolygon last (all of them, also when the
        /// polygon buffer had room for fewer).</summary>
        public uint PolygonCount;
    }

    /// <summary>nl_random_points_def: which random points Native.nl_navmesh_random_points draws. Filter is a
    /// QueryFilterDef* borrowed for the call (or null). Get one from Native.nl_default_random_points_def();
    /// World.RandomPoints takes its fields as arguments.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct RandomPointsDef
    {
        public uint Size;
        public IntPtr Filter;
        /// <summary>With Radius &gt; 0: points within Radius of it, seen from above.</summary>
        public Vec3 Centre;
        /// <summary>0 (default): anywhere on the navmesh.</summary>
        public float Radius;
        /// <summary>A polygon, or Limits.NoPolygon (default): only points the filter's body can reach from it.</summary>
        public uint ReachableFrom;
        /// <summary>Must be 0.</summary>
        public uint Reserved;
        /// <summary>The same seed, navmesh and def give the same points on every run and thread count.</summary>
        public ulong Seed;
    }
}
