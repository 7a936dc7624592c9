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
        // C names whose C# type is not "strip nl_, PascalCase": taken by System.Version, and by the
        // PathResult class that carries the points too.
        private static readonly Dictionary<string, string> Renamed = new Dictionary<string, string>
        {
            {"nl_version", "NavLinkVersion"},
            {"nl_path_result", "PathResultInfo"},
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
