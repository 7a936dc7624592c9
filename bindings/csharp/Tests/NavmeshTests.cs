using System;
using System.IO;
using System.Linq;
using NavLink;

namespace NavLink.Tests
{
    // Navmeshes built by Recast and handed over by the host; point location; a navmesh that rides a moving mesh,
    // a cross link onto it, and cross links generated between it and a ledge.
    internal static class NavmeshTests
    {
        // The moving surface: an 8 x 4 m movable box (top y = 0 in its own space) carrying a 7.2 x 3.2 m navmesh
        // quad, then moved 10 m along x and turned 90 degrees about y: its x axis goes to the world's -z, its z
        // axis to x.
        private static readonly float[] RaftQuad = {-3.6f, 0, -1.6f, -3.6f, 0, 1.6f, 3.6f, 0, 1.6f, 3.6f, 0, -1.6f};
        private static readonly float[] RaftMoved = {0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 10, 0, 0, 1};
        private static readonly float[] RaftScaled = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 10, 0, 0, 1};

        // A cross link onto a moving surface: a static 6 x 4 m ledge navmesh (x in [-6, 0], z in [-2, 2], y = 0)
        // and, 1 m past its edge, a 4 x 4 m movable box (x in [1, 5]; its own space is the world's until it moves)
        // carrying a 3.6 x 3.6 m navmesh quad. The link goes from the ledge's edge onto the box; the box then
        // moves 2 m away along x and back.
        private static readonly float[] LedgeQuad = {-6, 0, -2, -6, 0, 2, 0, 0, 2, 0, 0, -2};
        private static readonly float[] DeckQuad = {1.2f, 0, -1.8f, 1.2f, 0, 1.8f, 4.8f, 0, 1.8f, 4.8f, 0, -1.8f};
        private static readonly float[] DeckHome = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        private static readonly float[] DeckAway = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 2, 0, 0, 1};
        private static readonly Vec3 CrossStart = new Vec3(-0.4f, 0, 0), CrossEnd = new Vec3(1.6f, 0, 0),
                                     CrossEndAway = new Vec3(3.6f, 0, 0);

        // Generated cross links (tests/core/world/surface_tests.cpp's ferry): a static 6 x 6 m ledge (box x in [0, 6], z in
        // [0, 6], top y = 0) whose navmesh is its top eroded 0.3 m, and a 4 x 4 m movable box (top y = 0 in its own
        // space, centred on its origin) carrying its top eroded 0.3 m as a navmesh, placed 1 m off the ledge's edge
        // (centre x = 9, z = 3), then 3 m off (x = 11). Both navmeshes for radius 0.3; jumps up to 2 m across.
        private static readonly float[] LedgeTop = {0.3f, 0, 0.3f, 0.3f, 0, 5.7f, 5.7f, 0, 5.7f, 5.7f, 0, 0.3f};
        private static readonly float[] PlatformTop = {-1.7f, 0, -1.7f, -1.7f, 0, 1.7f, 1.7f, 0, 1.7f, 1.7f, 0, -1.7f};

        /// <summary>The platform's transform: its centre at (x, 0, 3) (column-major).</summary>
        private static float[] PlatformAt(float x) { return new float[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, 0, 3, 1}; }

        private static NavmeshInput Quad(float[] vertices, MeshId carrier = default(MeshId))
        {
            return new NavmeshInput
            {
                Vertices = vertices, Indices = new uint[] {0, 1, 2, 3}, PolygonVertexCounts = new byte[] {4}, Carrier = carrier,
            };
        }

        // Within a millimetre: navmeshes keep coordinates on a grid of 1/1024 m.
        private static bool Near(Vec3 a, Vec3 b)
        {
            return Math.Abs(a.X - b.X) < 1e-3f && Math.Abs(a.Y - b.Y) < 1e-3f && Math.Abs(a.Z - b.Z) < 1e-3f;
        }

        private static bool Same(Vec3 a, Vec3 b) { return a.X == b.X && a.Y == b.Y && a.Z == b.Z; }

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
                    check.Near(info.AgentType.Radius, 0.6f, 1e-6f, "the navmesh remembers its agent");
                    check.That(info.TurnedOverMeshCount == 0,
                               "the level's fronts are wound counter-clockwise: " + info.TurnedOverMeshCount + " meshes turned over");
                    check.That(info.BuildWarnings == BuildWarnings.None, "the level is in metres with y up: " + info.BuildWarnings);
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
                    check.Throws(StatusCode.ParseError, "settings", () => world.BuildNavmesh(World.DefaultAgentType(), null, "{oops"),
                                 "malformed settings JSON");
                    check.Throws(StatusCode.NotFound, "nope", () => world.BuildNavmesh(World.DefaultAgentType(), null, null, "nope"),
                                 "an unknown builder");
                    world.RemoveNavmesh(navmesh);
                    check.That(!world.IsValid(navmesh), "a removed navmesh is not valid");
                    check.Throws(StatusCode.InvalidHandle, "nl_navmesh_get_info", () => world.GetNavmeshInfo(navmesh), "a stale navmesh");
                }
                using (var empty = new World())
                    check.Throws(StatusCode.NotFound, "walkable", () => empty.BuildNavmesh(World.DefaultAgentType()),
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
                    check.Throws(StatusCode.InvalidArgument, "polygon", () => world.GetPolygon(navmesh, 99), "polygon 99");
                    input.Indices[2] = 40;
                    check.Throws(StatusCode.InvalidArgument, "indices", () => world.AddNavmesh(input), "an index out of range");
                }
            });

            check.Run("tiles out and in again", () =>
            {
                // A 40 x 12 m floor (top y = 0) built in tiles of 32 cells (9.6 m); the tile under (20, 0, 3) goes and
                // comes back built again from the level (BuildTiles), goes again and comes back as a hand-made quad,
                // the floor eroded 0.6 m within the tile's square.
                using (var world = new World())
                {
                    TestLevels.AddBox(world, 0, -1, 0, 40, 0, 12);
                    RecastSettings recast = World.DefaultRecastSettings();
                    check.That(recast.TileSize == 0 && recast.TileBorder == 0, "solo by default: tile size " + recast.TileSize);
                    recast.TileSize = 32;
                    NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType(), recast);
                    NavmeshInfo info = world.GetNavmeshInfo(navmesh);
                    TileCoord[] tiles = world.GetTiles(navmesh);
                    check.That(tiles.Length > 1 && tiles.Length == info.TileCount,
                               tiles.Length + " tiles listed, info says " + info.TileCount);
                    check.That(tiles.SequenceEqual(tiles.OrderBy(t => t.Z).ThenBy(t => t.X)), "row order: z, then x");
                    check.Near(info.TileWidth, 32 * recast.CellSize, 1e-4f, "the tile width");
                    float width = info.TileWidth, originX, originZ;
                    unsafe
                    {
                        originX = info.TileOrigin[0];
                        originZ = info.TileOrigin[1];
                    }
                    Vec3 middle = new Vec3(20, 0, 3), near = new Vec3(0.4f, 0.3f, 0.4f);
                    Vec3 west = new Vec3(2, 0, 3), east = new Vec3(38, 0, 3);
                    var tile = new TileCoord((int)Math.Floor((middle.X - originX) / width), (int)Math.Floor((middle.Z - originZ) / width));
                    check.That(tiles.Contains(tile), "the tile under " + middle + ", " + tile + ", is loaded");
                    check.That(world.FindNearest(navmesh, new[] {middle}, near)[0].Found == 1, "the floor under it is walkable");
                    check.That(world.FindPath(new PathQuery(navmesh, west, east, TestLevels.Walker())).Outcome == PathOutcome.Complete,
                               "a path from end to end");

                    world.RemoveTile(navmesh, tile);
                    TileCoord[] after = world.GetTiles(navmesh);
                    check.That(after.Length == tiles.Length - 1 && after.SequenceEqual(tiles.Where(t => t != tile)),
                               "the tile is gone from the list: " + after.Length + " of " + tiles.Length);
                    check.That(world.GetNavmeshInfo(navmesh).TileCount == after.Length, "info counts the tiles left");
                    check.That(world.FindNearest(navmesh, new[] {middle}, near)[0].Found == 0, "a hole where the tile was");
                    check.Throws(StatusCode.NotFound, "no tile", () => world.RemoveTile(navmesh, tile), "the tile removed twice");
                    check.That(world.GetTiles(navmesh).SequenceEqual(after), "a refused removal changes nothing");

                    // The tile built again from the level, with the same settings, in a small box around its centre.
                    var centre = new Vec3(originX + (tile.X + 0.5f) * width, 0, originZ + (tile.Z + 0.5f) * width);
                    Vec3 boxMin = new Vec3(centre.X - 0.5f, -1, centre.Z - 0.5f), boxMax = new Vec3(centre.X + 0.5f, 1, centre.Z + 0.5f);
                    world.BuildTiles(navmesh, World.DefaultAgentType(), boxMin, boxMax, recast);
                    check.That(world.GetTiles(navmesh).SequenceEqual(tiles), "the built tile is back in its place");
                    check.That(world.GetNavmeshInfo(navmesh).TileCount == tiles.Length, "info counts the built tile");
                    check.That(world.FindNearest(navmesh, new[] {middle}, near)[0].Found == 1, "the built tile fills the hole");
                    check.That(world.FindPath(new PathQuery(navmesh, west, east, TestLevels.Walker())).Outcome == PathOutcome.Complete,
                               "the built tile joins its neighbours: a path from end to end");
                    // Settings making tiles of another width (64 cells) are refused, and change nothing.
                    uint polygons = world.GetNavmeshInfo(navmesh).PolygonCount;
                    Vec3[] vertices = world.GetNavmeshVertices(navmesh);
                    RecastSettings wider = World.DefaultRecastSettings();
                    wider.TileSize = 64;
                    check.Throws(StatusCode.InvalidArgument, "makes tiles of",
                                 () => world.BuildTiles(navmesh, World.DefaultAgentType(), boxMin, boxMax, wider), "tiles of 64 cells");
                    check.That(world.GetTiles(navmesh).SequenceEqual(tiles), "a refused build changes no tile");
                    check.That(world.GetNavmeshInfo(navmesh).TileCount == tiles.Length, "info's count unchanged");
                    check.That(world.GetNavmeshInfo(navmesh).PolygonCount == polygons &&
                               world.GetNavmeshVertices(navmesh).SequenceEqual(vertices), "a refused build changes no polygon");
                    check.That(world.FindPath(new PathQuery(navmesh, west, east, TestLevels.Walker())).Outcome == PathOutcome.Complete,
                               "a path from end to end still");
                    world.RemoveTile(navmesh, tile);
                    check.That(world.GetTiles(navmesh).SequenceEqual(after), "the built tile removed again");

                    // The host's tile: one quad on the navmesh's grid.
                    float x0 = Math.Max(originX + tile.X * width, 0.6f), z0 = Math.Max(originZ + tile.Z * width, 0.6f);
                    float x1 = Math.Min(originX + (tile.X + 1) * width, 39.4f), z1 = Math.Min(originZ + (tile.Z + 1) * width, 11.4f);
                    NavmeshInput quad = Quad(new[] {x0, 0, z0, x0, 0, z1, x1, 0, z1, x1, 0, z0});
                    quad.TileWidth = width;
                    quad.TileOriginX = originX;
                    quad.TileOriginZ = originZ;
                    quad.TileX = tile.X;
                    quad.TileZ = tile.Z;
                    world.AddTile(navmesh, quad);
                    check.That(world.GetTiles(navmesh).SequenceEqual(tiles), "the hand-made tile is back in its place");
                    check.That(world.GetNavmeshInfo(navmesh).TileCount == tiles.Length, "info counts it");
                    check.That(world.FindNearest(navmesh, new[] {middle}, near)[0].Found == 1, "the hand-made tile fills the hole");
                    check.That(world.FindPath(new PathQuery(navmesh, west, east, TestLevels.Walker())).Outcome == PathOutcome.Complete,
                               "the tile joins its neighbours: a path from end to end");
                    check.Throws(StatusCode.InvalidArgument, "loaded already", () => world.AddTile(navmesh, quad), "a tile added twice");
                    quad.TileWidth = 2 * width;
                    quad.TileX = 99;
                    check.Throws(StatusCode.InvalidArgument, "another grid", () => world.AddTile(navmesh, quad), "a tile of another grid");
                    NavmeshInput noTile = Quad(new[] {x0, 0, z0, x0, 0, z1, x1, 0, z1, x1, 0, z0});
                    check.Throws(StatusCode.InvalidArgument, "not a tile", () => world.AddTile(navmesh, noTile), "polygons that are not a tile");
                    // A solo navmesh has no tiles and takes none.
                    NavmeshId solo = world.AddNavmesh(Quad(new float[] {-5, 0, -5, -5, 0, 5, 5, 0, 5, 5, 0, -5}));
                    check.That(world.GetTiles(solo).Length == 0 && world.GetNavmeshInfo(solo).TileCount == 0, "a solo navmesh lists no tiles");
                    check.Throws(StatusCode.InvalidArgument, "not tiled", () => world.RemoveTile(solo, new TileCoord(0, 0)),
                                 "removing a tile of a solo navmesh");
                    check.That((uint)AgentReason.TileUnloaded == 9u, "AgentReason.TileUnloaded");
                }
            });

            check.Run("tiles saved and loaded as tiles' files", () =>
            {
                // The gap level built in tiles of 32 cells (9.6 m), its links generated (the jumps start on one tile and
                // land on another); every tile saved and described; the first tile's bytes loaded in a second world with
                // the same level and the others added make the same tiles and links.
                string dir = Path.Combine(Path.GetTempPath(), "navlink-csharp-" + Guid.NewGuid().ToString("N"));
                Directory.CreateDirectory(dir);
                try
                {
                    using (var world = new World())
                    {
                        TestLevels.AddGapLevel(world);
                        RecastSettings recast = World.DefaultRecastSettings();
                        recast.TileSize = 32;
                        NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType(), recast);
                        world.GenerateLinks(navmesh);
                        NavmeshInfo info = world.GetNavmeshInfo(navmesh);
                        TileCoord[] tiles = world.GetTiles(navmesh);
                        int linkCount = world.GetLinks(navmesh).Length;
                        check.That(tiles.Length > 1 && linkCount > 0, tiles.Length + " tiles, " + linkCount + " links");
                        float originX, originZ;
                        unsafe
                        {
                            originX = info.TileOrigin[0];
                            originZ = info.TileOrigin[1];
                        }

                        var files = new byte[tiles.Length][];
                        long tileLinks = 0;
                        for (int k = 0; k < tiles.Length; ++k)
                        {
                            files[k] = world.SaveTile(navmesh, tiles[k]);
                            NavmeshFileInfo described = World.DescribeNavmeshFile(files[k]);
                            check.That(described.IsTile == 1 && described.Tile == tiles[k],
                                       "tile " + tiles[k] + "'s file describes tile " + described.Tile + ", is_tile " + described.IsTile);
                            ulong hash = world.GetTileHash(navmesh, tiles[k]);
                            check.That(hash != 0 && described.ContentHash == hash,
                                       "tile " + tiles[k] + "'s content hash " + described.ContentHash.ToString("x16") + ", the world's " +
                                       hash.ToString("x16"));
                            check.That(described.TileWidth == info.TileWidth && described.TileOriginX == originX &&
                                       described.TileOriginZ == originZ && described.FileSize == (ulong)files[k].Length,
                                       "tile " + tiles[k] + "'s grid and size");
                            tileLinks += described.LinkCount;
                        }
                        check.That(tileLinks == linkCount, "the tiles' files hold " + tileLinks + " links of " + linkCount);
                        check.That(World.DescribeNavmeshFile(world.SaveNavmesh(navmesh)).IsTile == 0, "a whole navmesh's file is no tile's");

                        using (var other = new World())
                        {
                            TestLevels.AddGapLevel(other);
                            NavmeshId loaded = other.LoadNavmesh(files[0]);
                            check.That(other.GetTiles(loaded).SequenceEqual(new[] {tiles[0]}), "the first tile's file makes a navmesh of that tile");
                            for (int k = 1; k < tiles.Length; ++k) other.AddTileBytes(loaded, files[k]);
                            check.That(other.GetTiles(loaded).SequenceEqual(tiles), "the same tiles loaded");
                            check.That(other.GetLinks(loaded).Length == linkCount,
                                       other.GetLinks(loaded).Length + " links loaded, " + linkCount + " saved");
                            check.That(other.GetNavmeshInfo(loaded).PolygonCount == info.PolygonCount, "the same polygon count");

                            // Once through a file: the tile with the most links, saved to a file, removed and added back from it.
                            int most = Enumerable.Range(0, tiles.Length)
                                                 .OrderByDescending(k => World.DescribeNavmeshFile(files[k]).LinkCount).First();
                            string file = Path.Combine(dir, "tile.nlnav");
                            world.SaveTileFile(navmesh, tiles[most], file);
                            check.That(File.ReadAllBytes(file).SequenceEqual(files[most]), "the tile's file holds its bytes");
                            other.RemoveTile(loaded, tiles[most]);
                            check.That(other.GetTiles(loaded).Length == tiles.Length - 1, "the tile removed");
                            other.AddTileFile(loaded, file);
                            check.That(other.GetTiles(loaded).SequenceEqual(tiles), "the tile added from the file");
                            check.That(other.GetLinks(loaded).Length == linkCount, "its links back with it");

                            check.Throws(StatusCode.InvalidArgument, "loaded already", () => other.AddTileBytes(loaded, files[most]),
                                         "a tile's file added twice");
                            check.That(other.GetTiles(loaded).SequenceEqual(tiles) && other.GetLinks(loaded).Length == linkCount,
                                       "a refused tile changes nothing");
                        }
                    }
                }
                finally
                {
                    Directory.Delete(dir, true);
                }
            });

            check.Run("navmesh on a moving surface", () =>
            {
                using (var world = new World())
                {
                    MeshId raft = TestLevels.AddBox(world, -4, -1, -2, 4, 0, 2, MeshFlags.Movable);
                    var input = new NavmeshInput
                    {
                        Vertices = RaftQuad, Indices = new uint[] {0, 1, 2, 3}, PolygonVertexCounts = new byte[] {4}, Carrier = raft,
                    };
                    NavmeshId navmesh = world.AddNavmesh(input);
                    NavmeshInfo info = world.GetNavmeshInfo(navmesh);
                    check.That(info.Carrier.Equals(raft) && info.PolygonCount == 1, "the navmesh rides the raft: " + info.Carrier);
                    Vec3 onRaft = new Vec3(10, 0.5f, 3), oldPlace = new Vec3(0, 0.5f, 0), box = new Vec3(0.5f, 2, 0.5f);
                    NavPoint[] found = world.FindNearest(navmesh, new[] {oldPlace, onRaft}, box);
                    check.That(found[0].Found == 1 && found[1].Found == 0, "before the move: at the origin");

                    world.SetMeshTransform(raft, RaftMoved);
                    info = world.GetNavmeshInfo(navmesh);
                    check.That(info.Carrier.Equals(raft), "still riding the raft");
                    check.That(info.BoundsMin.X <= 8.4f + 1e-3f && info.BoundsMax.X >= 11.6f - 1e-3f &&
                               info.BoundsMin.Z <= -3.6f + 1e-3f && info.BoundsMax.Z >= 3.6f - 1e-3f,
                               "the bounds hold the moved quad: " + info.BoundsMin + " " + info.BoundsMax);
                    // (10, 3) is on the quad only if it was turned (its z half-width is 1.6 before).
                    found = world.FindNearest(navmesh, new[] {oldPlace, onRaft}, box);
                    check.That(found[0].Found == 0, "nothing left at the old place");
                    check.That(found[1].Found == 1 && Near(found[1].Point, new Vec3(10, 0, 3)),
                               "the navmesh point on the moved raft: " + found[1].Point);

                    // Along the raft: the world's +z to -z is the mesh's -x to +x.
                    PathResult path = world.FindPath(new PathQuery(navmesh, new Vec3(10, 0, 3), new Vec3(10, 0, -3), TestLevels.Walker()));
                    check.That(path.Outcome == PathOutcome.Complete, "a path along the raft: " + path.Outcome);
                    check.Near(path.Info.Length, 6, 1e-4f, "its length");
                    PathPoint first = path.Points[0], last = path.Points[path.Points.Length - 1];
                    check.That(Near(first.Position, new Vec3(10, 0, 3)) && Near(last.Position, new Vec3(10, 0, -3)),
                               "positions in the world: " + first.Position + " " + last.Position);
                    check.That(Near(first.CarrierPosition, new Vec3(-3, 0, 0)) && Near(last.CarrierPosition, new Vec3(3, 0, 0)),
                               "carrier positions in the mesh's space: " + first.CarrierPosition + " " + last.CarrierPosition);

                    // Only rigid moves for a mesh that carries a navmesh, and it cannot go while the navmesh rides it.
                    check.Throws(StatusCode.InvalidArgument, "nl_mesh_set_transform", () => world.SetMeshTransform(raft, RaftScaled),
                                 "a scaling transform");
                    MeshInfo mesh = world.GetMeshInfo(raft);
                    bool unmoved = true;
                    unsafe
                    {
                        for (int k = 0; k < 16; ++k) unmoved &= mesh.Transform[k] == RaftMoved[k];
                    }
                    check.That(unmoved, "a refused move moves nothing");
                    check.Throws(StatusCode.InvalidArgument, "nl_mesh_remove", () => world.RemoveMesh(raft), "removing the raft");

                    // Recast on the raft alone, in its space, riding it; without a carrier a build sees static meshes only.
                    NavmeshId built = world.BuildNavmesh(World.DefaultAgentType(), carrier: raft);
                    check.That(world.GetNavmeshInfo(built).Carrier.Equals(raft), "a navmesh built on the raft rides it");
                    found = world.FindNearest(built, new[] {onRaft, oldPlace}, box);
                    check.That(found[0].Found == 1 && found[1].Found == 0, "the built navmesh is where the raft is");
                    check.Throws(StatusCode.NotFound, "no triangles", () => world.BuildNavmesh(World.DefaultAgentType()),
                                 "a build without a carrier leaves the movable raft out");
                    world.RemoveNavmesh(built);
                    world.RemoveNavmesh(navmesh);
                    world.RemoveMesh(raft);
                    check.That(!world.IsValid(raft), "the raft goes once no navmesh rides it");

                    // A navmesh on no carrier reports the null id, and its path points' CarrierPosition is Position.
                    NavmeshId ground = world.AddNavmesh(new NavmeshInput
                    {
                        Vertices = new float[] {-5, 0, -5, 5, 0, -5, 5, 0, 5, -5, 0, 5}, Indices = new uint[] {0, 2, 1, 0, 3, 2},
                    });
                    check.That(world.GetNavmeshInfo(ground).Carrier.IsNull, "a navmesh on no carrier");
                    PathResult stroll = world.FindPath(new PathQuery(ground, new Vec3(-4, 0, -4), new Vec3(4, 0, 4), TestLevels.Walker()));
                    check.That(stroll.Points.Length >= 2 && stroll.Points.All(q => Same(q.CarrierPosition, q.Position)),
                               "CarrierPosition is Position on a navmesh that rides nothing");
                }
            });

            check.Run("cross link onto a moving surface", () =>
            {
                using (var world = new World())
                {
                    NavmeshId ledge = world.AddNavmesh(Quad(LedgeQuad));
                    MeshId deckBox = TestLevels.AddBox(world, 1, -1, -2, 5, 0, 2, MeshFlags.Movable);
                    NavmeshId deck = world.AddNavmesh(Quad(DeckQuad, deckBox));
                    LinkDef def = World.DefaultLinkDef();
                    check.That(def.LandingNavmesh.IsNull && def.Tolerance == 0.25f,
                               "a link within one navmesh by default, tolerance " + def.Tolerance);
                    def.Start = CrossStart;  // in the world, the box beside the ledge
                    def.End = CrossEnd;
                    def.LandingNavmesh = deck;
                    LinkId cross = world.AddLink(ledge, def);
                    Link link = world.GetLink(cross);
                    check.That(link.Navmesh.Equals(ledge) && link.LandingNavmesh.Equals(deck) && link.Holds == 1 &&
                               link.Bidirectional == 0 && link.Tolerance == 0.25f,
                               "a cross link onto the deck that holds: " + link.LandingNavmesh + " holds " + link.Holds);
                    check.That(link.EndPolygon != Limits.NoPolygon, "the end is on a polygon of the deck");
                    check.That(Near(link.Start, CrossStart) && Near(link.End, CrossEnd),
                               "its ends: " + link.Start + " " + link.End);

                    world.SetMeshTransform(deckBox, DeckAway);
                    link = world.GetLink(cross);
                    check.That(link.Holds == 0, "the box moved 2 m away: past the link's tolerance");
                    check.That(Near(link.Start, CrossStart), "the start stays on the ledge: " + link.Start);
                    check.That(Near(link.End, CrossEndAway), "the end moved with the box: " + link.End);
                    Link[] listed = world.GetLinks(ledge);
                    check.That(listed.Length == 1 && listed[0].Id.Equals(cross) && listed[0].LandingNavmesh.Equals(deck) &&
                               listed[0].Holds == 0 && Near(listed[0].End, CrossEndAway), "the listed link");

                    world.SetMeshTransform(deckBox, DeckHome);
                    link = world.GetLink(cross);
                    check.That(link.Holds == 1, "the box is back");
                    check.That(Near(link.End, CrossEnd), "the end is back: " + link.End);

                    // A link within one navmesh: no landing navmesh, always holds, tolerance 0.
                    LinkDef within = World.DefaultLinkDef();
                    within.Start = new Vec3(-5, 0, 0);
                    within.End = new Vec3(-1, 0, 0);
                    Link plain = world.GetLink(world.AddLink(ledge, within));
                    check.That(plain.LandingNavmesh.IsNull && plain.Holds == 1 && plain.Tolerance == 0,
                               "a link within the ledge");

                    // Cross links are one-way, lead to another live navmesh, and links files do not hold them.
                    LinkDef twoWay = def;
                    twoWay.Bidirectional = 1;
                    check.Throws(StatusCode.InvalidArgument, "bidirectional", () => world.AddLink(ledge, twoWay),
                                 "a two-way cross link");
                    LinkDef ontoItself = def;
                    ontoItself.LandingNavmesh = ledge;
                    check.Throws(StatusCode.InvalidArgument, "landing_navmesh", () => world.AddLink(ledge, ontoItself),
                                 "a cross link onto its own navmesh");
                    NavmeshId gone = world.AddNavmesh(Quad(DeckQuad));
                    world.RemoveNavmesh(gone);
                    LinkDef stale = def;
                    stale.LandingNavmesh = gone;
                    check.Throws(StatusCode.InvalidHandle, "landing_navmesh", () => world.AddLink(ledge, stale),
                                 "a removed landing navmesh");
                    LinkDef negative = def;
                    negative.Tolerance = -1;
                    check.Throws(StatusCode.InvalidArgument, "tolerance", () => world.AddLink(ledge, negative),
                                 "a negative tolerance");
                    check.That(world.GetLinks(ledge).Length == 2, "nothing refused was added");
                    check.Throws(StatusCode.InvalidArgument, "cross link", () => world.SaveLinksJson(ledge),
                                 "saving cross links");
                }
            });

            check.Run("cross links generated for where a platform stands", () =>
            {
                using (var world = new World())
                {
                    TestLevels.AddBox(world, 0, -1, 0, 6, 0, 6);
                    MeshId platform = TestLevels.AddBox(world, -2, -0.5f, -2, 2, 0, 2, MeshFlags.Movable, PlatformAt(9));
                    AgentType agent = World.DefaultAgentType();
                    agent.Radius = 0.3f;
                    NavmeshInput ledgeInput = Quad(LedgeTop), deckInput = Quad(PlatformTop, platform);
                    ledgeInput.AgentType = deckInput.AgentType = agent;
                    NavmeshId ledge = world.AddNavmesh(ledgeInput), deck = world.AddNavmesh(deckInput);
                    LinkSettings settings = World.DefaultLinkSettings();
                    settings.MaxJumpGap = 2.0f;
                    Func<NavmeshId, NavmeshId, Link[]> crossing =
                        (navmesh, landing) => world.GetLinks(navmesh).Where(l => l.LandingNavmesh.Equals(landing)).ToArray();
                    Func<Link[], LinkId[]> ids = links => links.Select(l => l.Id).ToArray();

                    float lastFraction = -1;
                    LinkGenerationReport report = world.GenerateCrossLinks(ledge, deck, 0.25f, settings, (fraction, stage) =>
                    {
                        lastFraction = fraction;
                        return true;
                    });
                    check.That(lastFraction == 1.0f, "progress reported to the end: " + lastFraction);
                    Link[] onto = crossing(ledge, deck), off = crossing(deck, ledge);
                    check.That(report.JumpLinks > 0, report.JumpLinks + " jumps, " + report.DropLinks + " drops");
                    check.That(onto.Length > 0, "links from the ledge onto the platform");
                    check.That(off.Length > 0, "links from the platform onto the ledge");
                    check.That(report.JumpLinks + report.DropLinks == onto.Length + off.Length,
                               "the report counts them: " + onto.Length + " + " + off.Length + " listed");
                    check.That(world.GetLinks(ledge).Length + world.GetLinks(deck).Length == onto.Length + off.Length,
                               "no links within either navmesh");
                    check.That(onto.Concat(off).All(l => l.Generated == 1 && l.Holds == 1 && l.Bidirectional == 0 &&
                                                         l.Tolerance == 0.25f && l.EndPolygon != Limits.NoPolygon),
                               "generated one-way cross links with tolerance 0.25 that hold");
                    // In the world: from the ledge's rim (x 5.7) to the platform's (x 7.3), and back.
                    check.That(onto.All(l => l.Start.X > 5.5f && l.Start.X < 6 && l.End.X > 7 && l.End.X < 7.5f) &&
                               off.All(l => l.Start.X > 7 && l.Start.X < 7.5f && l.End.X > 5.5f && l.End.X < 6),
                               "across the 1 m gap, rim to rim");

                    // 3 m off the ledge: nothing holds; beyond a 2 m jump nothing is found, and the links made 1 m off stay.
                    world.SetMeshTransform(platform, PlatformAt(11));
                    check.That(crossing(ledge, deck).Concat(crossing(deck, ledge)).All(l => l.Holds == 0), "none holds 3 m off");
                    report = world.GenerateCrossLinks(ledge, deck, 0.25f, settings);
                    check.That(report.JumpLinks == 0 && report.DropLinks == 0, "none found 3 m off: " + report.JumpLinks);
                    check.That(ids(crossing(ledge, deck)).SequenceEqual(ids(onto)) && ids(crossing(deck, ledge)).SequenceEqual(ids(off)),
                               "the links made 1 m off are kept for when it is back");

                    // Back 1 m off: they hold again, and generating there again replaces them (not doubled).
                    world.SetMeshTransform(platform, PlatformAt(9));
                    check.That(crossing(ledge, deck).Concat(crossing(deck, ledge)).All(l => l.Holds == 1), "they hold again");
                    world.GenerateCrossLinks(ledge, deck, 0.25f, settings);
                    check.That(crossing(ledge, deck).Length == onto.Length && crossing(deck, ledge).Length == off.Length,
                               "generated again at the same stop: replaced, not doubled");

                    // Refused: the same navmesh twice, a bad tolerance, another body, a stale navmesh; a cancel changes nothing.
                    check.Throws(StatusCode.InvalidArgument, "nl_navmesh_generate_cross_links",
                                 () => world.GenerateCrossLinks(ledge, ledge, 0.25f, settings), "the same navmesh twice");
                    check.Throws(StatusCode.InvalidArgument, "tolerance", () => world.GenerateCrossLinks(ledge, deck, -1, settings),
                                 "a negative tolerance");
                    NavmeshId wide = world.AddNavmesh(Quad(PlatformTop));  // the default radius, 0.6
                    check.Throws(StatusCode.InvalidArgument, "bodies", () => world.GenerateCrossLinks(ledge, wide, 0.25f, settings),
                                 "navmeshes for different bodies");
                    world.RemoveNavmesh(wide);
                    check.Throws(StatusCode.InvalidHandle, "second", () => world.GenerateCrossLinks(ledge, wide, 0.25f, settings),
                                 "a removed navmesh");
                    LinkId[] before = ids(world.GetLinks(ledge));
                    check.Throws(StatusCode.Cancelled, "", () => world.GenerateCrossLinks(ledge, deck, 0.25f, settings, (f, s) => false),
                                 "a cancelled generation");
                    check.That(ids(world.GetLinks(ledge)).SequenceEqual(before), "a cancelled generation changes nothing");
                }
            });
        }
    }
}
