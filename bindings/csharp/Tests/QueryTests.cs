using System;
using System.Linq;
using NavLink;

namespace NavLink.Tests
{
    // navlink.h's "Queries on a navmesh for one body" (tests/abi/queries_tests.c's cells): a navmesh of 1 m cells
    // in one row, "..#..#..": polygons 0-1 (x in [0, 2]), 2-3 (x in [3, 5]) and 4-5 (x in [6, 8]), z in [0, 1],
    // y = 0, for radius 0; a one-way manual link from cell 1's centre to cell 3's (2 m: its gap). A jumper
    // (3 m) takes it, a walker does not. And find_nearest's point beyond its box.
    internal static class QueryTests
    {
        private static readonly Vec3 Start = new Vec3(0.5f, 0, 0.5f);

        /// <summary>The cells of one row, '.' area 0, '#' none, as QueryTests' navmesh, with its link.</summary>
        public static NavmeshId AddCellRow(World world, string row)
        {
            var vertices = new System.Collections.Generic.List<float>();
            int cells = 0;
            for (int c = 0; c < row.Length; ++c)
            {
                if (row[c] != '.') continue;
                vertices.AddRange(new float[] {c, 0, 0, c, 0, 1, c + 1, 0, 1, c + 1, 0, 0});
                ++cells;
            }
            var input = new NavmeshInput
            {
                Vertices = vertices.ToArray(),
                Indices = Enumerable.Range(0, 4 * cells).Select(i => (uint)i).ToArray(),
                PolygonVertexCounts = Enumerable.Repeat((byte)4, cells).ToArray(),
            };
            input.AgentType.Radius = 0;
            return world.AddNavmesh(input);
        }

        private static QueryFilter Body(float jump)
        {
            AgentCapabilities agent = World.DefaultAgentCapabilities();
            agent.Radius = 0;
            agent.MaxJumpDistance = jump;
            return new QueryFilter(agent);
        }

        private static bool Near(Vec3 a, float x, float y, float z)
        {
            return Math.Abs(a.X - x) < 1e-3f && Math.Abs(a.Y - y) < 1e-3f && Math.Abs(a.Z - z) < 1e-3f;
        }

        private static bool SameHit(NavmeshRaycastHit a, NavmeshRaycastHit b)
        {
            return a.Hit == b.Hit && a.T == b.T && a.Point.Equals(b.Point) && a.WallNormal.Equals(b.WallNormal) &&
                   a.EndPolygon == b.EndPolygon && a.PolygonCount == b.PolygonCount;
        }

