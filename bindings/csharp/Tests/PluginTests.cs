using System.Linq;
using NavLink;

namespace NavLink.Tests
{
    // Plugins: the built-in Recast builder listed, a C# builder registered and used, loading failures.
    internal static class PluginTests
    {
        public static void Run(Checks check)
        {
            check.Run("plugins", () =>
            {
                using (var world = new World())
                {
                    PluginId[] builtin = world.GetPlugins();
                    PluginSummary recast = builtin.Length > 0 ? world.DescribePlugin(builtin[0]) : null;
                    check.That(recast != null && recast.Name == "recast" && recast.Builtin &&
                               (recast.Kinds & PluginKinds.NavmeshBuilder) != 0, "the built-in Recast builder comes first");

                    PluginId roof = world.RegisterPlugin(RoofPlugin.EntryFunction);
                    PluginSummary mine = world.DescribePlugin(roof);
                    check.That(mine.Name == RoofPlugin.Name && !mine.Builtin && mine.Version == "1.0" && mine.AbiVersion == 1 &&
                               mine.Kinds == PluginKinds.NavmeshBuilder, "the C# plugin describes itself: " + mine.Name);
                    check.That(world.GetPlugins().Length == builtin.Length + 1, "and is listed");
                    check.Throws(StatusCode.InvalidArgument, RoofPlugin.Name, () => world.RegisterPlugin(RoofPlugin.EntryFunction),
                                 "a second plugin of the same name");

                    // Its refusal reaches the caller through host->set_error.
                    check.Throws(StatusCode.NotFound, RoofPlugin.NoTrianglesMessage,
                                 () => world.BuildNavmesh(World.DefaultAgentType(), null, null, RoofPlugin.Name), "an empty level");

                    world.AddMesh(new float[] {0, 0, 0, 0, 0, 4, 4, 0.5f, 4}, new uint[] {0, 1, 2});
                    NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType(), null, null, RoofPlugin.Name);
                    NavmeshInfo info = world.GetNavmeshInfo(navmesh);
                    check.That(info.PolygonCount == 1 && info.BoundsMax.Y == 0.5f && info.BoundsMax.X == 4,
                               "the roof: " + info.PolygonCount + " polygon at y = " + info.BoundsMax.Y);
                    string madeFor;
                    World.DescribeNavmeshFile(world.SaveNavmesh(navmesh), out madeFor);
                    check.That(madeFor.Contains("\"builder_settings\":" + RoofPlugin.Used), "what the roof recorded: " + madeFor);

                    check.Throws(StatusCode.NotFound, "nl_plugin_load", () => world.LoadPlugin("/no/such/plugin.so"), "a missing library");
                }
            });
        }
    }
}
