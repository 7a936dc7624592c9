using System;
using NavLink;

namespace NavLink.Tests
{
    // The C# binding's test: drives libnavlink.so through the binding as a Unity game would.
    // Usage: mono NavLinkTests.exe --levels DIR --layout FILE --package DIR --project FILE --library-dir DIR
    //   (FILE from bindings/layout/c_layout.py; the package folder com.navlink.sdk; NavLink.csproj; the folder
    //   of libnavlink.so, which NavLink.dll.config must map navlink to, and which the missing-library test
    //   keeps out of reach)
    // or:    mono NavLinkTests.exe --missing-library   (what MissingLibraryTests runs without the library)
    internal static class Program
    {
        private static int Main(string[] args)
        {
            if (Array.IndexOf(args, MissingLibraryTests.ChildFlag) >= 0) return MissingLibraryTests.Child();
            string levels = Argument(args, "--levels");
            string layout = Argument(args, "--layout");
            string package = Argument(args, "--package");
            string project = Argument(args, "--project");
            string libraryDir = Argument(args, "--library-dir");
            if (levels == null || layout == null || package == null || project == null || libraryDir == null)
            {
                Console.Error.WriteLine("usage: NavLinkTests.exe --levels DIR --layout FILE --package DIR --project FILE --library-dir DIR");
                return 2;
            }
            var check = new Checks();
            check.Run("structs, initialisers and constants against the C compiler", () => LayoutTests.Run(check, layout));
            PackageTests.Run(check, package, project);
            MissingLibraryTests.Run(check, libraryDir);
            EnumTests.Run(check);
            LevelTests.Run(check, levels);
            HostTaskTests.Run(check);
            NavmeshTests.Run(check);
            QueryTests.Run(check);
            MeshInputTests.Run(check);
            LinkTests.Run(check);
            NavmeshFileTests.Run(check);
            PluginTests.Run(check);
            PathTests.Run(check);
            PathWaitTests.Run(check);
            AgentTests.Run(check);
            Console.WriteLine(check.Passed + " passed, " + check.Failed + " failed");
            return check.Failed == 0 && check.Passed > 0 ? 0 : 1;
        }

        private static string Argument(string[] args, string name)
        {
            int i = Array.IndexOf(args, name);
            return i >= 0 && i + 1 < args.Length ? args[i + 1] : null;
        }
    }
}
