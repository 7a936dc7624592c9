using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public sealed partial class World
    {
        /// <summary>Recast's usual agent: radius 0.6, height 2, climb 0.9, slope 45.</summary>
        public static AgentType DefaultAgentType() { LibraryCheck.EnsureLoaded(); return Native.nl_default_agent_type(); }

        public static RecastSettings DefaultRecastSettings() { LibraryCheck.EnsureLoaded(); return Native.nl_default_recast_settings(); }

        /// <summary>Builds a navmesh with a builder plugin ("recast" when builder is null) from every static
        /// mesh, or, with a carrier (a MeshFlags.Movable mesh), from that mesh alone in its own space: the
        /// navmesh then rides it. recast: the Recast builder's settings; settingsJson is applied over them.
        /// Meshes flagged NotInNavmesh are left out, Obstacle ones only block, and each mesh's area goes to the
        /// polygons over it. A level that looks wound clockwise, given in other units than metres or with z up
        /// (where its meshes did not say: AddMesh's metresPerUnit and upAxis) still builds: the log says why in
        /// a warning and NavmeshInfo.BuildWarnings has a bit for each. progress is told of the build on this
        /// thread (fractions 0 to 1); returning false cancels it (NavLinkException with Cancelled, nothing
        /// added); an exception thrown by progress cancels the build and is rethrown here.</summary>
        public unsafe NavmeshId BuildNavmesh(AgentType agentType, RecastSettings? recast = null, string settingsJson = null,
                                             string builder = null, MeshId carrier = default(MeshId),
                                             ProgressHandler progress = null)
        {
            NavmeshId id = default(NavmeshId);
            WithBuildDef(agentType, recast, settingsJson, builder, carrier, progress, (world, def) =>
            {
                NavmeshId built;
                StatusCode status = Native.nl_navmesh_build(world, def, &built);
                id = built;
                return status;
            });
            return id;
        }

        /// <summary>Builds again, from the level as it is now, the tiles of a tiled navmesh's grid whose squares
        /// overlap the box [boxMin, boxMax] seen from above (y is not read), with a builder plugin ("recast" when
        /// builder is null) and its settings as BuildNavmesh takes them: they must make tiles of the navmesh's
        /// width (the same TileSize and CellSize it was built with), and agentType must be the navmesh's. In one
        /// step a tile loaded there is replaced, one that comes out with no walkable surface is removed, the
        /// others are added. NavLinkException with InvalidArgument for a navmesh that is not tiled, a box not
        /// finite or with min &gt; max (or of more than 2^22 tiles), another agent type, settings making another
        /// tile width, or no tile left; the builder's failures; Cancelled from progress (as BuildNavmesh's);
        /// nothing changed on a failure.</summary>
        public unsafe void BuildTiles(NavmeshId navmesh, AgentType agentType, Vec3 boxMin, Vec3 boxMax,
                                      RecastSettings? recast = null, string settingsJson = null, string builder = null,
                                      ProgressHandler progress = null)
        {
            Vec3 lo = boxMin, hi = boxMax;  // not captured: they stay put on the stack
            float* min = (float*)&lo, max = (float*)&hi;
            WithBuildDef(agentType, recast, settingsJson, builder, default(MeshId), progress,
                         (world, def) => Native.nl_navmesh_build_tiles(world, navmesh, def, min, max));
        }

        private unsafe delegate StatusCode NavmeshBuildDefCall(IntPtr world, NavmeshBuildDef* def);

        // Lays the build out as an nl_navmesh_build_def over its pinned strings and makes the call with it, in the
        // world, with progress's scope (BuildNavmesh, BuildTiles).
        private unsafe void WithBuildDef(AgentType agentType, RecastSettings? recast, string settingsJson, string builder,
                                         MeshId carrier, ProgressHandler progress, NavmeshBuildDefCall call)
        {
            NavmeshBuildDef def = Native.nl_default_navmesh_build_def();
            RecastSettings settings = recast ?? default(RecastSettings);
            byte[] json = settingsJson == null ? null : System.Text.Encoding.UTF8.GetBytes(settingsJson);
            byte[] name = Utf8.EncodeZ(builder);
            fixed (byte* j = json)
            fixed (byte* n = name)
            using (var scope = new ProgressScope(progress))
            using (var w = Enter())
            {
                def.AgentType = agentType;
                def.Builder = (IntPtr)n;
                def.Settings = recast.HasValue ? (IntPtr)(&settings) : IntPtr.Zero;
                // A non-null pointer for "", which is not a JSON object: let the library say so.
                byte empty = 0;
                def.SettingsJson = json == null ? IntPtr.Zero : json.Length == 0 ? (IntPtr)(&empty) : (IntPtr)j;
                def.SettingsJsonLength = (UIntPtr)(json == null ? 0 : json.Length);
                def.Carrier = carrier;
                def.Progress = scope.Function;
                def.ProgressUser = scope.User;
                scope.Check(call(w.Pointer, &def));
            }
        }

        /// <summary>Adds the host's navmesh (copied and repaired as nl_navmesh_add says). With input.TileWidth
        /// &gt; 0 the polygons are one tile of a grid: the navmesh is then tiled, of that one tile, and AddTile
        /// grows it.</summary>
        public unsafe NavmeshId AddNavmesh(NavmeshInput input)
        {
            NavmeshId id = default(NavmeshId);
            WithNavmeshDef(input, "input", (world, def) =>
            {
                NavmeshId added;
                StatusCode status = Native.nl_navmesh_add(world, def, &added);
                id = added;
                return status;
            });
            return id;
        }

        private unsafe delegate StatusCode NavmeshDefCall(IntPtr world, NavmeshDef* def);

        // Lays `input` out as an nl_navmesh_def over its pinned arrays and makes the call with it, in the world.
        private unsafe void WithNavmeshDef(NavmeshInput input, string name, NavmeshDefCall call)
        {
            if (input == null) throw new ArgumentNullException(name);
            NavmeshDef def = Native.nl_default_navmesh_def();
            fixed (float* v = input.Vertices)
            fixed (uint* i = input.Indices)
            fixed (byte* c = input.PolygonVertexCounts)
            fixed (byte* a = input.Areas)
            fixed (float* dv = input.DetailVertices)
            fixed (uint* dt = input.DetailTriangles)
            fixed (uint* ds = input.DetailTriangleStarts)
            using (var w = Enter())
            {
                def.Vertices = (IntPtr)v;
                def.VertexCount = (uint)(input.Vertices == null ? 0 : input.Vertices.Length / 3);
                def.Indices = (IntPtr)i;
                def.PolygonVertexCounts = (IntPtr)c;
                def.PolygonCount = (uint)(input.PolygonVertexCounts != null ? input.PolygonVertexCounts.Length
                                          : input.Indices == null ? 0 : input.Indices.Length / 3);
                def.Areas = (IntPtr)a;
                def.WeldTolerance = input.WeldTolerance;
                def.AgentType = input.AgentType;
                def.DetailVertices = (IntPtr)dv;
                def.DetailVertexCount = (uint)(input.DetailVertices == null ? 0 : input.DetailVertices.Length / 3);
                def.DetailTriangles = (IntPtr)dt;
                def.DetailTriangleCount = (uint)(input.DetailTriangles == null ? 0 : input.DetailTriangles.Length / 3);
                def.DetailTriangleStarts = (IntPtr)ds;
                def.Carrier = input.Carrier;
                def.TileWidth = input.TileWidth;
                def.TileOriginX = input.TileOriginX;
                def.TileOriginZ = input.TileOriginZ;
                def.TileX = input.TileX;
                def.TileZ = input.TileZ;
                Status.Check(call(w.Pointer, &def));
            }
        }

        public void RemoveNavmesh(NavmeshId navmesh)
        {
            using (var w = Enter()) Status.Check(Native.nl_navmesh_remove(w.Pointer, navmesh));
        }

        public bool IsValid(NavmeshId navmesh)
        {
            using (var w = Enter()) return Native.nl_navmesh_is_valid(w.Pointer, navmesh) != 0;
        }

        public unsafe NavmeshInfo GetNavmeshInfo(NavmeshId navmesh)
        {
            NavmeshInfo info = Native.nl_navmesh_info_init();
            using (var w = Enter()) Status.Check(Native.nl_navmesh_get_info(w.Pointer, navmesh, &info));
            return info;
        }

        /// <summary>The navmesh's vertices after welding.</summary>
        public unsafe Vec3[] GetNavmeshVertices(NavmeshId navmesh)
        {
            using (var w = Enter())
            {
                IntPtr world = w.Pointer;
                return ListTwoCall<Vec3>((buffer, capacity, count) =>
                    Native.nl_navmesh_get_vertices(world, navmesh, (float*)buffer, capacity, count));
            }
        }

        public unsafe NavPolygon GetPolygon(NavmeshId navmesh, uint polygon)
        {
            NavPolygon result = Native.nl_nav_polygon_init();
            using (var w = Enter()) Status.Check(Native.nl_navmesh_get_polygon(w.Pointer, navmesh, polygon, &result));
            return result;
        }

        public unsafe BoundaryEdge[] GetBoundaryEdges(NavmeshId navmesh)
        {
            using (var w = Enter())
            {
                IntPtr world = w.Pointer;
                return ListTwoCall<BoundaryEdge>((buffer, capacity, count) =>
                    Native.nl_navmesh_get_boundary_edges(world, navmesh, (BoundaryEdge*)buffer, capacity, count));
            }
        }

        /// <summary>Adds the host's polygons as a tile of a tiled navmesh (one built with RecastSettings.TileSize,
        /// or added from a tile): tile.TileWidth, TileOriginX and TileOriginZ must be the navmesh's grid
        /// (NavmeshInfo.TileWidth, TileOrigin), tile.AgentType its agent type, and no tile loaded at (TileX,
        /// TileZ); the navmesh is joined again with it. NavLinkException with InvalidArgument otherwise (also for
        /// a navmesh that is not tiled, and for a Carrier that is not the navmesh's), nothing changed. A tile's
        /// file (SaveTile) is added with AddTileBytes or AddTileFile.</summary>
        public unsafe void AddTile(NavmeshId navmesh, NavmeshInput tile)
        {
            WithNavmeshDef(tile, "tile", (world, def) => Native.nl_navmesh_add_tile(world, navmesh, def));
        }

        /// <summary>Removes the tile at that place from a tiled navmesh. NavLinkException with NotFound when no tile
        /// is loaded there (removed twice), InvalidArgument for a navmesh that is not tiled or its last tile
        /// (remove the navmesh instead); nothing changed.</summary>
        public void RemoveTile(NavmeshId navmesh, TileCoord tile)
        {
            using (var w = Enter()) Status.Check(Native.nl_navmesh_remove_tile(w.Pointer, navmesh, tile));
        }

        /// <summary>The loaded tiles' places in row order (z, then x); none for a navmesh that is not tiled.</summary>
        public unsafe TileCoord[] GetTiles(NavmeshId navmesh)
        {
            using (var w = Enter())
            {
                IntPtr world = w.Pointer;
                return ListTwoCall<TileCoord>((buffer, capacity, count) =>
                    Native.nl_navmesh_get_tiles(world, navmesh, (TileCoord*)buffer, capacity, count));
            }
        }

        /// <summary>The navmesh point nearest each query point within the box point +- halfExtents.</summary>
        public unsafe void FindNearest(NavmeshId navmesh, ReadOnlySpan<Vec3> points, Vec3 halfExtents, Span<NavPoint> found)
        {
            if (found.Length < points.Length) throw new ArgumentException("one result per point", "found");
            fixed (Vec3* p = &MemoryMarshal.GetReference(points))
            fixed (NavPoint* f = &MemoryMarshal.GetReference(found))
            using (var w = Enter())
                Status.Check(Native.nl_navmesh_find_nearest(w.Pointer, navmesh, (float*)p, (uint)points.Length,
                                                            (float*)&halfExtents, f));
        }

        public NavPoint[] FindNearest(NavmeshId navmesh, Vec3[] points, Vec3 halfExtents)
        {
            var found = new NavPoint[points.Length];
            FindNearest(navmesh, points, halfExtents, found);
            return found;
        }

        public unsafe NavmeshId[] GetNavmeshes()
        {
            using (var w = Enter())
            {
                IntPtr world = w.Pointer;
                return ListTwoCall<NavmeshId>((buffer, capacity, count) =>
                    Native.nl_world_get_navmeshes(world, (NavmeshId*)buffer, capacity, count));
            }
        }
    }
}