        public static void Run(Checks check)
        {
            check.Run("queries for one body: reachability, raycast, slide, random points", () =>
            {
                using (var world = new World())
                {
                    NavmeshId navmesh = AddCellRow(world, "..#..#..");
                    LinkDef link = World.DefaultLinkDef();
                    link.Start = new Vec3(1.5f, 0, 0.5f);
                    link.End = new Vec3(3.5f, 0, 0.5f);
                    world.AddLink(navmesh, link);
                    QueryFilter walker = Body(0), jumper = Body(3);
                    check.That(new QueryFilter().Capabilities.Radius == World.DefaultAgentCapabilities().Radius &&
                               new QueryFilter().AreaCosts == null, "new QueryFilter() is nl_default_query_filter()'s walker");
                    QueryFilterDef raw = Native.nl_default_query_filter();
                    check.That(raw.Size == (uint)System.Runtime.InteropServices.Marshal.SizeOf(typeof(QueryFilterDef)) && raw.AreaCosts == IntPtr.Zero && raw.AreaCostCount == 0, "nl_default_query_filter's size and no costs");

                    // Reachability.
                    check.That(world.CanReach(navmesh, 0, 1, walker), "a cell reaches its neighbour");
                    check.That(!world.CanReach(navmesh, 0, 1), "the default walker (radius 0.6) does not fit through a 1 m portal");
                    check.That(!world.CanReach(navmesh, 1, 2, walker), "a walker does not cross the gap");
                    check.That(world.CanReach(navmesh, 0, 3, jumper), "a jumper takes the link to the next island");
                    check.That(!world.CanReach(navmesh, 3, 0, jumper), "the one-way link does not lead back");
                    bool[] answers = world.CanReach(navmesh, new uint[] {0, 3, 5}, new uint[] {3, 0, 4}, jumper);
                    check.That(answers.SequenceEqual(new[] {true, false, true}), "a batch of pairs: " + string.Join(",", answers));
                    check.That(world.GetReachablePolygons(navmesh, 1, jumper).SequenceEqual(new uint[] {0, 1, 2, 3}),
                               "a jumper reaches polygons 0-3 from 1");
                    check.That(world.GetReachablePolygons(navmesh, 1, walker).SequenceEqual(new uint[] {0, 1}), "a walker 0-1");
                    uint islandCount;
                    uint[] islands = world.GetIslands(navmesh, out islandCount, jumper);
                    check.That(islandCount == 3 && islands.SequenceEqual(new uint[] {0, 0, 1, 1, 2, 2}),
                               "three islands, numbered by their lowest polygon: " + string.Join(",", islands));
                    var keepOut = new QueryFilter(jumper.Capabilities, new[] {Limits.AreaExcluded});
                    islands = world.GetIslands(navmesh, out islandCount, keepOut);
                    check.That(islandCount == 0 && islands.Length == 6 && islands.All(i => i == Limits.NoIsland),
                               "keeping out of area 0 leaves no island");
                    check.That(!world.CanReach(navmesh, 0, 1, keepOut) && world.CanReach(navmesh, 0, 0, keepOut),
                               "an excluded polygon is reached from nowhere else, but reaches itself");
                    check.Throws(StatusCode.InvalidArgument, "to_polygons[0] is 6", () => world.CanReach(navmesh, 0, 6, jumper),
                                 "a polygon out of range");

                    // The navmesh raycast: into the missing cell 2, its wall at x = 2 stops the walk.
                    uint[] crossed;
                    NavmeshRaycastHit hit = world.Raycast(navmesh, 0, Start, new Vec3(4.5f, 0, 0.5f), out crossed);
                    check.That(hit.Hit == 1 && Math.Abs(hit.T - 0.375f) < 1e-4f && Near(hit.Point, 2, 0, 0.5f) &&
                               Near(hit.WallNormal, -1, 0, 0) && hit.EndPolygon == 1,
                               "a raycast into a missing cell stops at its wall: t " + hit.T + " at " + hit.Point + ", normal " + hit.WallNormal);
                    check.That(hit.PolygonCount == 2 && crossed.SequenceEqual(new uint[] {0, 1}), "crossed 0 and 1: " + string.Join(",", crossed));
                    hit = world.Raycast(navmesh, 0, Start, new Vec3(1.5f, 0, 0.5f));
                    check.That(hit.Hit == 0 && hit.T == 1 && Near(hit.Point, 1.5f, 0, 0.5f) && Near(hit.WallNormal, 0, 0, 0) &&
                               hit.EndPolygon == 1 && hit.PolygonCount == 2, "a raycast within the island arrives");
                    // The single ray is a batch of one: the library names it rays[0].
                    check.Throws(StatusCode.InvalidArgument, "rays[0].start is not over rays[0].start_polygon 2",
                                 () => world.Raycast(navmesh, 2, Start, new Vec3(1, 0, 1)), "a start off its polygon");

                    // A batch of rays gives each the answer a single call gives it.
                    var rays = new[]
                    {
                        new NavmeshRay(Start, 0, new Vec3(4.5f, 0, 0.5f)),           // into the missing cell
                        new NavmeshRay(Start, 0, new Vec3(1.5f, 0, 0.5f)),           // arrives
                        new NavmeshRay(new Vec3(3.5f, 0, 0.5f), 2, new Vec3(0.5f, 0, 0.5f)),  // west into the gap
                        new NavmeshRay(new Vec3(6.5f, 0, 0.25f), 4, new Vec3(7.5f, 0, 0.75f)),  // across the last island
                        new NavmeshRay(new Vec3(1.5f, 0, 0.5f), 1, new Vec3(1.5f, 0, 3)),  // out through the side
                    };
                    uint[][] batchCrossed;
                    NavmeshRaycastHit[] hits = world.Raycast(navmesh, rays, out batchCrossed, jumper);
                    NavmeshRaycastHit[] bare = world.Raycast(navmesh, rays, jumper);
                    check.That(hits.Length == 5 && batchCrossed.Length == 5 && bare.Length == 5, "one hit and one list per ray");
                    for (int i = 0; i < rays.Length; ++i)
                    {
                        uint[] single;
                        NavmeshRaycastHit one = world.Raycast(navmesh, rays[i].StartPolygon, rays[i].Start, rays[i].End, out single, jumper);
                        check.That(SameHit(hits[i], one) && SameHit(bare[i], one) && batchCrossed[i].SequenceEqual(single) &&
                                   one.PolygonCount == single.Length,
                                   "ray " + i + " in a batch as alone: t " + hits[i].T + " / " + one.T + ", polygons " +
                                   string.Join(",", batchCrossed[i]) + " / " + string.Join(",", single));
                    }
                    check.That(hits[0].Hit == 1 && Near(hits[0].Point, 2, 0, 0.5f) && hits[1].Hit == 0 &&
                               hits[2].Hit == 1 && Near(hits[2].Point, 3, 0, 0.5f) && Near(hits[2].WallNormal, 1, 0, 0) &&
                               batchCrossed[2].SequenceEqual(new uint[] {2}) && hits[3].Hit == 0 && hits[3].EndPolygon == 5 &&
                               hits[4].Hit == 1 && Near(hits[4].Point, 1.5f, 0, 1) && Near(hits[4].WallNormal, 0, 0, -1),
                               "the batch's own answers: " + hits[2].Point + ", " + hits[4].Point);
                    var into = new NavmeshRaycastHit[6];
                    world.Raycast(navmesh, rays, into, jumper);
                    check.That(Enumerable.Range(0, 5).All(i => SameHit(into[i], hits[i])) && into[0].Size == hits[0].Size,
                               "into a span of hits");
                    check.That(world.Raycast(navmesh, new NavmeshRay[0], out batchCrossed).Length == 0 && batchCrossed.Length == 0,
                               "an empty batch");
                    rays[3].StartPolygon = 2;
                    into = new NavmeshRaycastHit[5];
                    check.Throws(StatusCode.InvalidArgument, "rays[3].start is not over rays[3].start_polygon 2",
                                 () => world.Raycast(navmesh, rays, into), "a batch with one ray off its polygon is refused");
                    check.That(into.All(h => h.T == 0 && h.PolygonCount == 0 && h.EndPolygon == 0),
                               "a refused batch writes no hit (the binding set the first one's Size only)");

                    // Sliding along the surface: towards the missing cell, to the wall's point nearest the target.
                    uint[] visited;
                    NavPoint moved = world.MoveAlongSurface(navmesh, 0, Start, new Vec3(2.5f, 0, 0.5f), out visited);
                    check.That(moved.Found == 1 && Near(moved.Point, 2, 0, 0.5f) && moved.Polygon == 1 &&
                               Math.Abs(moved.Distance - 0.5f) < 1e-3f, "a slide into a wall stops on it, 0.5 m short: " + moved.Point);
                    check.That(visited.Length >= 2 && visited[0] == 0 && visited[visited.Length - 1] == 1,
                               "visited from 0 to 1: " + string.Join(",", visited));
                    moved = world.MoveAlongSurface(navmesh, 0, Start, new Vec3(1.5f, 0, 0.5f), walker);
                    check.That(Near(moved.Point, 1.5f, 0, 0.5f) && moved.Polygon == 1 && moved.Distance == 0, "a clear slide arrives");

                    // Random points: on their cells, the same for the same seed.
                    NavPoint[] points = world.RandomPoints(navmesh, 50, seed: 7);
                    check.That(points.Length == 50 && points.All(p => p.Found == 1 && p.Distance == 0 && p.Point.Y == 0 &&
                                                                      p.Point.Z >= 0 && p.Point.Z <= 1 && p.Polygon < 6),
                               "50 random points on the navmesh");
                    float[] cellX = {0, 1, 3, 4, 6, 7};
                    check.That(points.All(p => p.Point.X >= cellX[p.Polygon] && p.Point.X <= cellX[p.Polygon] + 1),
                               "each random point on its polygon");
                    NavPoint[] again = world.RandomPoints(navmesh, 50, seed: 7);
                    check.That(Enumerable.Range(0, 50).All(i => points[i].Point.Equals(again[i].Point) && points[i].Polygon == again[i].Polygon),
                               "the same seed gives the same points");
                    again = world.RandomPoints(navmesh, 50, seed: 8);
                    check.That(Enumerable.Range(0, 50).Any(i => !points[i].Point.Equals(again[i].Point)), "another seed gives others");
                    points = world.RandomPoints(navmesh, 50, seed: 7, filter: jumper, reachableFrom: 4);
                    check.That(points.Length == 50 && points.All(p => p.Polygon == 4 || p.Polygon == 5),
                               "reachable from polygon 4: the last island only");
                    points = world.RandomPoints(navmesh, 50, centre: new Vec3(0.5f, 0, 0.5f), radius: 0.5f);
                    check.That(points.Length == 50 && points.All(p => p.Point.HorizontalDistance(Start) <= 0.5f + 1e-4f),
                               "within 0.5 m of the centre");
                    check.That(world.RandomPoints(navmesh, 10, filter: keepOut).Length == 0, "none outside the excluded area");
                    var span = new NavPoint[4];
                    check.That(world.RandomPoints(navmesh, span, seed: 7) == 4 && span[3].Found == 1, "into a span");

                    // find_nearest beyond its box: the navmesh's nearest point, 4 m off.
                    NavPoint[] nearest = world.FindNearest(navmesh, new[] {new Vec3(12, 0, 0.5f), Start}, new Vec3(1, 1, 1));
                    check.That(nearest[0].Found == 0 && nearest[0].BeyondBox == 1 && nearest[0].Polygon == Limits.NoPolygon &&
                               Near(nearest[0].Point, 8, 0, 0.5f) && Math.Abs(nearest[0].Distance - 4) < 1e-3f,
                               "a miss gives the nearest point beyond the box: " + nearest[0].Point + ", " + nearest[0].Distance + " m");
                    check.That(nearest[1].Found == 1 && nearest[1].BeyondBox == 0 && nearest[1].Polygon == 0, "a hit is not beyond the box");
                }
            });

            check.Run("queries for one body: walks longer than the first buffer", () =>
            {
                using (var world = new World())
                {
                    // 40 cells in a row: a walk from the first to the last crosses 40 polygons, more than the
                    // binding's first buffer holds, so it asks again.
                    NavmeshId row = AddCellRow(world, new string('.', 40));
                    uint[] crossed, visited;
                    NavmeshRaycastHit hit = world.Raycast(row, 0, Start, new Vec3(39.5f, 0, 0.5f), out crossed);
                    check.That(hit.Hit == 0 && hit.PolygonCount == 40 && crossed.SequenceEqual(Enumerable.Range(0, 40).Select(i => (uint)i)),
                               "a raycast across 40 cells lists them all: " + crossed.Length);
                    NavPoint moved = world.MoveAlongSurface(row, 0, Start, new Vec3(39.5f, 0, 0.5f), out visited);
                    check.That(moved.Polygon == 39 && Near(moved.Point, 39.5f, 0, 0.5f) && visited.Length == 40 &&
                               visited[0] == 0 && visited[39] == 39, "a slide across 40 cells lists them all: " + visited.Length);

                    // A batch of long and short walks: those that crossed more than 32 are walked again, together.
                    var rays = new[]
                    {
                        new NavmeshRay(Start, 0, new Vec3(39.5f, 0, 0.5f)),
                        new NavmeshRay(Start, 0, new Vec3(1.5f, 0, 0.5f)),
                        new NavmeshRay(new Vec3(39.5f, 0, 0.5f), 39, new Vec3(2.5f, 0, 0.5f)),
                        new NavmeshRay(new Vec3(10.5f, 0, 0.5f), 10, new Vec3(45, 0, 0.5f)),
                        new NavmeshRay(new Vec3(20.5f, 0, 0.5f), 20, new Vec3(20.5f, 0, 0.5f)),
                    };
                    uint[][] lists;
                    NavmeshRaycastHit[] hits = world.Raycast(row, rays, out lists);
                    uint[] counts = hits.Select(h => h.PolygonCount).ToArray();
                    check.That(counts.SequenceEqual(new uint[] {40, 2, 38, 30, 1}) && lists.Select(l => (uint)l.Length).SequenceEqual(counts),
                               "each ray's polygons, the long ones too: " + string.Join(",", counts));
                    check.That(lists[0].SequenceEqual(crossed) && lists[2].SequenceEqual(Enumerable.Range(2, 38).Reverse().Select(i => (uint)i)) &&
                               hits[3].Hit == 1 && Near(hits[3].Point, 40, 0, 0.5f) && lists[4].SequenceEqual(new uint[] {20}) && hits[4].T == 1,
                               "backwards, out of the row's end, and a ray of no length");
                    for (int i = 0; i < rays.Length; ++i)
                    {
                        uint[] single;
                        NavmeshRaycastHit one = world.Raycast(row, rays[i].StartPolygon, rays[i].Start, rays[i].End, out single);
                        check.That(SameHit(hits[i], one) && lists[i].SequenceEqual(single), "long ray " + i + " in a batch as alone");
                    }
                }
            });
        }
    }
}
