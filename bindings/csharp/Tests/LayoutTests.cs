using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using NavLink;

namespace NavLink.Tests
{
    // Every struct of the public headers against the C compiler's view of it (bindings/layout/c_layout.py
    // writes the table): same size, a C# field for each C field (snake_case -> PascalCase) at the same
    // offset, and no C# field the C struct lacks. And each inline initialiser of the headers
    // (NL_DEFINE_OUTPUT_INIT) against its twin in Native: same name, the same struct, the same Size set
    // (the C one's, from calling it), every other byte zero.
    internal static class LayoutTests
    {
        // C names whose C# type is not "strip nl_, PascalCase": taken by System.Version, by the PathResult
        // class that carries the points too, by the PathShortfall class that carries its text as a string,
        // and by the QueryFilter class that carries its area costs.
        private static readonly Dictionary<string, string> Renamed = new Dictionary<string, string>
        {
            {"nl_version", "NavLinkVersion"},
            {"nl_path_result", "PathResultInfo"},
            {"nl_path_shortfall", "PathShortfallInfo"},
            {"nl_query_filter", "QueryFilterDef"},
        };

        // The constant classes and enums of Generated/Constants.g.cs and the prefix of the #defines each holds: a
        // C# constant is PREFIX + its name in UPPER_SNAKE (InvalidArgument: NL_STATUS_INVALID_ARGUMENT), but for
        // RenamedConstants.
        private static readonly Dictionary<Type, string> ConstantPrefixes = new Dictionary<Type, string>
        {
            {typeof(HeaderVersion), "NL_VERSION_"}, {typeof(StatusCode), "NL_STATUS_"}, {typeof(Limits), "NL_"},
            {typeof(LogLevel), "NL_LOG_"}, {typeof(MeshFlags), "NL_MESH_"}, {typeof(UpAxis), "NL_UP_AXIS_"},
            {typeof(BuildWarnings), "NL_BUILD_WARNING_"}, {typeof(LinkKind), "NL_LINK_"},
            {typeof(PathOutcome), "NL_PATH_"}, {typeof(PathShortfallReason), "NL_PATH_SHORTFALL_"}, {typeof(LinkLimit), "NL_LINK_LIMIT_"},
            {typeof(AgentState), "NL_AGENT_"}, {typeof(AgentReason), "NL_AGENT_REASON_"},
            {typeof(TrajectoryKind), "NL_TRAJECTORY_"}, {typeof(AgentEventKind), "NL_AGENT_EVENT_"}, {typeof(PluginKinds), "NL_PLUGIN_"},
            {typeof(PluginAbi), "NL_PLUGIN_ABI_"},
            {typeof(RecastPartition), "NL_RECAST_PARTITION_"}, {typeof(NavmeshLoadFlags), "NL_NAVMESH_LOAD_"},
            {typeof(LinksLoadFlags), "NL_LINKS_LOAD_"},
        };
        private static readonly Dictionary<string, string> RenamedConstants = new Dictionary<string, string>
        {
            {"LinkKind.Walk", "NL_SEGMENT_WALK"},
        };
        // #defines a C# constant of another name stands for, with the same value: LinkKind is also the header's
        // nl_segment_kind (PathPoint.Segment).
        private static readonly Dictionary<string, string> SameAs = new Dictionary<string, string>
        {
            {"NL_SEGMENT_JUMP", "NL_LINK_JUMP"}, {"NL_SEGMENT_DROP", "NL_LINK_DROP"}, {"NL_SEGMENT_MANUAL", "NL_LINK_MANUAL"},
        };

        public static void Run(Checks check, string layoutFile)
        {
            string[] lines = File.ReadAllLines(layoutFile);
            check.That(lines.Any(l => l.StartsWith("struct ")), "the layout table lists structs");
            var fieldCounts = new Dictionary<Type, int>();
            int inits = 0;
            foreach (string line in lines)
            {
                string[] p = line.Split(' ');
                if (p[0] == "struct")
                {
                    Type type = CSharpType(p[1]);
                    if (!check.That(type != null, p[1] + " has a C# struct")) continue;
                    check.That(Marshal.SizeOf(type) == int.Parse(p[2]),
                               p[1] + ": C size " + p[2] + ", C# " + Marshal.SizeOf(type));
                    fieldCounts[type] = 0;
                }
                else if (p[0] == "field")
                {
                    Type type = CSharpType(p[1]);
                    if (type == null) continue;
                    string name = Pascal(p[2]);
                    FieldInfo field = type.GetField(name, BindingFlags.Public | BindingFlags.Instance);
                    if (!check.That(field != null, p[1] + "." + p[2] + ": no field " + type.Name + "." + name)) continue;
                    fieldCounts[type] = fieldCounts[type] + 1;
                    int offset = Marshal.OffsetOf(type, name).ToInt32();
                    check.That(offset == int.Parse(p[3]), p[1] + "." + p[2] + ": C offset " + p[3] + ", C# " + offset);
                }
                else if (p[0] == "init")
                {
                    ++inits;
                    CheckInit(check, p[1], p[2], uint.Parse(p[3]));
                }
            }
            check.That(inits >= 11, inits + " inline initialisers in the layout table");
            foreach (var entry in fieldCounts)
            {
                int fields = entry.Key.GetFields(BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance).Length;
                check.That(fields == entry.Value, entry.Key.Name + " has " + fields + " fields, its C struct " + entry.Value);
            }
            CheckConstants(check, lines);
        }

