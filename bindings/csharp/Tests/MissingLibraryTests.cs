using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using NavLink;

namespace NavLink.Tests
{
    // A program whose libnavlink cannot be found must be told what was looked for and where to put it. This
    // process has loaded the library, so the test runs the test program again (--missing-library) with
    // libnavlink's folder taken off LD_LIBRARY_PATH; the child creates a World and prints what it caught.
    internal static class MissingLibraryTests
    {
        public const string ChildFlag = "--missing-library";

        public static void Run(Checks check, string libraryDir)
        {
            check.Run("a missing libnavlink is explained (NavLinkException)", () =>
            {
                string exe = typeof(MissingLibraryTests).Assembly.Location;
                var start = new ProcessStartInfo(Process.GetCurrentProcess().MainModule.FileName, "--debug \"" + exe + "\" " + ChildFlag)
                {
                    UseShellExecute = false,
                    RedirectStandardOutput = true,
                    RedirectStandardError = true,
                };
                string full = Path.GetFullPath(libraryDir).TrimEnd('/');
                string path = Environment.GetEnvironmentVariable("LD_LIBRARY_PATH") ?? "";
                start.EnvironmentVariables["LD_LIBRARY_PATH"] = string.Join(":",
                    path.Split(':').Where(d => d.Length > 0 && Path.GetFullPath(d).TrimEnd('/') != full));
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
                foreach (string part in new[] { "[DllImport(\"navlink\")]", "libnavlink.so", "Linux", "LD_LIBRARY_PATH",
                                                "next to the executable", "dllmap", "Plugins/", "DllNotFoundException" })
                    check.That(message.Contains(part), "the message names " + part + ": " + message);
                check.That(lines.Any(l => l == "again: same message"), "a second call says the same (no TypeInitializationException)");
            });
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
