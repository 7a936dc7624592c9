namespace NavLink
{
    /// <summary>A navmesh from the host's engine (nl_navmesh_def), as managed arrays. Null arrays are the
    /// header's NULL: every polygon a triangle, area 0, no detail mesh.</summary>
    public sealed class NavmeshInput
    {
        /// <summary>x y z per vertex, world space (or the Carrier mesh's own space).</summary>
        public float[] Vertices;
        /// <summary>Polygon corners, polygon after polygon.</summary>
        public uint[] Indices;
        /// <summary>Corners of each polygon (3..16); null: triangles.</summary>
        public byte[] PolygonVertexCounts;
        public byte[] Areas;
        public float WeldTolerance = 0.001f;
        public AgentType AgentType;
        public float[] DetailVertices;
        public uint[] DetailTriangles;
        public uint[] DetailTriangleStarts;
        /// <summary>The navmesh's carrier: a movable mesh (MeshFlags.Movable) it rides, or the null id (default):
        /// with one, the coordinates are in that mesh's own space and World.SetMeshTransform moves the navmesh
        /// with it.</summary>
        public MeshId Carrier;
        /// <summary>Metres; 0 (default): not a tile. Above 0 the polygons are the tile (TileX, TileZ) of a grid
        /// of squares this wide on the x-z plane whose tile (0, 0) has its lower corner at (TileOriginX,
        /// TileOriginZ): it spans x in [TileOriginX + TileX * TileWidth, + TileWidth] and z alike (World.AddTile;
        /// a navmesh's grid is NavmeshInfo.TileWidth and TileOrigin).</summary>
        public float TileWidth;
        /// <summary>x of tile (0, 0)'s lower corner.</summary>
        public float TileOriginX;
        /// <summary>z of tile (0, 0)'s lower corner.</summary>
        public float TileOriginZ;
        /// <summary>The tile's column.</summary>
        public int TileX;
        /// <summary>The tile's row.</summary>
        public int TileZ;

        public NavmeshInput()
        {
            LibraryCheck.EnsureLoaded();
            AgentType = Native.nl_default_agent_type();
        }
    }
}