        // Every integer #define of the headers is a C# constant with its value, and every public integer
        // constant of the binding is one of them.
        private static void CheckConstants(Checks check, string[] lines)
        {
            var header = lines.Select(l => l.Split(' ')).Where(p => p[0] == "const").ToDictionary(p => p[1], p => long.Parse(p[2]));
            check.That(header.Count >= 40, header.Count + " integer constants in the layout table");
            var mine = new Dictionary<string, long>();
            foreach (Type type in typeof(World).Assembly.GetTypes().Where(t => t.IsPublic))
            {
                var constants = type.IsEnum
                    ? Enum.GetNames(type).Select(n => new KeyValuePair<string, object>(n, Convert.ChangeType(Enum.Parse(type, n), Enum.GetUnderlyingType(type))))
                    : type.GetFields(BindingFlags.Public | BindingFlags.Static)
                          .Where(f => f.IsLiteral && (f.FieldType == typeof(int) || f.FieldType == typeof(uint)))
                          .Select(f => new KeyValuePair<string, object>(f.Name, f.GetRawConstantValue()));
                foreach (var c in constants)
                {
                    // A [Flags] enum's None (no bit set) is C#'s convention; the headers write 0.
                    if (type.IsDefined(typeof(FlagsAttribute), false) && c.Key == "None" && Convert.ToInt64(c.Value) == 0) continue;
                    string prefix;
                    if (!check.That(ConstantPrefixes.TryGetValue(type, out prefix), type.Name + "." + c.Key + ": a constant outside the classes of Constants.g.cs"))
                        continue;
                    string cName;
                    if (!RenamedConstants.TryGetValue(type.Name + "." + c.Key, out cName)) cName = prefix + UpperSnake(c.Key);
                    mine[cName] = Convert.ToInt64(c.Value);
                    long value;
                    check.That(header.TryGetValue(cName, out value) && value == mine[cName],
                               type.Name + "." + c.Key + " = " + c.Value + ": the headers' " + cName + " is " +
                               (header.ContainsKey(cName) ? header[cName].ToString() : "not defined"));
                }
            }
            foreach (var entry in header)
            {
                string other;
                if (SameAs.TryGetValue(entry.Key, out other))
                    check.That(mine.ContainsKey(other) && mine[other] == entry.Value,
                               entry.Key + " (" + entry.Value + ") is not the C# constant of " + other);
                else
                    check.That(mine.ContainsKey(entry.Key), entry.Key + " (" + entry.Value + ") has no C# constant");
            }
        }

        private static string UpperSnake(string pascal)
        {
            return string.Concat(pascal.Select((c, i) => i > 0 && char.IsUpper(c) ? "_" + c : char.ToUpperInvariant(c).ToString()));
        }

        private static void CheckInit(Checks check, string cStruct, string function, uint cSize)
        {
            Type type = CSharpType(cStruct);
            MethodInfo init = typeof(Native).GetMethod(function, BindingFlags.Public | BindingFlags.Static, null, Type.EmptyTypes, null);
            if (!check.That(init != null && type != null && init.ReturnType == type,
                            function + ": Native." + function + "() returning the C# twin of " + cStruct)) return;
            object value = init.Invoke(null, null);
            int size = Marshal.SizeOf(type);
            IntPtr memory = Marshal.AllocHGlobal(size);
            try
            {
                // Through unmanaged memory (zeroed first: padding is nobody's): Size is the first 4 bytes, the
                // rest must be zero.
                var bytes = new byte[size];
                Marshal.Copy(bytes, 0, memory, size);
                Marshal.StructureToPtr(value, memory, false);
                Marshal.Copy(memory, bytes, 0, size);
                uint written = BitConverter.ToUInt32(bytes, 0);
                check.That(written == cSize, function + "() sets size " + written + ", C's " + cSize);
                check.That(bytes.Skip(4).All(b => b == 0), function + "() zeroes every other byte");
            }
            finally
            {
                Marshal.FreeHGlobal(memory);
            }
        }

        private static Type CSharpType(string cName)
        {
            string name;
            if (!Renamed.TryGetValue(cName, out name)) name = Pascal(cName.Substring(3));
            return typeof(World).Assembly.GetType("NavLink." + name);
        }

        private static string Pascal(string snake)
        {
            return string.Concat(snake.Split('_').Select(w => w.Length == 0 ? w : char.ToUpperInvariant(w[0]) + w.Substring(1)));
        }
    }
}
