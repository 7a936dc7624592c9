using System;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using System.Xml.Linq;
using NavLink;

namespace NavLink.Tests
{
    // The Unity package (com.navlink.sdk) and the project file stay what a user takes as is: the package's
    // name and version (the headers' version), its assembly definition, and a project file that compiles
    // every source folder of Runtime/. (run_tests.sh builds NavLink.dll with that project file.)
    internal static class PackageTests
    {
        public static void Run(Checks check, string packageDir, string projectFile)
        {
            check.Run("the Unity package and the project file", () =>
            {
                XElement package = NavmeshFileTests.ParseJson(File.ReadAllText(Path.Combine(packageDir, "package.json")));
                check.That((string)package.Element("name") == "com.navlink.sdk", "package.json name: " + (string)package.Element("name"));
                string version = HeaderVersion.Major + "." + HeaderVersion.Minor + "." + HeaderVersion.Patch;
                check.That((string)package.Element("version") == version,
                           "package.json version " + (string)package.Element("version") + ", the headers' " + version);
                check.That(Regex.IsMatch((string)package.Element("unity") ?? "", @"^20\d\d\.\d$"),
                           "package.json names the oldest Unity it takes: " + (string)package.Element("unity"));

                string runtime = Path.Combine(packageDir, "Runtime");
                XElement asmdef = NavmeshFileTests.ParseJson(File.ReadAllText(Path.Combine(runtime, "NavLink.asmdef")));
                check.That((string)asmdef.Element("name") == typeof(World).Assembly.GetName().Name,
                           "the asmdef names the assembly as the project file does: " + (string)asmdef.Element("name"));
                check.That((string)asmdef.Element("allowUnsafeCode") == "true", "the asmdef allows unsafe code");
                check.That(File.Exists(Path.Combine(packageDir, "README.md")) &&
                           File.Exists(Path.Combine(packageDir, "Plugins", "README.md")),
                           "README.md and Plugins/README.md (where the native library goes)");

                // xbuild's ** globs list files twice, so the project names each folder: a new one must be added.
                XNamespace msbuild = "http://schemas.microsoft.com/developer/msbuild/2003";
                string[] compiled = XDocument.Load(projectFile).Descendants(msbuild + "Compile")
                    .SelectMany(c => ((string)c.Attribute("Include")).Split(';')).Select(p => p.Replace('\\', '/')).ToArray();
                foreach (string dir in new[] {runtime}.Concat(Directory.GetDirectories(runtime, "*", SearchOption.AllDirectories)))
                {
                    if (Directory.GetFiles(dir, "*.cs").Length == 0) continue;
                    string glob = "com.navlink.sdk/" + dir.Substring(packageDir.Length).Trim('/') + "/*.cs";
                    check.That(compiled.Contains(glob), "NavLink.csproj compiles " + glob);
                }
            });
        }
    }
}
