using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using NavLink;

namespace NavLink.Tests
{
    // Kinds, flags, statuses and outcomes are enums in the idiomatic API: values written as enums reach the
    // library and come back as the same enums. (LayoutTests holds every enum member against its #define.)
    internal static class EnumTests
    {
        // Members whose name says they hold a kind, flags, a status or an outcome.
        private static readonly string[] KindLikeNames =
            { "Kind", "Kinds", "Flags", "Status", "StatusCode", "Level", "LogLevel", "Segment", "Partition", "Outcome", "State", "Reason",
              "UpAxis", "BuildWarnings" };

        public static void Run(Checks check)
        {
            check.Run("enums: none of the public API's kinds, flags or statuses is a bare uint", () =>
            {
                var raw = new[] { typeof(Native), typeof(NativeCallbacks) };
                var bare = new List<string>();
                foreach (Type type in typeof(World).Assembly.GetExportedTypes().Where(t => !raw.Contains(t) && !raw.Contains(t.DeclaringType)))
                {
                    const BindingFlags all = BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;
                    foreach (FieldInfo f in type.GetFields(all))
                        if (f.FieldType == typeof(uint) && !f.IsLiteral && IsKindLike(f.Name)) bare.Add(type.Name + "." + f.Name);
                    foreach (PropertyInfo p in type.GetProperties(all))
                        if (p.PropertyType == typeof(uint) && IsKindLike(p.Name)) bare.Add(type.Name + "." + p.Name);
                    foreach (MethodBase m in type.GetMethods(all).Cast<MethodBase>().Concat(type.GetConstructors()))
                        foreach (ParameterInfo a in m.GetParameters())
                            if (a.ParameterType == typeof(uint) && IsKindLike(a.Name)) bare.Add(type.Name + "." + m.Name + "(" + a.Name + ")");
                }
                check.That(bare.Count == 0, "uint where an enum belongs: " + string.Join(", ", bare));
                check.That(typeof(MeshFlags).IsDefined(typeof(FlagsAttribute), false) && typeof(StatusCode).IsDefined(typeof(FlagsAttribute), false) &&
                           typeof(PluginKinds).IsDefined(typeof(FlagsAttribute), false) && !typeof(LinkKind).IsDefined(typeof(FlagsAttribute), false) &&
                           typeof(BuildWarnings).IsDefined(typeof(FlagsAttribute), false) && !typeof(UpAxis).IsDefined(typeof(FlagsAttribute), false),
                           "bit sets are [Flags], kinds are not");
            });

            check.Run("enums: round trips through the library", () =>
            {
                var logged = new List<KeyValuePair<LogLevel, StatusCode>>();
                var options = new WorldOptions { LogLevel = LogLevel.Error };
                options.Log = (level, status, message) => { lock (logged) logged.Add(new KeyValuePair<LogLevel, StatusCode>(level, status)); };
                using (var world = new World(options))
                {
                    MeshId platform = TestLevels.AddBox(world, -5, -1, -5, 5, 0, 5, MeshFlags.Movable);
                    MeshId floor = TestLevels.AddBox(world, -9, -11, -9, 9, -10, 9);
                    check.That(world.GetMeshInfo(platform).Flags == MeshFlags.Movable && world.GetMeshInfo(floor).Flags == MeshFlags.None,
                               "mesh flags: " + world.GetMeshInfo(platform).Flags + ", " + world.GetMeshInfo(floor).Flags);

                    try
                    {
                        world.RemoveMesh(default(MeshId));
                        check.That(false, "removing the null mesh throws");
                    }
                    catch (NavLinkException e)
                    {
                        check.That(e.StatusCode == (StatusCode.Failure | StatusCode.InvalidHandle) && e.StatusCode.ToString() == "InvalidHandle, Failure",
                                   "the exception's status as an enum: " + e.StatusCode);
                        check.That(e.Has(StatusCode.InvalidHandle) && !e.Has(StatusCode.InvalidArgument) && !e.Has(0),
                                   "Has tests its detail bits");
                        check.That(Status.Describe(e.StatusCode).Contains("invalid handle"), "Describe: " + Status.Describe(e.StatusCode));
                    }
                    lock (logged)
                        check.That(logged.Count == 1 && logged[0].Key == LogLevel.Error && logged[0].Value == (StatusCode.Failure | StatusCode.InvalidHandle),
                                   "the log handler gets a LogLevel and a StatusCode: " + string.Join(", ", logged));

                    RecastSettings recast = World.DefaultRecastSettings();
                    check.That(recast.Partition == RecastPartition.Watershed, "the default partition: " + recast.Partition);
                    recast.Partition = RecastPartition.Monotone;
                    NavmeshId navmesh = world.BuildNavmesh(World.DefaultAgentType(), recast);
                    check.That(world.GetNavmeshInfo(navmesh).PolygonCount > 0, "a navmesh built with RecastPartition.Monotone");
                    recast.Partition = (RecastPartition)7;
                    check.Throws(StatusCode.InvalidArgument, "partition", () => world.BuildNavmesh(World.DefaultAgentType(), recast),
                                 "an undefined partition is refused");

                    LinkDef manual = World.DefaultLinkDef();
                    check.That(manual.Kind == LinkKind.Manual, "a manual link's kind: " + manual.Kind);
                    // On the floor: a movable mesh is no part of a navmesh build.
                    manual.Start = new Vec3(-4, -10, 0);
                    manual.End = new Vec3(4, -10, 0);
                    check.That(world.GetLink(world.AddLink(navmesh, manual)).Kind == LinkKind.Manual, "read back as LinkKind.Manual");

                    PluginSummary recastPlugin = world.GetPlugins().Select(world.DescribePlugin).First(p => p.Name == "recast");
                    check.That(recastPlugin.Kinds == PluginKinds.NavmeshBuilder, "the recast plugin's kinds: " + recastPlugin.Kinds);
                }
            });
        }

        private static bool IsKindLike(string name)
        {
            return KindLikeNames.Any(k => string.Equals(name, k, StringComparison.OrdinalIgnoreCase));
        }
    }
}
