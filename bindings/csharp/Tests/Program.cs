using System;
using NavLink;

namespace NavLink.Tests
{
    // The C# binding's test: drives libnavlink.so through the binding as a Unity game would.
    // Usage: mono NavLinkTests.exe --levels DIR --layout FILE   (FILE from bindings/layout/c_layout.py)
    internal static class Program
    {
        private static int Main(string[] args)
        {
            string levels = Argument(args, "--levels");
            string layout = Argument(args, "--layout");
            if (levels == null || layout == null)
            {
                Console.Error.WriteLine("usage: NavLinkTests.exe --levels DIR --layout FILE");
                return 2;
            }
            var check = new Checks();
            check.Run("structs, initialisers and constants against the C compiler", () => LayoutTests.Run(check, layout));
            LevelTests.Run(check, levels);
            HostTaskTests.Run(check);
            NavmeshTests.Run(check);
            LinkTests.Run(check);
            NavmeshFileTests.Run(check);
            PluginTests.Run(check);
            PathTests.Run(check);
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
