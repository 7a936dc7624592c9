using System;
using System.Linq;
using NavLink;

namespace NavLink.Tests
{
    // Navmeshes built by Recast and handed over by the host; point location.
    internal static class NavmeshTests
    {
        public static void Run(Checks check)
        {
            check.Run("navmesh from the level (Recast)", () =>
            {
                using (var world = new World())
                {
                    TestLevels.AddGapLevel(world);
                    RecastSettings recast = World.DefaultRecastSettings();
                    check.Near(recast.CellSize, 0.3f, 1e-6f, "Recast's default cell size");
                    recast.CellSize = 0.2f;
                    NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType(), recast, "{\"edge_max_length\": 6}");
                    NavmeshInfo info = world.GetNavmeshInfo(navmesh);
                    check.That(info.PolygonCount >= 2 && info.BoundaryEdgeCount >= 8,
                               info.PolygonCount + " polygons, " + info.BoundaryEdgeCount + " boundary edges");
                    check.Near(info.Agent.Radius, 0.6f, 1e-6f, "the navmesh remembers its agent");
                    // Three islands: the platforms (top y = 0) and the pit floor 20 m down, walkable but unreachable.
                    check.That(info.BoundsMin.X >= -12 && info.BoundsMax.X <= 12 && info.BoundsMax.Y < 0.5f &&
                               info.BoundsMin.Y > -20.1f && info.BoundsMin.Y < -19.5f,
                               "the navmesh covers the platforms and the pit floor: " + info.BoundsMin + " " + info.BoundsMax);

                    Vec3[] vertices = world.GetNavmeshVertices(navmesh);
                    check.That(vertices.Length == info.VertexCount, vertices.Length + " vertices listed, info says " + info.VertexCount);
                    BoundaryEdge[] edges = world.GetBoundaryEdges(navmesh);
                    check.That(edges.Length == info.BoundaryEdgeCount, "boundary edges listed: " + edges.Length);
                    check.That(edges.All(e => Math.Abs(Math.Sqrt(e.Outward.X * e.Outward.X + e.Outward.Z * e.Outward.Z) - 1) < 1e-3),
                               "outward directions are unit and horizontal");

                    NavPoint[] found = world.FindNearest(navmesh, new[] { new Vec3(-6, 3, 0), new Vec3(0, 0, 0), new Vec3(0, 0, 30) },
                                                         new Vec3(2, 4, 2));
                    check.That(found[0].Found == 1 && Math.Abs(found[0].Point.X + 6) < 1e-3 && found[0].Point.Y < 0.5f,
                               "(-6 3 0) lands on the west platform: " + found[0].Point);
                    check.That(found[1].Found == 1 && found[1].Point.X <= -1.5f || found[1].Point.X >= 1.5f,
                               "over the gap, the nearest point is on a rim: " + found[1].Point);
                    check.That(found[2].Found == 0 && found[2].Polygon == Limits.NoPolygon, "(0 0 30) is nowhere near");

                    check.That(world.GetNavmeshes().SequenceEqual(new[] { navmesh }), "the world lists its navmesh");

                    // The settings struct reaches the builder: 3 corners per polygon turn the platforms' quads into triangles.
                    RecastSettings triangles = World.DefaultRecastSettings();
                    triangles.VerticesPerPolygon = 3;
                    NavmeshId triangulated = world.BuildNavmesh(World.DefaultAgentType(), triangles);
                    uint polygons = world.GetNavmeshInfo(triangulated).PolygonCount;
                    check.That(Enumerable.Range(0, (int)polygons).All(i => world.GetPolygon(triangulated, (uint)i).VertexCount == 3) &&
                               Enumerable.Range(0, (int)info.PolygonCount).Any(i => world.GetPolygon(navmesh, (uint)i).VertexCount > 3),
                               "vertices_per_polygon 3: triangles only (the default has larger polygons)");
                    world.RemoveNavmesh(triangulated);
                    check.Throws(StatusBits.ParseError, "settings", () => world.BuildNavmesh(World.DefaultAgentType(), null, "{oops"),
                                 "malformed settings JSON");
                    check.Throws(StatusBits.NotFound, "nope", () => world.BuildNavmesh(World.DefaultAgentType(), null, null, "nope"),
                                 "an unknown builder");
                    world.RemoveNavmesh(navmesh);
                    check.That(!world.IsValid(navmesh), "a removed navmesh is not valid");
                    check.Throws(StatusBits.InvalidHandle, "nl_navmesh_get_info", () => world.GetNavmeshInfo(navmesh), "a stale navmesh");
                }
                using (var empty = new World())
                    check.Throws(StatusBits.NotFound, "walkable", () => empty.BuildNavmesh(World.DefaultAgentType()),
                                 "a level with nothing walkable");
            });

            check.Run("navmesh from the host", () =>
            {
                // Two 1 x 1 m squares as four triangles with their own vertices (Unity's triangulation).
                var input = new NavmeshInput
                {
                    Vertices = new float[] {0, 0, 0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0,
                                            1, 0, 0, 1, 0, 1, 2, 0, 1, 1, 0, 0, 2, 0, 1, 2, 0, 0},
                    Indices = new uint[] {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11},
                    Areas = new byte[] {0, 0, 5, 5},
                };
                using (var world = new World())
                {
                    NavmeshId navmesh = world.AddNavmesh(input);
                    NavmeshInfo info = world.GetNavmeshInfo(navmesh);
                    check.That(info.VertexCount == 6 && info.WeldedVertexCount == 6 && info.PortalCount == 3 &&
                               info.BoundaryEdgeCount == 6,
                               "welded: " + info.VertexCount + " vertices, " + info.PortalCount + " portals, " + info.BoundaryEdgeCount + " edges");
                    NavPolygon polygon = world.GetPolygon(navmesh, 2);
                    unsafe
                    {
                        int linked = 0;
                        for (int k = 0; k < polygon.VertexCount; ++k)
                            if (polygon.Neighbours[k] != Limits.NoPolygon) ++linked;
                        check.That(polygon.VertexCount == 3 && polygon.Area == 5 && linked >= 1 && polygon.Neighbours[15] == Limits.NoPolygon,
                                   "polygon 2: 3 corners, area 5, " + linked + " neighbours, unused entries NO_POLYGON");
                    }
                    check.Throws(StatusBits.InvalidArgument, "polygon", () => world.GetPolygon(navmesh, 99), "polygon 99");
                    input.Indices[2] = 40;
                    check.Throws(StatusBits.InvalidArgument, "indices", () => world.AddNavmesh(input), "an index out of range");
                }
            });
        }
    }
}
