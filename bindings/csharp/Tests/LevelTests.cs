using System;
using System.IO;
using NavLink;

namespace NavLink.Tests
{
    // The world, level geometry, ray and segment queries, OBJ loading.
    internal static class LevelTests
    {
        private static readonly float[] Floor = {-5, 0, -5, 5, 0, -5, 5, 0, 5, -5, 0, 5};
        private static readonly uint[] Quad = {0, 2, 1, 0, 3, 2};

        public static void Run(Checks check, string levelsDir)
        {
            check.Run("version and statuses", () =>
            {
                NavLinkVersion v = World.LibraryVersion;
                check.That(v.Major == HeaderVersion.Major && v.Minor == HeaderVersion.Minor && v.Patch == HeaderVersion.Patch,
                           "library version " + v + " is the header version the binding was written from");
                check.That(Status.Describe(StatusCode.Failure | StatusCode.InvalidHandle).Contains("invalid handle"),
                           "nl_status_string names the detail: " + Status.Describe(StatusCode.Failure | StatusCode.InvalidHandle));
            });

            check.Run("world options", () =>
            {
                using (var one = new World(new WorldOptions { WorkerCount = 1, PathWorkerCount = 0 }))
                    check.That(one.WorkerCount == 1, "worker_count 1: " + one.WorkerCount);
                check.Throws(StatusCode.InvalidArgument, "worker_count", () => new World(new WorldOptions { WorkerCount = -5 }),
                             "worker_count -5");
                var world = new World();
                world.Dispose();
                check.That(world.IsDisposed, "disposed");
                try
                {
                    world.GetMeshes();
                    check.That(false, "a disposed world throws ObjectDisposedException");
                }
                catch (ObjectDisposedException)
                {
                    check.That(true, "");
                }
            });

            check.Run("meshes and rays", () =>
            {
                using (var world = new World())
                {
                    MeshId floor = world.AddMesh(Floor, Quad, 0, default(ReadOnlySpan<float>), 42);
                    check.That(!floor.IsNull && world.IsValid(floor), "the floor is registered: " + floor);
                    MeshInfo info = world.GetMeshInfo(floor);
                    check.That(info.TriangleCount == 2 && info.VertexCount == 4 && info.UserData == 42,
                               "mesh info: " + info.TriangleCount + " triangles, user data " + info.UserData);
                    check.Near(info.BoundsMax.X, 5, 0, "bounds max x");

                    var rays = new[]
                    {
                        new Ray(new Vec3(-2, 2, 1), new Vec3(0, -1, 0), 100),
                        new Ray(new Vec3(8, 2, 0), new Vec3(0, -1, 0), 100),  // beside the floor
                    };
                    RayHit[] hits = world.CastRays(rays);
                    check.That(hits[0].Hit == 1 && hits[0].Mesh.Equals(floor), "ray 0 hits the floor");
                    check.Near(hits[0].Distance, 2, 1e-5f, "ray 0 distance");
                    check.Near(hits[0].Normal.Y, 1, 1e-5f, "ray 0 normal y");
                    check.That(hits[1].Hit == 0 && hits[1].Distance == 0, "ray 1 misses, fields zero");

                    // A movable 2 x 2 m tile 1 m up at x = 4, then lifted to 3.5 m.
                    float[] at = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 4, 1, 0, 1};
                    float[] tile = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
                    MeshId lift = world.AddMesh(tile, Quad, MeshFlags.Movable, at);
                    var down = new[] { new Ray(new Vec3(4, 50, 0), new Vec3(0, -1, 0), 100) };
                    check.Near(world.CastRays(down)[0].Point.Y, 1, 1e-4f, "the lift at 1 m");
                    at[13] = 3.5f;
                    world.SetMeshTransform(lift, at);
                    check.Near(world.CastRays(down)[0].Point.Y, 3.5f, 1e-4f, "the lift moved to 3.5 m");
                    check.That(world.GetMeshes().Length == 2, "two meshes listed");

                    // Segments: through the lift, and beside it.
                    bool[] blocked = world.SegmentsBlocked(new[]
                    {
                        new Segment(new Vec3(4, 5, 0), new Vec3(4, 2, 0)),
                        new Segment(new Vec3(-4, 5, 0), new Vec3(-4, 2, 0)),
                    });
                    check.That(blocked[0] && !blocked[1], "segments: through the lift blocked, beside it clear");

                    // Stale ids are refused, never obeyed.
                    world.RemoveMesh(lift);
                    check.That(!world.IsValid(lift), "a removed mesh is not valid");
                    check.Throws(StatusCode.InvalidHandle, "nl_mesh_remove", () => world.RemoveMesh(lift), "removing a stale mesh");
                    check.Throws(StatusCode.InvalidHandle, "nl_mesh_set_transform", () => world.SetMeshTransform(lift, at),
                                 "moving a stale mesh");
                    MeshInfo unused;
                    check.That(!world.TryGetMeshInfo(lift, out unused), "TryGetMeshInfo of a stale mesh is false");
                }
            });

