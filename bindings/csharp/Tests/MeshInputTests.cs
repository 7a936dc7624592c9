using System;
using System.Collections.Generic;
using System.Linq;
using NavLink;

namespace NavLink.Tests
{
    // What a navmesh build takes from the level (tests/abi/navmesh_build_tests.c's winding, mesh_roles,
    // mesh_areas and build_progress, with their geometry): the winding of a mesh's triangles, obstacles and
    // meshes left out of builds, each mesh's area in the polygons built over it, a mesh's units; and a
    // build's progress and cancel.
    internal static class MeshInputTests
    {
        // A horizontal quad's corners, x in [x0, x1], z in [z0, z1] at height y; FrontUp is counter-clockwise
        // seen from above (its front faces up), FrontDown the same triangles wound the other way.
        private static readonly uint[] FrontUp = {0, 1, 2, 0, 2, 3}, FrontDown = {0, 2, 1, 0, 3, 2};

        private static MeshId AddQuad(World world, float x0, float z0, float x1, float z1, float y, uint[] winding,
                                      MeshFlags flags = MeshFlags.None, uint area = 0)
        {
            float[] corners = {x0, y, z0, x0, y, z1, x1, y, z1, x1, y, z0};
            return world.AddMesh(corners, winding, flags, area: area);
        }

        /// <summary>The polygon within (0.4, 0.3, 0.4) of the point, or null.</summary>
        private static NavPolygon? PolygonAt(World world, NavmeshId navmesh, float x, float y, float z)
        {
            NavPoint hit = world.FindNearest(navmesh, new[] {new Vec3(x, y, z)}, new Vec3(0.4f, 0.3f, 0.4f))[0];
            if (hit.Found == 0) return null;
            return world.GetPolygon(navmesh, hit.Polygon);
        }

        private static bool WalkableAt(World world, NavmeshId navmesh, float x, float y, float z)
        {
            return PolygonAt(world, navmesh, x, y, z).HasValue;
        }

        // Scaled in floats: 500 x 0.01 is 5 to within rounding.
        private static bool Near(Vec3 a, Vec3 b)
        {
            return Math.Abs(a.X - b.X) < 1e-4f && Math.Abs(a.Y - b.Y) < 1e-4f && Math.Abs(a.Z - b.Z) < 1e-4f;
        }

        public static void Run(Checks check)
        {
            check.Run("mesh winding: NL_MESH_CLOCKWISE", () =>
            {
                using (var world = new World())
                {
                    // Wound clockwise (fronts down): nothing to walk on, and the message names the flag to set.
                    MeshId floor = AddQuad(world, -10, -10, 10, 10, 0, FrontDown);
                    check.Throws(StatusCode.NotFound, "NL_MESH_CLOCKWISE", () => world.BuildNavmesh(World.DefaultAgentType()),
                                 "a floor wound clockwise, unflagged");
                    world.RemoveMesh(floor);
                    floor = AddQuad(world, -10, -10, 10, 10, 0, FrontDown, MeshFlags.Clockwise);
                    check.That(world.GetMeshInfo(floor).Flags == MeshFlags.Clockwise, "the mesh keeps its Clockwise flag");
                    NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType());
                    check.That(WalkableAt(world, navmesh, 0, 0, 0), "the same floor flagged Clockwise is walked on");
                }
            });

            check.Run("mesh roles: obstacles and meshes left out of navmesh builds", () =>
            {
                using (var world = new World())
                {
                    AddQuad(world, -10, -10, 10, 10, 0, FrontUp);
                    // A 4 x 4 x 1 m crate, x and z in [3, 7]: its top is walkable as any floor, unless it is an obstacle.
                    MeshId crate = TestLevels.AddBox(world, 3, 0, 3, 7, 1, 7);
                    check.That(WalkableAt(world, world.BuildNavmesh(World.DefaultAgentType()), 5, 1, 5), "an ordinary crate's top is walkable");
                    world.RemoveMesh(crate);
                    crate = TestLevels.AddBox(world, 3, 0, 3, 7, 1, 7, MeshFlags.Obstacle);
                    check.That(world.GetMeshInfo(crate).Flags == MeshFlags.Obstacle, "the crate keeps its Obstacle flag");
                    NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType());
                    check.That(!WalkableAt(world, navmesh, 5, 1, 5), "an obstacle crate's top is not walked on");
                    check.That(!WalkableAt(world, navmesh, 5, 0, 5), "the floor under the obstacle is blocked");
                    check.That(WalkableAt(world, navmesh, -5, 0, 5), "the floor beside it is walkable");

                    // A slab 1 m over the floor leaves no headroom; left out of builds it leaves the floor, and rays meet it.
                    MeshId slab = AddQuad(world, -8, -8, -2, -2, 1, FrontDown);
                    check.That(!WalkableAt(world, world.BuildNavmesh(World.DefaultAgentType()), -5, 0, -5), "no headroom under the slab");
                    world.RemoveMesh(slab);
                    slab = AddQuad(world, -8, -8, -2, -2, 1, FrontDown, MeshFlags.NotInNavmesh);
                    check.That(WalkableAt(world, world.BuildNavmesh(World.DefaultAgentType()), -5, 0, -5),
                               "a slab left out of builds leaves the floor walkable");
                    RayHit hit = world.CastRays(new[] {new Ray(new Vec3(-5, 5, -5), new Vec3(0, -1, 0), 10)})[0];
                    check.That(hit.Hit == 1 && hit.Mesh.Equals(slab) && Math.Abs(hit.Point.Y - 1) < 1e-4f,
                               "a ray down onto the left-out slab hits it: " + hit.Hit + " at " + hit.Point);
                    check.Throws(StatusCode.InvalidArgument, "", () => AddQuad(world, 0, 0, 1, 1, 0, FrontUp, MeshFlags.Obstacle | MeshFlags.NotInNavmesh),
                                 "Obstacle together with NotInNavmesh");
                }
            });

