using System;
using System.IO;
using NavLink;

namespace NavLink.Tests
{
    // Procedural levels with exact answers, built from boxes (as the C API tests do).
    internal static class TestLevels
    {
        private static readonly uint[] BoxIndices = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                                                     2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};

        /// <summary>A box from (x0, y0, z0) to (x1, y1, z1): corner k takes x from bit 0, y from bit 1, z from bit 2;
        /// transform: column-major 4x4 (null: identity); metresPerUnit and upAxis as World.AddMesh takes them.</summary>
        public static MeshId AddBox(World world, float x0, float y0, float z0, float x1, float y1, float z1, MeshFlags flags = MeshFlags.None,
                                    float[] transform = null, float metresPerUnit = 0, UpAxis upAxis = UpAxis.NotSaid)
        {
            var v = new float[24];
            for (int k = 0; k < 8; ++k)
            {
                v[3 * k] = (k & 1) != 0 ? x1 : x0;
                v[3 * k + 1] = (k & 2) != 0 ? y1 : y0;
                v[3 * k + 2] = (k & 4) != 0 ? z1 : z0;
            }
            return world.AddMesh(v, BoxIndices, flags, transform, metresPerUnit: metresPerUnit, upAxis: upAxis);
        }

        /// <summary>
        /// "gap": two 10 x 10 m platforms (top y = 0, 1 m thick), x in [-11, -1] and [1, 11], z in [-5, 5],
        /// 2 m apart over a pit whose floor (y = -20) is beyond any drop. Recast's navmesh stops 0.6-0.9 m
        /// short of each rim, so a jump across is 3.2-3.8 m: only an agent that jumps gets across.
        /// </summary>
        public static void AddGapLevel(World world)
        {
            AddBox(world, -11, -1, -5, -1, 0, 5);
            AddBox(world, 1, -1, -5, 11, 0, 5);
            AddBox(world, -12, -21, -6, 12, -20, 6);
        }

        /// <summary>
        /// The gap level with Recast's navmesh for the default body, its generated links and one manual
        /// link across the gap (from (-5, 0, 4) to (5, 0, 4)): a navmesh with links of both kinds.
        /// </summary>
        public static NavmeshId AddGapNavmeshWithLinks(World world)
        {
            AddGapLevel(world);
            NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType());
            world.GenerateLinks(navmesh);
            LinkDef manual = World.DefaultLinkDef();
            manual.Start = new Vec3(-5, 0, 4);
            manual.End = new Vec3(5, 0, 4);
            world.AddLink(navmesh, manual);
            return navmesh;
        }

        /// <summary>
        /// "bridge" (tests/abi/agents_tests.c's level): two 4 x 10 m platforms (tops at y = 0) 2 m apart along x,
        /// x in [0, 4] and [6, 10], z in [0, 10], joined by a bridge at z 8-10; the host's navmesh is their
        /// tops set in 0.3 m from every rim (five convex polygons, for radius 0.3), its links generated. A
        /// walker goes round by the bridge; a jumper jumps the gap.
        /// </summary>
        public static NavmeshId AddBridgeLevel(World world)
        {
            AddBox(world, 0, -1, 0, 4, 0, 10);
            AddBox(world, 6, -1, 0, 10, 0, 10);
            AddBox(world, 4, -1, 8, 6, 0, 10);
            float[][] polygons =
            {
                new[] {0.3f, 0.3f, 0.3f, 8, 3.7f, 8, 3.7f, 0.3f},
                new[] {0.3f, 8, 0.3f, 9.7f, 4, 9.7f, 4, 8, 3.7f, 8},
                new[] {4f, 8, 4, 9.7f, 6, 9.7f, 6, 8},
                new[] {6f, 8, 6, 9.7f, 9.7f, 9.7f, 9.7f, 8, 6.3f, 8},
                new[] {6.3f, 0.3f, 6.3f, 8, 9.7f, 8, 9.7f, 0.3f},
            };
            var vertices = new System.Collections.Generic.List<float>();
            var input = new NavmeshInput { PolygonVertexCounts = new byte[polygons.Length] };
            for (int p = 0; p < polygons.Length; ++p)
            {
                input.PolygonVertexCounts[p] = (byte)(polygons[p].Length / 2);
                for (int k = 0; k < polygons[p].Length; k += 2) vertices.AddRange(new[] {polygons[p][k], 0, polygons[p][k + 1]});
            }
            input.Vertices = vertices.ToArray();
            input.Indices = new uint[input.Vertices.Length / 3];
            for (uint i = 0; i < input.Indices.Length; ++i) input.Indices[i] = i;
            input.AgentType.Radius = 0.3f;
            NavmeshId navmesh = world.AddNavmesh(input);
            world.GenerateLinks(navmesh);
            return navmesh;
        }

        public static readonly Vec3 WestPoint = new Vec3(-6, 0, 0);
        public static readonly Vec3 EastPoint = new Vec3(6, 0, 0);

        /// <summary>The default body: no jumps, no drops.</summary>
        public static AgentCapabilities Walker() { return World.DefaultAgentCapabilities(); }

        /// <summary>Jumps 4.5 m across and 1.5 m up, drops 5 m.</summary>
        public static AgentCapabilities Jumper()
        {
            AgentCapabilities c = World.DefaultAgentCapabilities();
            c.MaxJumpDistance = 4.5f;
            c.MaxJumpHeight = 1.5f;
            c.MaxDropHeight = 5f;
            return c;
        }

        /// <summary>The triangles an OBJ file's faces make when fan-triangulated, counted independently of
        /// the library (a face of n corners is n - 2 triangles).</summary>
        public static int CountObjTriangles(string path)
        {
            int triangles = 0;
            foreach (string line in File.ReadLines(path))
            {
                string[] parts = line.Split((char[])null, StringSplitOptions.RemoveEmptyEntries);
                if (parts.Length > 0 && parts[0] == "f") triangles += parts.Length - 3;
            }
            return triangles;
        }
    }
}
