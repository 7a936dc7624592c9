using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Xml.Linq;
using NavLink;

namespace NavLink.Tests
{
    // How a Mono program finds libnavlink: NavLink.dll.config beside NavLink.dll (written when NavLink.dll was
    // built, by write_dll_config.sh) maps [DllImport("navlink")] to the library's absolute path; run_tests.sh
    // keeps its folder off LD_LIBRARY_PATH, so this process found it through that file alone.
    // And a program whose libnavlink cannot be found must be told what was looked for and where to put it:
    // this process has loaded the library, so the test runs the test program again (--missing-library) from
    // a copy of it and NavLink.dll whose NavLink.dll.config names a folder without the library (as after the
    // library moved); the child creates a World and prints what it caught.
    internal static class MissingLibraryTests
    {
        public const string ChildFlag = "--missing-library";

        public static void Run(Checks check, string libraryDir)
        {
            string full = Path.GetFullPath(libraryDir).TrimEnd('/');
            string path = Environment.GetEnvironmentVariable("LD_LIBRARY_PATH") ?? "";
            string[] otherFolders = path.Split(':').Where(d => d.Length > 0 && Path.GetFullPath(d).TrimEnd('/') != full).ToArray();

            check.Run("NavLink.dll.config maps navlink to the library, found without LD_LIBRARY_PATH", () =>
            {
                string config = typeof(World).Assembly.Location + ".config";
                if (!check.That(File.Exists(config), "NavLink.dll.config beside NavLink.dll: " + config)) return;
                XElement map = XDocument.Load(config).Root.Elements("dllmap").FirstOrDefault(e => (string)e.Attribute("dll") == Native.Library);
                string target = map == null ? "" : (string)map.Attribute("target") ?? "";
                check.That(Path.IsPathRooted(target) && Path.GetDirectoryName(target).TrimEnd('/') == full && File.Exists(target),
                           "a <dllmap dll=\"navlink\"> to the library in " + full + ": '" + target + "'");
                check.That(otherFolders.Length == path.Split(':').Count(d => d.Length > 0),
                           "LD_LIBRARY_PATH does not name " + full + " (run_tests.sh keeps it off): " + path);
                using (new World()) check.That(true, "the library loaded");
            });

            check.Run("a missing libnavlink is explained (NavLinkException)", () =>
            {
                string copy = Path.Combine(Path.GetTempPath(), "navlink-missing-library-" + Process.GetCurrentProcess().Id);
                string gone = Path.Combine(copy, "no-library", "lib" + Native.Library + ".so.0");
                Directory.CreateDirectory(copy);
                try
                {
                    foreach (string assembly in new[] { typeof(MissingLibraryTests).Assembly.Location, typeof(World).Assembly.Location })
                        foreach (string file in new[] { assembly, assembly + ".mdb" }.Where(File.Exists))
                            File.Copy(file, Path.Combine(copy, Path.GetFileName(file)), true);
                    File.WriteAllText(Path.Combine(copy, "NavLink.dll.config"),
                        "<configuration>\n  <dllmap dll=\"" + Native.Library + "\" target=\"" + gone + "\"/>\n</configuration>\n");
                    RunChild(check, Path.Combine(copy, Path.GetFileName(typeof(MissingLibraryTests).Assembly.Location)), otherFolders, gone);
                }
                finally
                {
                    Directory.Delete(copy, true);
                }
            });
        }

        private static void RunChild(Checks check, string exe, string[] otherFolders, string gone)
        {
            var start = new ProcessStartInfo(Process.GetCurrentProcess().MainModule.FileName, "--debug \"" + exe + "\" " + ChildFlag)
            {
                UseShellExecute = false,
                RedirectStandardOutput = true,
                RedirectStandardError = true,
            };
            start.EnvironmentVariables["LD_LIBRARY_PATH"] = string.Join(":", otherFolders);
            string output, errors;
            int exitCode;
            using (Process child = Process.Start(start))
            {
                // Both streams read at once, so that neither fills its pipe while the other is waited for.
                var errorsRead = child.StandardError.ReadToEndAsync();
                output = child.StandardOutput.ReadToEnd();
                errors = errorsRead.Result;
                child.WaitForExit();
                exitCode = child.ExitCode;
            }
            check.That(exitCode == 0, "the child ran (exit " + exitCode + "): " + output + errors);
            string[] lines = output.Split('\n');
            string caught = lines.FirstOrDefault(l => l.StartsWith("caught ")) ?? "";
            string message = string.Join("\n", lines.SkipWhile(l => !l.StartsWith("caught ")).Skip(1));
            check.That(caught == "caught NavLink.NavLinkException " + (StatusCode.Failure | StatusCode.NotFound),
                       "the first call throws NavLinkException with Failure | NotFound: '" + caught + "'" +
                       (caught.Length == 0 ? " (the library was found anyway? " + output + ")" : ""));
            // The file the stale NavLink.dll.config names (Mono's own words): the config was read.
            foreach (string part in new[] { "[DllImport(\"navlink\")]", "libnavlink.so", "Linux", "LD_LIBRARY_PATH", gone,
                                            "next to the executable", "dllmap", "NavLink.dll.config", "NavLinkLibraryDir",
                                            "Plugins/", "DllNotFoundException" })
                check.That(message.Contains(part), "the message names " + part + ": " + message);
            check.That(lines.Any(l => l == "again: same message"), "a second call says the same (no TypeInitializationException)");
        }

        /// <summary>In the child: the first NavLink call, with libnavlink out of reach.</summary>
        public static int Child()
        {
            string first = Attempt();
            Console.WriteLine(first);
            Console.WriteLine(Attempt() == first ? "again: same message" : "again: a different message");
            return 0;
        }

        private static string Attempt()
        {
            try
            {
                using (new World()) return "loaded: the library was found";
            }
            catch (Exception e)
            {
                var navlink = e as NavLinkException;
                return "caught " + e.GetType().FullName + (navlink != null ? " " + navlink.StatusCode : "") + "\n" + e.Message;
            }
        }
    }
}