            check.Run("mesh areas in the built polygons", () =>
            {
                using (var world = new World())
                {
                    AddQuad(world, -10, -10, 0, 10, 0, FrontUp);
                    MeshId east = AddQuad(world, 0, -10, 10, 10, 0, FrontUp, area: 5);
                    check.That(world.GetMeshInfo(east).Area == 5, "the mesh info reports area " + world.GetMeshInfo(east).Area);
                    NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType());
                    NavPolygon? eastPolygon = PolygonAt(world, navmesh, 5, 0, 0), westPolygon = PolygonAt(world, navmesh, -5, 0, 0);
                    check.That(eastPolygon.HasValue && eastPolygon.Value.Area == 5,
                               "the polygon over the east mesh has its area 5: " + (eastPolygon.HasValue ? eastPolygon.Value.Area.ToString() : "none"));
                    check.That(westPolygon.HasValue && westPolygon.Value.Area == 0, "the polygon over the west mesh has area 0");
                    check.Throws(StatusCode.InvalidArgument, "", () => AddQuad(world, 0, 0, 1, 1, 0, FrontUp, area: Limits.MeshMaxArea + 1),
                                 "an area above MeshMaxArea");
                }
            });

            check.Run("mesh units: a level in centimetres registered in metres", () =>
            {
                var warnings = new List<string>();
                var options = new WorldOptions { Log = (level, status, message) => { if (level == LogLevel.Warning) lock (warnings) warnings.Add(message); } };
                using (var world = new World(options))
                {
                    // The 10 x 10 m box, 1 m thick, as an exporter in centimetres writes it.
                    MeshId box = TestLevels.AddBox(world, -500, -100, -500, 500, 0, 500, metresPerUnit: 0.01f, upAxis: UpAxis.Y);
                    MeshInfo info = world.GetMeshInfo(box);
                    check.That(info.MetresPerUnit == 0.01f && info.UpAxis == UpAxis.Y, "the mesh info reports its frame: " +
                               info.MetresPerUnit + " m per unit, " + info.UpAxis + " up");
                    check.That(Near(info.BoundsMin, new Vec3(-5, -1, -5)) && Near(info.BoundsMax, new Vec3(5, 0, 5)),
                               "the bounds in metres: " + info.BoundsMin + " " + info.BoundsMax);
                    BuildWarnings said = world.GetNavmeshInfo(world.BuildNavmesh(World.DefaultAgentType())).BuildWarnings;
                    check.That(said == BuildWarnings.None, "a level that said its frame builds without warnings: " + said);
                    world.RemoveMesh(box);
                    // Not said, its walls are 100 m tall for a body of 2 m. Coarse cells: read as metres it is 1 km wide.
                    TestLevels.AddBox(world, -500, -100, -500, 500, 0, 500);
                    NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType(), settingsJson: "{\"cell_size\": 2.0, \"cell_height\": 0.5}");
                    BuildWarnings unsaid = world.GetNavmeshInfo(navmesh).BuildWarnings;
                    check.That(unsaid == BuildWarnings.Units, "a level in centimetres read as metres is warned of: " + unsaid);
                    lock (warnings)
                        check.That(warnings.Any(m => m.Contains("metres_per_unit")), "the log's warning names the option: " + string.Join("\n", warnings));
                }
            });

            check.Run("navmesh build progress and cancel", () =>
            {
                using (var world = new World())
                {
                    TestLevels.AddBox(world, -10, 0, -10, 10, 1, 10);
                    var fractions = new List<float>();
                    var stages = new HashSet<string>();
                    world.BuildNavmesh(World.DefaultAgentType(), progress: (fraction, stage) =>
                    {
                        fractions.Add(fraction);
                        stages.Add(stage);
                        return true;
                    });
                    check.That(fractions.Count >= 2, fractions.Count + " progress calls");
                    check.That(fractions.Zip(fractions.Skip(1), (a, b) => b >= a).All(ordered => ordered),
                               "progress never goes back: " + string.Join(" ", fractions));
                    check.That(fractions.FirstOrDefault() == 0 && fractions.LastOrDefault() == 1,
                               "progress runs from 0 to 1: " + fractions.FirstOrDefault() + " to " + fractions.LastOrDefault());
                    check.That(stages.Contains("rasterising the level"), "the stages name rasterising: " + string.Join(", ", stages));

                    int callsAfterCancel = 0;
                    bool cancelled = false;
                    check.Throws(StatusCode.Cancelled, "cancelled", () => world.BuildNavmesh(World.DefaultAgentType(), progress: (fraction, stage) =>
                    {
                        if (cancelled)
                        {
                            ++callsAfterCancel;
                            return false;
                        }
                        cancelled = stage == "rasterising the level";
                        return !cancelled;
                    }), "a build cancelled from progress");
                    check.That(cancelled && callsAfterCancel == 0, "the build stopped at its cancel (" + callsAfterCancel + " calls after)");
                    check.That(world.GetNavmeshes().Length == 1, "a cancelled build adds no navmesh: " + world.GetNavmeshes().Length);

                    check.Throws(StatusCode.Cancelled, "the progress callback threw", () => world.BuildNavmesh(World.DefaultAgentType(),
                                 progress: (fraction, stage) => { throw new InvalidOperationException("stop"); }),
                                 "an exception thrown by progress cancels the build");
                    check.That(world.GetNavmeshes().Length == 1, "nor does a build whose progress threw");
                }
            });
        }
    }
}