            check.Run("invalid input", () =>
            {
                var logged = new System.Collections.Generic.List<string>();
                using (var world = new World(new WorldOptions { Log = (level, status, message) => { lock (logged) logged.Add(message); } }))
                {
                    check.Throws(StatusCode.InvalidArgument, "indices", () => world.AddMesh(Floor, new uint[] {0, 1, 7}),
                                 "an index past the vertices");
                    check.That(logged.Count == 1 && logged[0].Contains("indices"), "the log callback got the failure: " +
                               string.Join(" | ", logged));
                    check.Throws(StatusCode.InvalidArgument, "rays", () => world.CastRays(new[] { new Ray(new Vec3(0, 1, 0), new Vec3(0, 0, 0), 1) }),
                                 "a ray with a zero direction");
                    check.Throws(StatusCode.ParseError, ":2:", () => world.AddObjMemory(System.Text.Encoding.UTF8.GetBytes("v 0 0 0\nf 1 2 9\n")),
                                 "a malformed OBJ");
                    check.Throws(StatusCode.NotFound, "nl_mesh_add_obj_file", () => world.AddObjFile("/no/such/level.obj"),
                                 "a missing OBJ file");
                    MeshId floor = world.AddMesh(Floor, Quad);
                    check.Throws(StatusCode.InvalidArgument, "transform", () => world.SetMeshTransform(floor, new float[16]),
                                 "an all-zero transform");
                }
                unsafe
                {
                    // Null pointers through the raw layer: the header's INVALID_ARGUMENT, naming the argument.
                    check.Status(Native.nl_world_create(null, null), StatusCode.InvalidArgument, "out_world", "nl_world_create(NULL, NULL)");
                    check.Status(Native.nl_world_get_meshes(IntPtr.Zero, null, 0, null), StatusCode.InvalidArgument, "world",
                                 "nl_world_get_meshes(NULL, ...)");
                    check.That(Native.nl_world_get_worker_count(IntPtr.Zero) == 0 && Status.Failed(Native.nl_get_last_status()),
                               "nl_world_get_worker_count(NULL) is 0 and records a failure");
                    using (var world = new World())
                    {
                        check.Status(Native.nl_world_get_meshes(world.DangerousGetPointer(), null, 0, null), StatusCode.InvalidArgument,
                                     "out_count", "nl_world_get_meshes without out_count");
                        uint count = 0;
                        check.That(Native.nl_world_get_meshes(world.DangerousGetPointer(), null, 0, &count) == StatusCode.Success &&
                                   Status.LastErrorMessage() == "", "a success clears the last error message");

                        // Output arrays of growable elements: the library reads the element size from the first
                        // element, which World's methods set (Native.nl_ray_hit_init) and a raw caller must.
                        world.AddMesh(Floor, Quad);
                        var ray = new Ray(new Vec3(0, 2, 0), new Vec3(0, -1, 0), 100);
                        var hits = new RayHit[1];
                        fixed (RayHit* h = hits)
                        {
                            check.Status(Native.nl_world_cast_rays(world.DangerousGetPointer(), &ray, 1, h), StatusCode.InvalidArgument,
                                         "out_hits", "nl_world_cast_rays with out_hits[0].size 0");
                            hits[0] = Native.nl_ray_hit_init();
                            check.That(Native.nl_world_cast_rays(world.DangerousGetPointer(), &ray, 1, h) == StatusCode.Success &&
                                       hits[0].Hit == 1 && hits[0].Size == (uint)sizeof(RayHit), "with the size set, a hit");
                        }
                    }
                }
            });

            check.Run("OBJ: dungeon.obj", () =>
            {
                string path = Path.Combine(levelsDir, "dungeon.obj");
                using (var world = new World())
                {
                    MeshId dungeon = world.AddObjFile(path);
                    MeshInfo info = world.GetMeshInfo(dungeon);
                    int expected = TestLevels.CountObjTriangles(path);
                    check.That(info.TriangleCount + info.DegenerateTriangleCount == expected,
                               "dungeon.obj: " + info.TriangleCount + " + " + info.DegenerateTriangleCount + " degenerate triangles, " +
                               expected + " in the file's faces");
                    check.That(info.BoundsMax.Y > info.BoundsMin.Y, "the dungeon has height");
                }
            });
        }
    }
}
