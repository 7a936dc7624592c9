using System;
using System.IO;
using System.Linq;
using System.Runtime.Serialization.Json;
using System.Text;
using System.Xml;
using System.Xml.Linq;
using NavLink;

namespace NavLink.Tests
{
    // Baked navmesh files: saved to bytes and to a file, described, loaded into a new world (the same polygons,
    // links and paths); truncated and foreign bytes refused with nothing added.
    internal static class NavmeshFileTests
    {
        public static void Run(Checks check)
        {
            check.Run("baked navmesh file", () =>
            {
                string dir = Path.Combine(Path.GetTempPath(), "navlink-csharp-" + Guid.NewGuid().ToString("N"));
                Directory.CreateDirectory(dir);
                try
                {
                    using (var world = new World())
                        SaveDescribeLoad(check, world, dir);
                }
                finally
                {
                    Directory.Delete(dir, true);
                }
            });
        }

        private static void SaveDescribeLoad(Checks check, World world, string dir)
        {
            NavmeshId navmesh = TestLevels.AddGapNavmeshWithLinks(world);
            int linkCount = world.GetLinks(navmesh).Length;
            uint polygons = world.GetNavmeshInfo(navmesh).PolygonCount;
            PathResult original = world.FindPath(new PathQuery(navmesh, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Jumper()));
            check.That(original.Outcome == PathOutcome.Complete, "the jumper crosses on the original: " + original.Outcome);
            byte[] data = world.SaveNavmesh(navmesh);

            string madeForJson;
            NavmeshFileInfo info = World.DescribeNavmeshFile(data, out madeForJson);
            check.That(info.FileSize == (ulong)data.Length && info.Version >= 1,
                       "file size " + info.FileSize + " of " + data.Length + " bytes, version " + info.Version);
            check.That(info.PolygonCount == polygons, info.PolygonCount + " polygons described, the navmesh has " + polygons);
            check.That(info.LinkCount == linkCount && info.GeneratedLinkCount == linkCount - 1,
                       info.LinkCount + " links (" + info.GeneratedLinkCount + " generated) described, " + linkCount + " listed");
            check.Near(info.AgentType.Radius, 0.6f, 1e-6f, "the agent radius described");
            check.That(info.Quantum == 1.0f / 1024.0f && info.RidesCarrier == 0, "quantum " + info.Quantum + ", rides nothing");
            check.That(World.DescribeNavmeshFile(data).PolygonCount == polygons, "described without the JSON");
            XElement madeFor = ParseJson(madeForJson);
            XElement builder = madeFor.Element("builder");
            check.That(builder != null && builder.Value == "recast", "made for: " + madeForJson);
            XElement hash = madeFor.Element("level_hash");
            check.That(hash != null && hash.Value == info.LevelHash.ToString("x16"), "the JSON's level hash is the info's");

            Action<World, NavmeshId, string> same = (w, loaded, what) =>
            {
                check.That(w.GetNavmeshInfo(loaded).PolygonCount == polygons, what + ": the same polygon count");
                check.That(w.GetLinks(loaded).Length == linkCount, what + ": the same links");
                PathResult path = w.FindPath(new PathQuery(loaded, TestLevels.WestPoint, TestLevels.EastPoint, TestLevels.Jumper()));
                check.That(path.Outcome == PathOutcome.Complete, what + ": the jumper crosses: " + path.Outcome);
                check.Near(path.Length, original.Length, 1e-4f, what + ": the same path length");
            };

            using (var fresh = new World())
            {
                NavmeshId loaded = fresh.LoadNavmesh(data);
                same(fresh, loaded, "loaded from bytes");
                check.That(fresh.SaveNavmesh(loaded).SequenceEqual(data), "saved again, the same bytes: what it was made for travels with it");
            }

            string file = Path.Combine(dir, "gap.nlnav");
            world.SaveNavmeshFile(navmesh, file);
            check.That(File.ReadAllBytes(file).SequenceEqual(data), "the file holds the bytes");
            using (var fresh = new World())
                same(fresh, fresh.LoadNavmeshFile(file), "loaded from the file");

            // The level it was baked from: sameLevel refuses a world without it, takes one with it.
            using (var other = new World())
            {
                check.Throws(StatusCode.InvalidArgument, "baked from", () => other.LoadNavmesh(data, sameLevel: true),
                             "sameLevel in a world without the level");
                check.That(other.GetNavmeshes().Length == 0, "nothing added");
                TestLevels.AddGapLevel(other);
                same(other, other.LoadNavmesh(data, sameLevel: true), "loaded with sameLevel");

                int count = other.GetNavmeshes().Length;
                byte[] half = data.Take(data.Length / 2).ToArray();
                byte[] hello = Encoding.ASCII.GetBytes("hello");
                check.Throws(StatusCode.ParseError, "nl_navmesh_load", () => other.LoadNavmesh(half), "truncated bytes");
                check.Throws(StatusCode.VersionMismatch, "nl_navmesh_load", () => other.LoadNavmesh(hello), "foreign bytes");
                check.Throws(StatusCode.ParseError, "nl_navmesh_file_describe", () => World.DescribeNavmeshFile(half),
                             "describing truncated bytes");
                check.Throws(StatusCode.VersionMismatch, "nl_navmesh_file_describe", () => World.DescribeNavmeshFile(hello),
                             "describing foreign bytes");
                check.Throws(StatusCode.NotFound, "nl_navmesh_load_file", () => other.LoadNavmeshFile(Path.Combine(dir, "missing.nlnav")),
                             "a missing file");
                check.That(other.GetNavmeshes().Length == count, "nothing added on failure");
            }
        }

        /// <summary>The JSON object as the framework's JSON reader sees it (members as child elements); throws
        /// if it is not JSON.</summary>
        internal static XElement ParseJson(string json)
        {
            using (XmlDictionaryReader reader = JsonReaderWriterFactory.CreateJsonReader(Encoding.UTF8.GetBytes(json),
                                                                                          XmlDictionaryReaderQuotas.Max))
                return XElement.Load(reader);
        }
    }
}
