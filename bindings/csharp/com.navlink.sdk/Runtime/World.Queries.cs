using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    // navlink.h: "Queries on a navmesh for one body": reachability, the navmesh raycast and slide, random
    // points. Polygons come from FindNearest; a null filter is new QueryFilter() (a default walker).
    public sealed partial class World
    {
        // Polygons fetched per walk in one go by Raycast and MoveAlongSurface when a walk crosses no more;
        // longer walks take a second call with room for them all.
        private const uint FirstWalkCapacity = 32;

        /// <summary>Whether the filter's body can get from polygon fromPolygons[i] to toPolygons[i] by walking and
        /// by the links it can take, exactly as a path request for it would find; one answer per pair. Each
        /// answer takes constant time (the navmesh's reachability map for the body's class, built on the first
        /// query).</summary>
        public unsafe bool[] CanReach(NavmeshId navmesh, ReadOnlySpan<uint> fromPolygons, ReadOnlySpan<uint> toPolygons,
                                      QueryFilter filter = null)
        {
            if (fromPolygons.Length != toPolygons.Length)
                throw new ArgumentException("one to-polygon per from-polygon (" + fromPolygons.Length + " and " +
                                            toPolygons.Length + ")", "toPolygons");
            var answers = new byte[fromPolygons.Length];
            float[] costs = filter == null ? null : filter.AreaCosts;
            fixed (uint* from = &MemoryMarshal.GetReference(fromPolygons))
            fixed (uint* to = &MemoryMarshal.GetReference(toPolygons))
            fixed (byte* a = answers)
            fixed (float* c = costs)
            using (var w = Enter())
            {
                QueryFilterDef def = filter == null ? default(QueryFilterDef) : filter.ToDef(c);
                Status.Check(Native.nl_navmesh_can_reach(w.Pointer, navmesh, filter == null ? null : &def, from, to,
                                                         (uint)answers.Length, a));
            }
            var reachable = new bool[answers.Length];
            for (int i = 0; i < answers.Length; ++i) reachable[i] = answers[i] != 0;
            return reachable;
        }

        /// <summary>Whether the filter's body can get from polygon fromPolygon to toPolygon (one pair of CanReach).</summary>
        public bool CanReach(NavmeshId navmesh, uint fromPolygon, uint toPolygon, QueryFilter filter = null)
        {
            return CanReach(navmesh, new[] {fromPolygon}, new[] {toPolygon}, filter)[0];
        }

        /// <summary>Every polygon the filter's body can reach from fromPolygon (itself included), ascending.</summary>
        public unsafe uint[] GetReachablePolygons(NavmeshId navmesh, uint fromPolygon, QueryFilter filter = null)
        {
            float[] costs = filter == null ? null : filter.AreaCosts;
            fixed (float* c = costs)
            using (var w = Enter())
            {
                QueryFilterDef def = filter == null ? default(QueryFilterDef) : filter.ToDef(c);
                IntPtr world = w.Pointer, f = filter == null ? IntPtr.Zero : (IntPtr)(&def);
                return ListTwoCall<uint>((buffer, capacity, count) =>
                    Native.nl_navmesh_get_reachable_polygons(world, navmesh, (QueryFilterDef*)f, fromPolygon, (uint*)buffer,
                                                             capacity, count));
            }
        }

        /// <summary>The island of every polygon for the filter's body (one per polygon): polygons of one island
        /// reach each other; one-way links may lead from one island to another (ask CanReach). Islands are
        /// numbered from 0 in order of their lowest polygon; Limits.NoIsland for polygons in excluded areas.
        /// islandCount: the number of islands.</summary>
        public unsafe uint[] GetIslands(NavmeshId navmesh, out uint islandCount, QueryFilter filter = null)
        {
            float[] costs = filter == null ? null : filter.AreaCosts;
            fixed (float* c = costs)
            using (var w = Enter())
            {
                QueryFilterDef def = filter == null ? default(QueryFilterDef) : filter.ToDef(c);
                QueryFilterDef* f = filter == null ? null : &def;
                while (true)
                {
                    uint count, islands;
                    Status.Check(Native.nl_navmesh_get_islands(w.Pointer, navmesh, f, null, 0, &count, &islands));
                    var items = new uint[count];
                    StatusCode status;
                    fixed (uint* p = items)
                        status = Native.nl_navmesh_get_islands(w.Pointer, navmesh, f, p, count, &count, &islands);
                    if (Status.IsBufferTooSmall(status)) continue;  // the navmesh changed in between
                    Status.Check(status);
                    if (count < items.Length) Array.Resize(ref items, (int)count);
                    islandCount = islands;
                    return items;
                }
            }
        }

        /// <summary>GetIslands without the number of islands.</summary>
        public uint[] GetIslands(NavmeshId navmesh, QueryFilter filter = null)
        {
            uint islandCount;
            return GetIslands(navmesh, out islandCount, filter);
        }

        /// <summary>Walks each ray in a straight line (seen from above) from its Start, over its StartPolygon (from
        /// FindNearest), towards its End along the navmesh surface, as Detour's raycast: how far a body walks
        /// before a wall (the navmesh's outline, or an area the filter excludes) stops it. One hit per ray into
        /// hits (their contents are overwritten, Size included); the navmesh is looked up once and large batches
        /// run over the world's workers. A ray the library refuses (its start not over its polygon...) fails the
        /// whole batch, naming its index, and nothing is written.</summary>
        public unsafe void Raycast(NavmeshId navmesh, ReadOnlySpan<NavmeshRay> rays, Span<NavmeshRaycastHit> hits,
                                   QueryFilter filter = null)
        {
            if (hits.Length < rays.Length) throw new ArgumentException("one hit per ray", "hits");
            if (rays.Length > 0) hits[0] = Native.nl_navmesh_raycast_hit_init();  // the element size the library writes with
            fixed (NavmeshRay* r = &MemoryMarshal.GetReference(rays))
            fixed (NavmeshRaycastHit* h = &MemoryMarshal.GetReference(hits))
                Status.Check(RaycastBatch(navmesh, filter, r, (uint)rays.Length, h, null, 0));
        }

        /// <summary>Raycast of every ray into a new array of hits (the hits' PolygonCount counts the polygons
        /// each crossed).</summary>
        public NavmeshRaycastHit[] Raycast(NavmeshId navmesh, ReadOnlySpan<NavmeshRay> rays, QueryFilter filter = null)
        {
            var hits = new NavmeshRaycastHit[rays.Length];
            Raycast(navmesh, rays, hits, filter);
            return hits;
        }

        /// <summary>Raycast of every ray, with the polygons each crossed: polygons[i] for rays[i], its start
        /// polygon first and its hit's EndPolygon last. Room for 32 per ray is asked first; the rays that
        /// crossed more are walked again, together, with room for the most any of them crossed.</summary>
        public unsafe NavmeshRaycastHit[] Raycast(NavmeshId navmesh, ReadOnlySpan<NavmeshRay> rays, out uint[][] polygons,
                                                  QueryFilter filter = null)
        {
            int count = rays.Length;
            var hits = new NavmeshRaycastHit[count];
            polygons = new uint[count][];
            if (count == 0) return hits;
            var buffer = new uint[count * FirstWalkCapacity];
            hits[0] = Native.nl_navmesh_raycast_hit_init();
            fixed (NavmeshRay* r = &MemoryMarshal.GetReference(rays))
            fixed (NavmeshRaycastHit* h = hits)
            fixed (uint* p = buffer)
                Status.Check(RaycastBatch(navmesh, filter, r, (uint)count, h, p, FirstWalkCapacity));
            var longer = new System.Collections.Generic.List<int>();
            for (int i = 0; i < count; ++i)
            {
                if (hits[i].PolygonCount > FirstWalkCapacity)
                {
                    longer.Add(i);
                    continue;
                }
                polygons[i] = new uint[hits[i].PolygonCount];
                Array.Copy(buffer, i * FirstWalkCapacity, polygons[i], 0, polygons[i].Length);
            }
            while (longer.Count > 0)
            {
                // The hits say how many: walk those rays again with room for the most of them.
                var again = new NavmeshRay[longer.Count];
                uint room = 0;
                for (int k = 0; k < longer.Count; ++k)
                {
                    again[k] = rays[longer[k]];
                    room = Math.Max(room, hits[longer[k]].PolygonCount);
                }
                var againHits = new NavmeshRaycastHit[again.Length];
                againHits[0] = Native.nl_navmesh_raycast_hit_init();
                buffer = new uint[(long)again.Length * room];
                fixed (NavmeshRay* r = again)
                fixed (NavmeshRaycastHit* h = againHits)
                fixed (uint* p = buffer)
                    Status.Check(RaycastBatch(navmesh, filter, r, (uint)again.Length, h, p, room));
                var still = new System.Collections.Generic.List<int>();
                for (int k = 0; k < longer.Count; ++k)
                {
                    int i = longer[k];
                    hits[i] = againHits[k];
                    if (againHits[k].PolygonCount > room)
                    {
                        still.Add(i);  // cannot happen on a navmesh that never changes; asked again all the same
                        continue;
                    }
                    polygons[i] = new uint[againHits[k].PolygonCount];
                    Array.Copy(buffer, (long)k * room, polygons[i], 0, polygons[i].Length);
                }
                longer = still;
            }
            return hits;
        }

        /// <summary>Walks in a straight line (seen from above) from start, over startPolygon (from FindNearest),
        /// towards end along the navmesh surface, as Detour's raycast: how far a body walks before a wall (the
        /// navmesh's outline, or an area the filter excludes) stops it. polygons: those crossed, the start
        /// polygon first and the hit's EndPolygon last. A batch of one ray, with room for 32 polygons, walked
        /// again with room for the hit's PolygonCount when it crossed more.</summary>
        public NavmeshRaycastHit Raycast(NavmeshId navmesh, uint startPolygon, Vec3 start, Vec3 end,
                                         out uint[] polygons, QueryFilter filter = null)
        {
            uint[][] crossed;
            NavmeshRaycastHit hit = Raycast(navmesh, new[] {new NavmeshRay(start, startPolygon, end)}, out crossed, filter)[0];
            polygons = crossed[0];
            return hit;
        }

        /// <summary>Raycast without the polygons crossed (the hit's PolygonCount still counts them).</summary>
        public NavmeshRaycastHit Raycast(NavmeshId navmesh, uint startPolygon, Vec3 start, Vec3 end, QueryFilter filter = null)
        {
            return Raycast(navmesh, new[] {new NavmeshRay(start, startPolygon, end)}, filter)[0];
        }

        // nl_navmesh_raycast with the filter laid out for the call.
        private unsafe StatusCode RaycastBatch(NavmeshId navmesh, QueryFilter filter, NavmeshRay* rays, uint count,
                                               NavmeshRaycastHit* hits, uint* polygons, uint polygonsPerRay)
        {
            float[] costs = filter == null ? null : filter.AreaCosts;
            fixed (float* c = costs)
            using (var w = Enter())
            {
                QueryFilterDef def = filter == null ? default(QueryFilterDef) : filter.ToDef(c);
                return Native.nl_navmesh_raycast(w.Pointer, navmesh, filter == null ? null : &def, rays, count, hits,
                                                 polygons, polygonsPerRay);
            }
        }

        /// <summary>Slides a point from start (over startPolygon) towards target along the navmesh, as Detour's
        /// moveAlongSurface: target when the straight way there stays on the navmesh, else the point of the walls
        /// met nearest to it. The result's Point is at the surface height, Polygon holds it, Distance is how far
        /// short of target it stopped. visited: the polygons from the start's to the result's (room for 32 first;
        /// when more were visited, the call says how many and is made again with that room).</summary>
        public unsafe NavPoint MoveAlongSurface(NavmeshId navmesh, uint startPolygon, Vec3 start, Vec3 target,
                                                out uint[] visited, QueryFilter filter = null)
        {
            var buffer = new uint[FirstWalkCapacity];
            float[] costs = filter == null ? null : filter.AreaCosts;
            fixed (float* c = costs)
            using (var w = Enter())
            {
                QueryFilterDef def = filter == null ? default(QueryFilterDef) : filter.ToDef(c);
                while (true)
                {
                    NavPoint moved;
                    uint count;
                    StatusCode status;
                    fixed (uint* p = buffer)
                        status = Native.nl_navmesh_move_along_surface(w.Pointer, navmesh, filter == null ? null : &def,
                                                                      startPolygon, (float*)&start, (float*)&target, &moved,
                                                                      p, (uint)buffer.Length, &count);
                    if (Status.IsBufferTooSmall(status) && count > buffer.Length)
                    {
                        buffer = new uint[count];  // out_count is how many it visited: slide again with that room
                        continue;
                    }
                    Status.Check(status);
                    Array.Resize(ref buffer, (int)count);
                    visited = buffer;
                    return moved;
                }
            }
        }

        /// <summary>MoveAlongSurface without the polygons visited.</summary>
        public unsafe NavPoint MoveAlongSurface(NavmeshId navmesh, uint startPolygon, Vec3 start, Vec3 target, QueryFilter filter = null)
        {
            NavPoint moved;
            float[] costs = filter == null ? null : filter.AreaCosts;
            fixed (float* c = costs)
            using (var w = Enter())
            {
                QueryFilterDef def = filter == null ? default(QueryFilterDef) : filter.ToDef(c);
                Status.Check(Native.nl_navmesh_move_along_surface(w.Pointer, navmesh, filter == null ? null : &def, startPolygon,
                                                                  (float*)&start, (float*)&target, &moved, null, 0, null));
            }
            return moved;
        }

        /// <summary>Draws random points uniformly by surface area into points, and returns how many were drawn:
        /// points.Length, or 0 when no allowed polygon lies in the circle (the rest keep Found = 0), or fewer when
        /// the allowed part inside the circle is too thin. Each drawn point has its polygon, the surface height,
        /// Found = 1, Distance 0. filter: points stay out of its excluded areas; radius &gt; 0: only within radius
        /// of centre (seen from above); reachableFrom: only points the filter's body can reach from that polygon
        /// (Limits.NoPolygon: any). The same seed, navmesh and arguments give the same points everywhere.</summary>
        public unsafe int RandomPoints(NavmeshId navmesh, Span<NavPoint> points, ulong seed = 1, QueryFilter filter = null,
                                       Vec3 centre = default(Vec3), float radius = 0, uint reachableFrom = Limits.NoPolygon)
        {
            uint found;
            float[] costs = filter == null ? null : filter.AreaCosts;
            fixed (NavPoint* p = &MemoryMarshal.GetReference(points))
            fixed (float* c = costs)
            using (var w = Enter())
            {
                QueryFilterDef filterDef = filter == null ? default(QueryFilterDef) : filter.ToDef(c);
                RandomPointsDef def = Native.nl_default_random_points_def();
                def.Filter = filter == null ? IntPtr.Zero : (IntPtr)(&filterDef);
                def.Centre = centre;
                def.Radius = radius;
                def.ReachableFrom = reachableFrom;
                def.Seed = seed;
                Status.Check(Native.nl_navmesh_random_points(w.Pointer, navmesh, &def, p, (uint)points.Length, &found));
            }
            return (int)found;
        }

        /// <summary>RandomPoints into a new array of the points drawn (count of them, or fewer as RandomPoints says).</summary>
        public NavPoint[] RandomPoints(NavmeshId navmesh, int count, ulong seed = 1, QueryFilter filter = null,
                                       Vec3 centre = default(Vec3), float radius = 0, uint reachableFrom = Limits.NoPolygon)
        {
            if (count < 0) throw new ArgumentOutOfRangeException("count", "a count of points is >= 0");
            var points = new NavPoint[count];
            int found = RandomPoints(navmesh, points, seed, filter, centre, radius, reachableFrom);
            if (found < count) Array.Resize(ref points, found);
            return points;
        }
    }
}
